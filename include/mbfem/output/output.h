#ifndef mbfem_output_output_h
#define mbfem_output_output_h

#include <mbfem/base/files.h>
#include <mbfem/block/block.h>
#include <mbfem/material/in_situ_stress.h>
#include <mbfem/material/material.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <array>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /** Subsection "Output". */
  struct OutputParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Refuses an empty 'Output/Directory', the file system's root and the
     * system folders (/etc, /usr, /proc, ...) before anything is written.
     */
    static void
    check_directory(const std::string &directory);

    std::string directory = "results";
    std::string base_name = "solution";
    bool        write_vtu = true;
    /** Each increment's condensed contact problem (ContactProblem). */
    bool write_contact_problems = false;
    /** 'auto', 'full' or 'summary' (ScreenDetail). */
    std::string screen = "auto";
  };

  /**
   * Stress fields of a block for ParaView, computed at the output points
   * from the FE displacement gradient: the stress tensor, the plane-strain
   * sigma_zz (2D), the principal stresses sigma_1 >= sigma_2 >= sigma_3
   * (tension positive, as in the paper's figures) and the von Mises stress.
   * With an in-situ stress, the stress is the total one: sigma_0 plus the
   * stress of the displacement.
   */
  template <int dim>
  class StressPostprocessor : public DataPostprocessor<dim>
  {
  public:
    /**
     * @p plastic_stress: D eps_p at the QGauss(@p degree + 1) points of
     * every active cell (cell-major), subtracted from the elastic stress;
     * empty for an elastic block. At an output point it is interpolated
     * from the cell's Gauss points, so that at those points the output
     * stress is the returned one. (A cell mean gave sigma_1 of tens of MPa
     * at the corners of cells that yield in part.)
     */
    explicit StressPostprocessor(
      const Material                           &material,
      const InSituStress                       *in_situ        = nullptr,
      const std::vector<SymmetricTensor<2, 3>> &plastic_stress = {},
      const Mapping<dim>                       *mapping        = nullptr,
      const unsigned int                        degree         = 1);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    UpdateFlags
    get_needed_update_flags() const override;

    /**
     * D eps_p interpolated from the Gauss points of @p cell at @p point
     * (real coordinates); public for tests/stress_interpolation.
     */
    SymmetricTensor<2, 3>
    interpolated_plastic_stress(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const Point<dim>                                     &point) const;

  private:
    const Material                     material;
    const InSituStress                *in_situ;
    std::vector<SymmetricTensor<2, 3>> plastic_stress;
    const Mapping<dim>                *mapping;
    /** The 1D Gauss nodes, and each point's node index per direction. */
    std::vector<double>                        nodes;
    std::vector<std::array<unsigned int, dim>> node_of_point;
  };

  /**
   * Writes one VTU file per block and step and keeps the PVD index that
   * ParaView opens (blocks are the parts of each time step). Files are
   * written under a temporary name and renamed, so an interrupted run never
   * leaves a truncated file: what is on disk is what converged.
   */
  class OutputWriter
  {
  public:
    explicit OutputWriter(const OutputParameters &parameters);

    /**
     * Writes @p block at @p step; high-order cells (degree > 1) are written
     * as VTK Lagrange cells so ParaView shows them curved and not
     * subdivided. Returns the file name (relative to the directory).
     * Under mpirun only the block's owner writes it, every rank returns
     * the name: call it inside Parallel::together(), so that an error on
     * one rank ends all.
     */
    template <int dim>
    std::string
    write_block(const Block<dim>  &block,
                const unsigned int block_index,
                const unsigned int step) const;

    /** Adds a time step with its block files and rewrites the PVD index. */
    void
    add_step(const double time, const std::vector<std::string> &files);

    /** Path of the PVD index. */
    std::string
    pvd_file() const;

  private:
    const OutputParameters                                   parameters;
    std::vector<std::pair<double, std::vector<std::string>>> steps;
  };

} // namespace mbfem

#endif

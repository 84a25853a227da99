#ifndef mbfem_analysis_order_study_h
#define mbfem_analysis_order_study_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/types.h>

#include <memory>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  template <int dim>
  struct Parameters;

  template <int dim>
  class Block;

  /** Subsection "Order study". */
  struct OrderStudyParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    std::vector<unsigned int> degrees;
    std::vector<unsigned int> refinements;
    std::string               table_file;

    /**
     * Models of several blocks: 'same' (each degree in every block) or
     * 'all combinations' (every assignment of the degrees to the blocks).
     */
    std::string block_degrees = "same";

    /**
     * Relative errors below this are round-off: the solution lies in the
     * finite element space (or the solver's precision is reached) and no
     * rate is shown.
     */
    double round_off_floor = 1e-12;
  };

  /** Relative L2 errors of one block or of the whole model, and rates. */
  struct OrderStudyErrors
  {
    double displacement_error = 0.;
    double stress_error       = 0.;
    double displacement_rate  = 0.; // NaN where there is no rate
    double stress_rate        = 0.;
  };

  /**
   * One row of the order study: the degrees of the blocks on a mesh level.
   * A one-block study has one degree and no rows per block.
   */
  struct OrderStudyRow
  {
    std::vector<unsigned int> degrees; // per block, in the order of block ids
    unsigned int              refinement = 0;
    unsigned int              n_cells    = 0;
    unsigned int              n_dofs     = 0;
    OrderStudyErrors          total;
    std::vector<OrderStudyErrors> blocks; // several blocks only
  };

  /**
   * The comparison a user of this tool makes first: the same problem at
   * element orders p and mesh levels, with L2 errors of displacement and
   * stress against the closed form and the observed rates (expected p+1
   * and p for smooth solutions). The table goes to the screen and to CSV.
   *
   * A model of several blocks is run whole (contact, load history) for
   * each combination of block degrees and each level, and the table has
   * the errors of every block beside those of the model: how the order of
   * one block shows in its own stress and in its neighbours'.
   */
  template <int dim>
  class OrderStudy
  {
  public:
    OrderStudy(const Parameters<dim> &parameters, ConditionalOStream &pcout);

    void
    run();

    /**
     * Rates between consecutive levels of each degree, in place; none where
     * an error is below @p round_off_floor.
     */
    static void
    compute_rates(std::vector<OrderStudyRow> &rows,
                  const double                round_off_floor);

  private:
    /**
     * Sets whole_model and block_ids from the mesh, the excavation and the
     * stages; refuses 'all combinations' over node-to-node interfaces.
     */
    void
    find_blocks();

    /** The degrees of the blocks in each row, in the table's order. */
    std::vector<std::vector<unsigned int>>
    degree_cases() const;

    /** solve_model() or solve_block(), by whole_model. */
    OrderStudyRow
    solve_one(const std::vector<unsigned int> &degrees,
              const unsigned int               refinement) const;

    /** A one-block model: the block alone, its load at the final time. */
    OrderStudyRow
    solve_block(const unsigned int degree, const unsigned int refinement) const;

    /**
     * A model of several blocks: the whole simulation with these block
     * degrees, its output under a base name that names the case.
     */
    OrderStudyRow
    solve_model(const std::vector<unsigned int> &degrees,
                const unsigned int               refinement) const;

    /** The model's parameters for one case: degrees, level, base name. */
    Parameters<dim>
    case_parameters(const std::vector<unsigned int> &degrees,
                    const unsigned int               refinement) const;

    /** A row's cells, DoFs and errors, of the blocks in block_ids. */
    OrderStudyRow
    errors_of(const std::vector<std::unique_ptr<Block<dim>>> &blocks) const;

    /**
     * solve_one() for every degree and level, in the table's order. Under
     * mpirun each rank solves a share of a one-block study's cases and the
     * rows are exchanged; a model of several blocks runs every case on
     * all ranks, its blocks shared out (doc/parallel.md).
     */
    std::vector<OrderStudyRow>
    solve_all(const Timer &timer) const;

    void
    print_table(const std::vector<OrderStudyRow> &rows) const;

    /** The table of a model of several blocks: the model, then each block. */
    void
    print_block_table(const std::vector<OrderStudyRow> &rows) const;

    /** The CSV; a model of several blocks adds columns per block id. */
    void
    write_csv(const std::vector<OrderStudyRow> &rows) const;

    const Parameters<dim> &parameters;
    ConditionalOStream    &pcout;

    /**
     * A mesh of several material ids: each case is the whole simulation
     * (MultiBodyProblem), even where excavation leaves one block.
     */
    bool whole_model = false;

    /** 'Block degrees = same': a row is named by its one degree. */
    bool same_degrees = true;

    /**
     * The blocks of the final body (neither excavated nor removed by a
     * stage), whose errors the table shows; set by find_blocks().
     */
    std::vector<types::material_id> block_ids;
  };
} // namespace mbfem

#endif

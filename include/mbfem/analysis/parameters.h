#ifndef mbfem_analysis_parameters_h
#define mbfem_analysis_parameters_h

#include <mbfem/analysis/exact_solution.h>
#include <mbfem/analysis/load_history.h>
#include <mbfem/analysis/order_study.h>
#include <mbfem/analysis/reliability.h>
#include <mbfem/analysis/strength_reduction.h>
#include <mbfem/block/block.h>
#include <mbfem/block/boundary_conditions.h>
#include <mbfem/contact/contact_solver_parameters.h>
#include <mbfem/interface/contact_interface.h>
#include <mbfem/interface/joint_water.h>
#include <mbfem/linear_algebra/direct_solver.h>
#include <mbfem/material/in_situ_stress.h>
#include <mbfem/material/material.h>
#include <mbfem/material/plasticity.h>
#include <mbfem/mesh/mesh.h>
#include <mbfem/output/output.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace mbfem
{
  using namespace dealii;

  /** The top-level entries of a parameter file. */
  struct RunParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    unsigned int dimension = 2;
    std::string  mode      = "simulation";

    /** Screen output without timings or paths, for numdiff comparison. */
    bool test_mode = false;
  };

  /**
   * Everything a run reads from its parameter file. Each member declares
   * and parses its own subsection; this struct only gathers them, so the
   * documentation printed by `mbfem --print-parameters` is the manual.
   */
  template <int dim>
  struct Parameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /** @p input_folder: where relative paths in the file are taken from. */
    void
    parse_parameters(ParameterHandler &prm, const std::string &input_folder);

    RunParameters                          run;
    MeshParameters                         mesh;
    DiscretisationParameters               discretisation;
    Material                               material;
    std::map<types::material_id, Material> block_materials;
    DirectSolver::Parameters               linear_solver;
    BoundaryConditions<dim>                boundary_conditions;
    LoadHistory                            load_history;
    ExactSolution<dim>                     exact_solution;
    OutputParameters                       output;
    OrderStudyParameters                   order_study;
    ContactParameters                      contact;
    ContactSolverParameters                contact_solver;
    InSituStress                           in_situ_stress;
    Excavation                             excavation;
    PlasticityParameters                   plasticity;
    StrengthReductionParameters            strength_reduction;
    ReliabilityParameters                  reliability;
    WaterPressureParameters<dim>           water_pressure;
  };

  /**
   * Reads only "Dimension" from @p filename, so that main() can choose
   * Parameters<2> or Parameters<3>. Throws with the file name if the file
   * cannot be read.
   */
  unsigned int
  read_dimension(const std::string &filename);

  /** Declares, reads @p filename (.prm or .json) and parses. */
  template <int dim>
  void
  read_parameters(const std::string &filename, Parameters<dim> &parameters);
} // namespace mbfem

#endif

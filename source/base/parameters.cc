#include <mbfem/base/parameters.h>

#include <filesystem>
#include <fstream>

namespace mbfem
{
  void
  RunParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension: 2 (plane strain) or 3.");
    prm.declare_entry(
      "Mode",
      "simulation",
      Patterns::Selection("simulation|order study"),
      "'simulation': run the load history once. 'order study': solve the "
      "problem for every degree and refinement level in subsection 'Order "
      "study' and tabulate the errors against subsection 'Exact solution'.");
    prm.declare_entry(
      "Test mode",
      "false",
      Patterns::Bool(),
      "Leave timings and machine-dependent text out of the screen output, "
      "so that it can be compared with stored output (ctest).");
  }



  void
  RunParameters::parse_parameters(ParameterHandler &prm)
  {
    dimension = prm.get_integer("Dimension");
    mode      = prm.get("Mode");
    test_mode = prm.get_bool("Test mode");
  }



  template <int dim>
  void
  Parameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    RunParameters::declare_parameters(prm);
    MeshParameters::declare_parameters(prm);
    DiscretisationParameters::declare_parameters(prm);
    Material::declare_parameters(prm);
    DirectSolver::Parameters::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm);
    LoadHistory::declare_parameters(prm);
    ExactSolution<dim>::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    OrderStudyParameters::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    InSituStress::declare_parameters(prm);
    Excavation::declare_parameters(prm);
    PlasticityParameters::declare_parameters(prm);
  }



  template <int dim>
  void
  Parameters<dim>::parse_parameters(ParameterHandler  &prm,
                                    const std::string &input_folder)
  {
    run.parse_parameters(prm);
    mesh.parse_parameters(prm, input_folder);
    discretisation.parse_parameters(prm);
    material.parse_parameters(prm);
    block_materials = Material::parse_block_materials(prm);
    linear_solver.parse_parameters(prm);
    boundary_conditions.parse_parameters(prm);
    load_history.parse_parameters(prm);
    exact_solution.parse_parameters(prm);
    output.parse_parameters(prm);
    order_study.parse_parameters(prm);
    contact.parse_parameters(prm);
    in_situ_stress.parse_parameters(prm);
    excavation.parse_parameters(prm);
    plasticity.parse_parameters(prm);
    const bool excavates = !excavation.excavated_ids.empty() ||
                           !excavation.released_boundaries.empty();
    AssertThrow(!excavates || in_situ_stress.enabled,
                ExcMessage("Excavation: an excavation releases the in-situ "
                           "stress, so it needs 'In-situ stress/Enabled = "
                           "true'."));

    AssertThrow(run.mode != "order study" || exact_solution.enabled,
                ExcMessage("Mode = order study measures errors: set 'Exact "
                           "solution/Compute errors = true' and give the "
                           "exact displacement and stress."));
  }



  namespace
  {
    void
    check_readable(const std::string &filename)
    {
      AssertThrow(std::filesystem::is_regular_file(filename) &&
                    std::ifstream(filename).good(),
                  ExcMessage("Cannot read the parameter file <" + filename +
                             ">."));
    }
  } // namespace



  unsigned int
  read_dimension(const std::string &filename)
  {
    check_readable(filename);
    ParameterHandler prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    // Everything else is read (and checked) by read_parameters().
    prm.parse_input(filename, "", true);
    return prm.get_integer("Dimension");
  }



  template <int dim>
  void
  read_parameters(const std::string &filename, Parameters<dim> &parameters)
  {
    check_readable(filename);
    ParameterHandler prm;
    Parameters<dim>::declare_parameters(prm);
    prm.parse_input(filename);

    const std::filesystem::path folder =
      std::filesystem::path(filename).parent_path();
    parameters.parse_parameters(prm, folder.empty() ? "." : folder.string());
  }



  template struct Parameters<2>;
  template struct Parameters<3>;
  template void
  read_parameters(const std::string &, Parameters<2> &);
  template void
  read_parameters(const std::string &, Parameters<3> &);
} // namespace mbfem

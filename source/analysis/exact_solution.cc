#include <mbfem/analysis/exact_solution.h>
#include <mbfem/block/boundary_conditions.h>

namespace mbfem
{
  template <int dim>
  void
  ExactSolution<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    {
      prm.declare_entry("Compute errors",
                        "false",
                        Patterns::Bool(),
                        "Measure the L2 errors of displacement and stress "
                        "against the functions below at the end of the run.");
      prm.enter_subsection("Displacement");
      Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
      prm.leave_subsection();
      prm.enter_subsection("Stress");
      Functions::ParsedFunction<dim>::declare_parameters(prm, dim * dim);
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  ExactSolution<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    {
      enabled = prm.get_bool("Compute errors");
      prm.enter_subsection("Displacement");
      displacement =
        parse_function<dim>(prm, dim, "Exact solution/Displacement");
      prm.leave_subsection();
      prm.enter_subsection("Stress");
      stress = parse_function<dim>(prm, dim * dim, "Exact solution/Stress");
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }



  template struct ExactSolution<2>;
  template struct ExactSolution<3>;
} // namespace mbfem

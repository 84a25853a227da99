#ifndef mbfem_analysis_exact_solution_h
#define mbfem_analysis_exact_solution_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>

#include <memory>

namespace mbfem
{
  using namespace dealii;

  /**
   * A closed-form displacement and stress, given in the input file, against
   * which the L2 errors of a run are measured (subsection "Exact
   * solution"). This is how the element-order studies are verified.
   */
  template <int dim>
  struct ExactSolution
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    bool enabled = false;

    /** dim components. */
    std::shared_ptr<Functions::ParsedFunction<dim>> displacement;

    /** dim*dim components: sigma_xx; sigma_xy; sigma_yx; sigma_yy in 2D. */
    std::shared_ptr<Functions::ParsedFunction<dim>> stress;
  };
} // namespace mbfem

#endif

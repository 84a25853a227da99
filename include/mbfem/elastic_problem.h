#ifndef mbfem_elastic_problem_h
#define mbfem_elastic_problem_h

#include <deal.II/base/conditional_ostream.h>

namespace mbfem
{
  using namespace dealii;

  template <int dim>
  struct Parameters;

  /**
   * A single elastic block taken through the load history: mesh, stiffness
   * factorised once, one solve per increment, VTU/PVD output and a summary
   * (with errors when an exact solution is given). The multi-body solver
   * drives many such blocks; this is the one-block case on its own.
   */
  template <int dim>
  class ElasticProblem
  {
  public:
    ElasticProblem(Parameters<dim> &parameters, ConditionalOStream &pcout);

    void
    run();

  private:
    Parameters<dim>    &parameters;
    ConditionalOStream &pcout;
  };
} // namespace mbfem

#endif

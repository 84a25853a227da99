#ifndef mbfem_analysis_block_measures_h
#define mbfem_analysis_block_measures_h

#include <mbfem/block/block.h>
#include <mbfem/contact/contact_solver.h>

#include <deal.II/base/function.h>

#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * L2 errors against a closed-form solution, absolute and relative, and
   * the L2 norms of the exact fields (zero where an exact field is zero:
   * the relative error is then the absolute one).
   */
  struct ErrorNorms
  {
    double displacement          = 0.;
    double displacement_relative = 0.;
    double stress                = 0.;
    double stress_relative       = 0.;
    double displacement_norm     = 0.;
    double stress_norm           = 0.;
  };

  /**
   * The errors of several blocks as one body: absolute errors and exact
   * norms summed in squares, relative to the summed norm (absolute where
   * the exact field is zero throughout).
   */
  ErrorNorms
  combine_errors(const std::vector<ErrorNorms> &blocks);

  /**
   * L2 norms of u - u_exact and sigma - sigma_exact over @p block (the
   * latter a function with dim*dim components, row by row), each also
   * relative to the norm of the exact field. Elastic blocks are integrated
   * with QGauss(p + 3); plastic ones at the points of their stress state,
   * where their plastic strain is known.
   */
  template <int dim>
  ErrorNorms
  compute_errors(const Block<dim>    &block,
                 const Function<dim> &exact_displacement,
                 const Function<dim> &exact_stress);

  /**
   * Largest displacement magnitude over the support points (Lagrange
   * elements: nodal values are point values, so this is the maximum a
   * user sees in ParaView).
   */
  template <int dim>
  double
  max_displacement(const Block<dim> &block);

  /** Largest von Mises stress over the points of the stress state. */
  template <int dim>
  double
  max_von_mises_stress(const Block<dim> &block);

  /** Largest tangential relative displacement over the pairs of @p solver. */
  template <int dim>
  double
  max_slip(const ContactSolver<dim> &solver);
} // namespace mbfem

#endif

#ifndef mbfem_interface_pair_equation_h
#define mbfem_interface_pair_equation_h

#include <deal.II/base/tensor.h>

namespace mbfem
{
  using namespace dealii;

  /**
   * The equation a contact state (the paper's Table 1) gives one direction
   * of one pair, in the pair's frame (normal, tangents):
   *
   *   force_coefficients . rho_k + displacement_coefficients . d_k = value,
   *
   * rho_k the pair's force on its block b and d_k = u_b - u_a its relative
   * displacement, both in the frame. Open: rho = 0; closed (normal) and
   * stuck (tangential): a prescribed d; slipping: the friction law.
   *
   * Both contact formulations solve the same equations and differ only in
   * how d depends on the unknowns: through the blocks' flexibilities
   * (condensed) or through the displacement fields themselves (monolithic),
   * which is what makes the second a reference for the first.
   */
  template <int dim>
  struct PairEquation
  {
    Tensor<1, dim> force_coefficients;
    Tensor<1, dim> displacement_coefficients;
    double         value = 0.;

    bool
    has_force_terms() const
    {
      return force_coefficients.norm_square() > 0.;
    }
  };
} // namespace mbfem

#endif

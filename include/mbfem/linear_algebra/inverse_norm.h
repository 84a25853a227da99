#ifndef mbfem_linear_algebra_inverse_norm_h
#define mbfem_linear_algebra_inverse_norm_h

#include <deal.II/lac/vector.h>

#include <functional>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * |M^{-1}|_1 estimated from below, for the condition estimates of the
   * state systems (CondensedSystem, UpdatedLU; LAPACKFullMatrix's own
   * estimate is for Cholesky): two pseudo-random right-hand sides p, p_i =
   * sin(1.3 + 0.7 i (trial + 1)) + 0.1 on the entries @p support (the i-th
   * of them; every entry where it is empty) and zero elsewhere, and
   * |M^{-1} p|_1 / |p|_1 over the same entries. @p apply replaces its
   * argument (of size @p n) by M^{-1} times it. Infinite where a probe
   * overflows past a tiny pivot.
   */
  double
  inverse_norm_estimate(const unsigned int                           n,
                        const std::vector<unsigned int>             &support,
                        const std::function<void(Vector<double> &)> &apply);
} // namespace mbfem

#endif

// mbfem::NewtonJacobian's solves with old factors: J = D + A on 600
// unknowns (pairs of 2, A random with 40 entries per row, so that its LU
// fills in and a factorisation costs many substitutions, as on the jointed
// slope). The first solve factorises; a J that differs in the two rows of
// one pair (a pair that changes state, or a joint that breaks) is solved
// by GMRES with the old factors (rank 2: at most 3 iterations in exact
// arithmetic), and its solution agrees with a fresh LU's to 1e-10 (GMRES's
// residual is 1e-12 of b, the condition of J about 10); a J whose diagonal
// changed in every row by factors spread from 0.1 to 10 (GMRES would need
// far more iterations than a factorisation costs) is factorised again; a
// J with a zero row is reported singular (false).

#include <mbfem/contact/newton_jacobian.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace dealii;

namespace
{
  const unsigned int n = 600, block_size = 2;

  std::vector<mbfem::NewtonJacobian::Row>
  random_rows()
  {
    std::mt19937                                random(3);
    std::uniform_int_distribution<unsigned int> column(0, n - 1);
    std::uniform_real_distribution<double>      value(-0.05, 0.05);
    std::vector<mbfem::NewtonJacobian::Row>     rows(n);
    for (auto &row : rows)
      for (unsigned int k = 0; k < 40; ++k)
        row.emplace_back(column(random), value(random));
    return rows;
  }

  /**
   * J = diagonal + factor times A's row i (@p factor_of_pair_0 for rows 0
   * and 1), the diagonal times 10^sin(7 i) with @p spread; row
   * @p zero_row zero.
   */
  void
  assemble(mbfem::NewtonJacobian &jacobian,
           const double           factor_of_pair_0,
           const bool             spread   = false,
           const unsigned int     zero_row = n)
  {
    jacobian.clear_jacobian();
    for (unsigned int i = 0; i < n; ++i)
      if (i != zero_row)
        {
          jacobian.add(i,
                       i,
                       (4. + std::sin(i)) *
                         (spread ? std::pow(10., std::sin(7. * i)) : 1.));
          jacobian.add_row_of_a(i, i, i < block_size ? factor_of_pair_0 : 1.);
        }
  }

  Vector<double>
  right_hand_side()
  {
    Vector<double> b(n);
    for (unsigned int i = 0; i < n; ++i)
      b(i) = std::cos(1. + i);
    return b;
  }

  /** The same J solved by a NewtonJacobian that has no old factors. */
  Vector<double>
  fresh_solution(const double factor_of_pair_0, const bool spread)
  {
    mbfem::NewtonJacobian jacobian;
    jacobian.reinit(random_rows(), n, block_size);
    assemble(jacobian, factor_of_pair_0, spread);
    Vector<double> x = right_hand_side();
    jacobian.solve(x);
    return x;
  }

  void
  report(const char *label, const mbfem::NewtonJacobian &jacobian)
  {
    const auto [factorised, gmres] = jacobian.solve_counts();
    std::printf("%s: factorisations %u, solves with old factors %u\n",
                label,
                factorised,
                gmres);
  }
} // namespace

int
main()
{
  mbfem::NewtonJacobian jacobian;
  jacobian.reinit(random_rows(), n, block_size);

  assemble(jacobian, 1.);
  Vector<double> x = right_hand_side();
  std::printf("first J solved: %s\n", jacobian.solve(x) ? "yes" : "NO");
  report("first J", jacobian);

  // Pair 0's rows changed: GMRES with the old factors.
  assemble(jacobian, -2.);
  x                     = right_hand_side();
  const bool     solved = jacobian.solve(x);
  Vector<double> error  = fresh_solution(-2., false);
  error -= x;
  std::printf("pair 0 changed: solved %s, agrees with a new LU to 1e-10: %s\n",
              solved ? "yes" : "NO",
              error.linfty_norm() <= 1e-10 * x.linfty_norm() ? "yes" : "NO");
  report("pair 0 changed", jacobian);

  // Every row changed, the eigenvalues of J J_0^{-1} spread: a new LU.
  assemble(jacobian, -2., true);
  x     = right_hand_side();
  error = fresh_solution(-2., true);
  std::printf("every row changed: solved %s", jacobian.solve(x) ? "yes" : "NO");
  error -= x;
  std::printf(", agrees with a new LU to 1e-10: %s\n",
              error.linfty_norm() <= 1e-10 * x.linfty_norm() ? "yes" : "NO");
  report("every row changed", jacobian);

  // A zero row: neither GMRES nor the LU it falls back to solves it.
  assemble(jacobian, -2., true, 7);
  x = right_hand_side();
  std::printf("a zero row is reported singular: %s\n",
              jacobian.solve(x) ? "NO" : "yes");
  report("zero row", jacobian);
}

// mbfem::NewtonJacobian's solves with old factors: J = D + A on 600
// unknowns (pairs of 2, A random with 40 entries per row, so that its LU
// fills in and a factorisation costs many substitutions, as on the jointed
// slope). The first solve factorises; a J that differs in the two rows of
// one pair (a pair that changes state, or a joint that breaks) is solved
// by GMRES with the old factors (rank 2: at most 3 iterations in exact
// arithmetic); the same J again by the old factors alone; a J whose
// diagonal also changed in 20 more rows by factors spread from 0.1 to 10
// (rank 22, beyond GMRES's budget of about 20 iterations here) makes
// GMRES give up and J be factorised; a J changed in every row is
// factorised without trying GMRES; each answer agrees with a fresh LU's
// to 1e-9 in the 2-norm (GMRES's residual is within 1e-11 of b's, the
// condition of J at most about 100); a J with a zero row is reported
// singular (false).

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
   * and 1), the diagonal of rows 2 ... @p n_spread + 1 times
   * 10^sin(7 i); row @p zero_row zero.
   */
  void
  assemble(mbfem::NewtonJacobian &jacobian,
           const double           factor_of_pair_0,
           const unsigned int     n_spread = 0,
           const unsigned int     zero_row = n)
  {
    jacobian.clear_jacobian();
    for (unsigned int i = 0; i < n; ++i)
      if (i != zero_row)
        {
          const bool spread = i >= 2 && i < n_spread + 2;
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
  fresh_solution(const double factor_of_pair_0, const unsigned int n_spread)
  {
    mbfem::NewtonJacobian jacobian;
    jacobian.reinit(random_rows(), n, block_size);
    assemble(jacobian, factor_of_pair_0, n_spread);
    Vector<double> x = right_hand_side();
    jacobian.solve(x);
    return x;
  }

  /** Solves J, compares with a fresh LU, prints the counts. */
  void
  solve_and_report(const char            *label,
                   mbfem::NewtonJacobian &jacobian,
                   const double           factor_of_pair_0,
                   const unsigned int     n_spread)
  {
    Vector<double> x      = right_hand_side();
    const bool     solved = jacobian.solve(x);
    Vector<double> error  = fresh_solution(factor_of_pair_0, n_spread);
    error -= x;
    const auto [factorised, old_factors] = jacobian.solve_counts();
    std::printf("%s: solved %s, agrees with a new LU to 1e-9: %s; "
                "factorisations %u, solves with old factors %u\n",
                label,
                solved ? "yes" : "NO",
                error.l2_norm() <= 1e-9 * x.l2_norm() ? "yes" : "NO",
                factorised,
                old_factors);
  }
} // namespace

int
main()
{
  mbfem::NewtonJacobian jacobian;
  jacobian.reinit(random_rows(), n, block_size);

  assemble(jacobian, 1.);
  solve_and_report("first J", jacobian, 1., 0);
  assemble(jacobian, -2.);
  solve_and_report("pair 0 changed", jacobian, -2., 0);
  solve_and_report("the same J again", jacobian, -2., 0);
  assemble(jacobian, -2., 20);
  solve_and_report("20 more rows changed", jacobian, -2., 20);
  assemble(jacobian, -2., n - 2);
  solve_and_report("every row changed", jacobian, -2., n - 2);

  // A zero row: neither GMRES nor the LU it falls back to solves it.
  assemble(jacobian, -2., n - 2, 7);
  Vector<double> x = right_hand_side();
  std::printf("a zero row is reported singular: %s\n",
              jacobian.solve(x) ? "NO" : "yes");
}

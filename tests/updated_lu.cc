// mbfem::UpdatedLU: solves with a sparse matrix whose rows differ from a
// factorised base in a few places, by the Sherman-Morrison-Woodbury
// formula. A_0 = diagonal + 40 random entries per row on 600 unknowns
// (condition some 10); each A below is also factorised densely (LAPACK) as
// the reference. Checked: two rows replaced (a pair that switches state)
// solve to 1e-12 of the dense answer in the max norm, with a backward error
// below 1e-14 (one refinement step gives eps-level errors; the bound leaves
// room for rounding in the residual); a row replaced by a unit row (a pair
// that opens) gives x_i = b_i; Z's columns are computed once per row
// (three rows after {5, 6} then {5, 6, 7}); condition_bound(), built from
// probes that estimate inverses' norms from below, is at least a tenth of
// the condition number of A (dense inverse; CondensedSystem trusts it only
// a hundred times below its limit); an empty change is A_0 itself;
// a change with more rows than max_rank() is refused, and so is one that
// makes A singular (a row replaced by a copy of another). A right-hand side
// that differs from one solved before only in replaced rows is solved from
// the remembered A_0^{-1} b (no substitution), one that differs elsewhere
// by a substitution; both to 1e-12 of the dense answer.

#include <mbfem/linear_algebra/updated_lu.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace dealii;
using Row = mbfem::UpdatedLU::Row;

namespace
{
  const unsigned int n = 600;

  Row
  random_row(const unsigned int i, std::mt19937 &random)
  {
    std::uniform_int_distribution<unsigned int> column(0, n - 1);
    std::uniform_real_distribution<double>      value(-0.05, 0.05);
    std::map<unsigned int, double>              entries;
    entries[i] = 4. + std::sin(i);
    for (unsigned int k = 0; k < 40; ++k)
      entries[column(random)] += value(random);
    return Row(entries.begin(), entries.end());
  }

  /** The rows of A_0 with @p indices replaced by @p rows. */
  std::vector<Row>
  changed(std::vector<Row>                 rows,
          const std::vector<unsigned int> &indices,
          const std::vector<Row>          &new_rows)
  {
    for (unsigned int a = 0; a < indices.size(); ++a)
      rows[indices[a]] = new_rows[a];
    return rows;
  }

  LAPACKFullMatrix<double>
  dense(const std::vector<Row> &rows)
  {
    LAPACKFullMatrix<double> a(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (const auto &[j, value] : rows[i])
        a(i, j) += value;
    return a;
  }

  Vector<double>
  right_hand_side()
  {
    Vector<double> b(n);
    for (unsigned int i = 0; i < n; ++i)
      b(i) = std::cos(0.3 * i) + 0.5;
    return b;
  }

  /** Solves A x = b by @p lu and densely; prints the agreement. */
  void
  compare(const char             *what,
          const mbfem::UpdatedLU &lu,
          const std::vector<Row> &rows,
          const Vector<double>   &b = right_hand_side())
  {
    Vector<double>           x         = b;
    const double             error     = lu.solve(x);
    LAPACKFullMatrix<double> a         = dense(rows);
    Vector<double>           reference = b;
    a.compute_lu_factorization();
    a.solve(reference);
    Vector<double> difference = x;
    difference -= reference;
    std::printf("%s: rank %u, agrees with a dense LU to 1e-12: %s, "
                "backward error below 1e-14: %s\n",
                what,
                lu.rank(),
                difference.linfty_norm() <= 1e-12 * reference.linfty_norm() ?
                  "yes" :
                  "no",
                error < 1e-14 ? "yes" : "no");
  }
} // namespace



int
main()
{
  std::mt19937     random(7);
  std::vector<Row> base(n);
  for (unsigned int i = 0; i < n; ++i)
    base[i] = random_row(i, random);
  mbfem::UpdatedLU lu;
  std::printf("base factorised: %s\n", lu.factorize(base) ? "yes" : "no");
  compare("no change", lu, base);

  // A pair switches: rows 5 and 6 anew.
  const std::vector<unsigned int> pair      = {5, 6};
  const std::vector<Row>          pair_rows = {random_row(5, random),
                                               random_row(6, random)};
  std::printf("two rows replaced: %s\n",
              lu.replace_rows(pair, pair_rows) ? "yes" : "no");
  const std::vector<Row> a_pair = changed(base, pair, pair_rows);
  compare("two rows", lu, a_pair);

  // Its condition number against the bound.
  LAPACKFullMatrix<double> inverse = dense(a_pair);
  const double             norm    = inverse.l1_norm();
  inverse.invert();
  std::printf("condition bound at least a tenth of the condition number: %s\n",
              lu.condition_bound() >= 0.1 * norm * inverse.l1_norm() ? "yes" :
                                                                       "no");

  // Then row 7 opens (a unit row): x_7 = b_7, Z's columns of rows 5 and 6
  // kept.
  const std::vector<unsigned int> three      = {5, 6, 7};
  const std::vector<Row>          three_rows = {pair_rows[0],
                                                pair_rows[1],
                                                Row{{7, 1.}}};
  std::printf("three rows replaced: %s\n",
              lu.replace_rows(three, three_rows) ? "yes" : "no");
  compare("three rows", lu, changed(base, three, three_rows));
  Vector<double> x = right_hand_side();
  lu.solve(x);
  std::printf("x_7 = b_7 to 1e-14: %s\n",
              std::abs(x(7) - right_hand_side()(7)) < 1e-14 ? "yes" : "no");

  // The right-hand side changes in replaced row 6 (a switched pair's
  // equation has a new value): no substitution; in row 20: one.
  const std::vector<Row> a_three = changed(base, three, three_rows);
  Vector<double>         b       = right_hand_side();
  b(6) += 0.7;
  unsigned int recalled = lu.solve_counts().second;
  compare("b changed in a replaced row", lu, a_three, b);
  std::printf("A_0^{-1} b from the remembered one: %s\n",
              lu.solve_counts().second == recalled + 1 ? "yes" : "no");
  b(20) += 0.3;
  recalled                       = lu.solve_counts().second;
  const unsigned int substituted = lu.solve_counts().first;
  compare("b changed in a row not replaced", lu, a_three, b);
  std::printf("A_0^{-1} b by a substitution: %s\n",
              lu.solve_counts().second == recalled &&
                  lu.solve_counts().first > substituted ?
                "yes" :
                "no");
  std::printf("factorisations %u, columns of Z computed %u\n",
              lu.counts().first,
              lu.counts().second);

  // No change: A_0 again.
  lu.replace_rows({}, {});
  compare("change undone", lu, base);

  // Too many rows, and a singular A (row 9 a copy of row 8).
  std::vector<unsigned int> many;
  std::vector<Row>          many_rows;
  for (unsigned int i = 0; i <= lu.max_rank(); ++i)
    {
      many.push_back(10 + i);
      many_rows.push_back(random_row(10 + i, random));
    }
  std::printf("more than max_rank() rows refused: %s\n",
              lu.replace_rows(many, many_rows) ? "no" : "yes");
  std::printf("a singular change refused: %s\n",
              lu.replace_rows({9}, {base[8]}) ? "no" : "yes");
  recalled = lu.solve_counts().second;
  compare("after the refusals", lu, base);
  std::printf("b solved before recalled after a refused change: %s\n",
              lu.solve_counts().second == recalled + 1 ? "yes" : "no");

  // A new factorisation forgets every remembered b.
  const unsigned int substitutions = lu.solve_counts().first;
  lu.factorize(a_three);
  recalled = lu.solve_counts().second;
  compare("a new base", lu, a_three);
  std::printf("b solved again after the new factorisation: %s\n",
              lu.solve_counts().second == recalled &&
                  lu.solve_counts().first > substitutions ?
                "yes" :
                "no");
}

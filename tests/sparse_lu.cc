// mbfem::SparseLU (UMFPACK with METIS ordering, the symbolic analysis kept
// while the pattern stays): on a random unsymmetric sparse matrix of 400
// unknowns with a structurally unsymmetric pattern and a zero block on the
// diagonal (a saddle point, as the Newton Jacobian's floating-mode rows),
// the solution of A x = b has a relative residual below 1e-12 (LU with
// partial pivoting on a matrix of condition about 1e3: round-off times the
// condition and the growth, far below); a second matrix of the same
// pattern reuses the analysis and is solved as accurately; a third with a
// different pattern is analysed again; a matrix with a third of its rows
// reduced to their diagonal, factorised with its zeros kept and then left
// out, is solved as accurately each time, analysed anew for the nonzeros
// (which a pattern with the zeros would not need) and reused for them; the
// nested_dissection ordering (SparseLU::set_blocks(), a pair's two rows
// merged or not, pairs half reduced, blocks not filling the rows declared)
// solves such a matrix as accurately with METIS's order; a matrix with a
// zero row is reported singular (false), not thrown.

#include <mbfem/linear_algebra/sparse_lu.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <cstdio>
#include <random>
#include <utility>

using namespace dealii;

namespace
{
  // Rows 0 .. n - m - 1: diagonal 4 plus random entries; rows n - m ...:
  // coupling rows with a zero diagonal (the transpose of a few columns).
  void
  fill(const SparsityPattern &pattern,
       SparseMatrix<double>  &matrix,
       const unsigned int     n_modes,
       std::mt19937          &random)
  {
    std::uniform_real_distribution<double> uniform(-1., 1.);
    const unsigned int                     n = pattern.n_rows();
    matrix.reinit(pattern);
    for (unsigned int i = 0; i < n; ++i)
      for (auto entry = pattern.begin(i); entry != pattern.end(i); ++entry)
        {
          const unsigned int j = entry->column();
          if (i < n - n_modes)
            matrix.set(i, j, i == j ? 4. + uniform(random) : uniform(random));
          else if (i != j)
            matrix.set(i, j, 1. + 0.5 * uniform(random));
        }
  }

  double
  relative_residual(const SparseMatrix<double> &matrix,
                    const Vector<double>       &x,
                    const Vector<double>       &b)
  {
    Vector<double> r(b.size());
    matrix.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }

  /** Factorises, solves and prints the counts and the residual's test. */
  void
  factorise_and_report(const char                 *label,
                       mbfem::SparseLU            &lu,
                       const SparseMatrix<double> &matrix,
                       const Vector<double>       &b,
                       const bool                  drop_zeros)
  {
    const bool     factorised = lu.factorize(matrix, drop_zeros);
    Vector<double> x(b);
    if (factorised)
      lu.solve(x);
    const auto [reused, analysed] = lu.symbolic_counts();
    std::printf("%sfactorised: %s, analyses %u, reuses %u, residual below "
                "1e-12: %s\n",
                label,
                factorised ? "yes" : "no",
                analysed,
                reused,
                factorised && relative_residual(matrix, x, b) < 1e-12 ? "yes" :
                                                                        "NO");
  }

  void
  pattern_of(const unsigned int n,
             const unsigned int n_modes,
             const unsigned int seed,
             SparsityPattern   &pattern)
  {
    std::mt19937                                random(seed);
    std::uniform_int_distribution<unsigned int> column(0, n - n_modes - 1);
    DynamicSparsityPattern                      dsp(n, n);
    for (unsigned int i = 0; i < n - n_modes; ++i)
      {
        dsp.add(i, i);
        for (unsigned int k = 0; k < 5; ++k)
          dsp.add(i, column(random)); // unsymmetric pattern
      }
    for (unsigned int a = n - n_modes; a < n; ++a)
      for (unsigned int k = 0; k < 20; ++k)
        {
          const unsigned int j = column(random);
          dsp.add(a, j);
          dsp.add(j, a);
        }
    pattern.copy_from(dsp);
  }
} // namespace

int
main()
{
  const unsigned int n = 400, n_modes = 6;
  std::mt19937       random(7);
  SparsityPattern    pattern, other_pattern;
  pattern_of(n, n_modes, 1, pattern);
  pattern_of(n, n_modes, 2, other_pattern);
  SparseMatrix<double> matrix;
  Vector<double>       b(n);
  for (unsigned int i = 0; i < n; ++i)
    b(i) = std::sin(1. + i);

  mbfem::SparseLU lu;
  for (const auto *p : {&pattern, &pattern, &other_pattern})
    {
      fill(*p, matrix, n_modes, random);
      factorise_and_report("", lu, matrix, b, false);
    }

  // Exact zeros kept, then left out (drop_zeros, as for a Newton Jacobian
  // whose open pairs' rows hold zeros): the same accuracy; leaving them
  // out needs an analysis of its own, reused for the same zeros.
  fill(pattern, matrix, n_modes, random);
  for (unsigned int i = 0; i < n - n_modes; i += 3)
    for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
      if (entry->column() != i)
        entry->value() = 0.;
  for (const bool drop_zeros : {false, true, true})
    factorise_and_report(drop_zeros ? "zeros left out: " : "zeros kept: ",
                         lu,
                         matrix,
                         b,
                         drop_zeros);

  // METIS's nested dissection of the merged graph (a pair's two rows and
  // columns one vertex, the singletons first and left out), with every
  // third pair's rows reduced to their diagonal (open pairs), one row of
  // every fifth pair too (a pair half singleton), and the zeros left out:
  // as accurate, with METIS's order used, for blocks of two over all pair
  // rows, none, and blocks of three over a count that is no multiple of
  // three.
  fill(pattern, matrix, n_modes, random);
  for (unsigned int i = 0; i < n - n_modes; i += 2)
    for (unsigned int r = i; r < i + (i % 10 == 0 ? 1 : 2); ++r)
      if (i % 6 == 0 || i % 10 == 0)
        for (auto entry = matrix.begin(r); entry != matrix.end(r); ++entry)
          if (entry->column() != r)
            entry->value() = 0.;
  for (const auto &[block_size, n_blocked] :
       {std::pair<unsigned int, unsigned int>{2, n - n_modes},
        {1, n - n_modes},
        {3, n - n_modes - 1}})
    {
      mbfem::SparseLU nested(mbfem::SparseLU::Ordering::nested_dissection);
      nested.set_blocks(block_size, n_blocked);
      std::printf("nested dissection, blocks of %u over %u rows: ",
                  block_size,
                  n_blocked);
      factorise_and_report("", nested, matrix, b, true);
      std::printf("  METIS's order used: %s\n",
                  nested.order_given() ? "yes" : "NO");
    }

  // A zero row: singular, reported by false.
  fill(pattern, matrix, n_modes, random);
  for (auto entry = matrix.begin(10); entry != matrix.end(10); ++entry)
    entry->value() = 0.;
  std::printf("a matrix with a zero row is reported singular: %s\n",
              lu.factorize(matrix) ? "NO" : "yes");
}

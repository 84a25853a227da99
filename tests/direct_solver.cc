// The block's direct solver must give the same answer for a block of
// right-hand sides in one call as for each one alone (the flexibility of
// the multi-body method is computed that way), and agree with the
// stiffness: ||K x - b|| / ||b|| at round-off.

#include <mbfem/linear_algebra/direct_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <cstdio>
#include <iostream>

using namespace dealii;

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // A 1D Laplacian with a Dirichlet row at each end, n = 200, plus a
  // non-symmetric coupling to exercise a general sparse pattern.
  const unsigned int     n = 200;
  DynamicSparsityPattern dsp(n);
  for (unsigned int i = 0; i < n; ++i)
    for (int j = static_cast<int>(i) - 1; j <= static_cast<int>(i) + 1; ++j)
      if (j >= 0 && j < static_cast<int>(n))
        dsp.add(i, j);
  dsp.add(0, n - 1);
  TrilinosWrappers::SparseMatrix matrix;
  matrix.reinit(complete_index_set(n),
                complete_index_set(n),
                dsp,
                MPI_COMM_SELF);
  for (unsigned int i = 0; i < n; ++i)
    {
      matrix.set(i, i, 2.);
      if (i > 0)
        matrix.set(i, i - 1, -1.);
      if (i + 1 < n)
        matrix.set(i, i + 1, -1.);
    }
  matrix.set(0, n - 1, 0.5);
  matrix.compress(VectorOperation::insert);

  for (const std::string package : {"Amesos_Klu", "Amesos_Mumps"})
    {
      mbfem::DirectSolver solver(package);
      solver.factorize(matrix);

      const unsigned int  n_rhs = 7;
      std::vector<double> b(n * n_rhs), x_block(n * n_rhs);
      for (unsigned int k = 0; k < n_rhs; ++k)
        for (unsigned int i = 0; i < n; ++i)
          b[k * n + i] = std::sin(0.1 * (k + 1) * i) + (i == k ? 1. : 0.);
      solver.solve(x_block.data(), b.data(), n_rhs);

      double max_difference = 0., max_residual = 0.;
      for (unsigned int k = 0; k < n_rhs; ++k)
        {
          Vector<double> bk(b.begin() + k * n, b.begin() + (k + 1) * n);
          Vector<double> xk(n), r(n);
          solver.solve(xk, bk);
          for (unsigned int i = 0; i < n; ++i)
            max_difference =
              std::max(max_difference, std::abs(xk(i) - x_block[k * n + i]));
          matrix.vmult(r, xk);
          r -= bk;
          max_residual = std::max(max_residual, r.l2_norm() / bk.l2_norm());
        }
      std::printf("%s: %u right-hand sides; block vs single solves %s, "
                  "residual %s\n",
                  package.c_str(),
                  n_rhs,
                  max_difference < 1e-12 ? "agree" : "DIFFER",
                  max_residual < 1e-12 ? "at round-off" : "TOO LARGE");
    }
}

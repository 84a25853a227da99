#include <mbfem/base/exceptions.h>
#include <mbfem/linear_algebra/mumps_solver.h>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>
#include <mpi.h>

#include <algorithm>
#include <numeric>
#include <type_traits>

namespace mbfem
{
  struct MumpsSolver::Data
  {
    DMUMPS_STRUC_C         id;
    bool                   initialised = false;
    std::vector<MUMPS_INT> rows, columns;
    std::vector<double>    values;
  };



  namespace
  {
    /** MUMPS's ICNTL(i), 1-based as in its manual. */
    MUMPS_INT &
    icntl(DMUMPS_STRUC_C &id, const unsigned int i)
    {
      return id.icntl[i - 1];
    }
  } // namespace



  MumpsSolver::MumpsSolver()
    : data(std::make_unique<Data>())
  {}



  MumpsSolver::~MumpsSolver()
  {
    if (data->initialised)
      {
        data->id.job = -2;
        dmumps_c(&data->id);
      }
  }



  void
  MumpsSolver::run(const int job, const char *what) const
  {
    data->id.job = job;
    dmumps_c(&data->id);
    const int info1 = data->id.infog[0], info2 = data->id.infog[1];
    if (info1 == -10)
      AssertThrow(false,
                  Exceptions::ExcSingularMatrix(
                    "The stiffness matrix is singular (MUMPS, " +
                    std::string(what) +
                    "): the supports leave a rigid-body motion free."));
    AssertThrow(info1 >= 0,
                ExcMessage("MUMPS failed in " + std::string(what) +
                           ": INFOG(1) = " + std::to_string(info1) +
                           ", INFOG(2) = " + std::to_string(info2) +
                           " (see the MUMPS users' guide, section 'Error "
                           "diagnostics')."));
  }



  void
  MumpsSolver::set_matrix(const TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    data->rows.clear();
    data->columns.clear();
    data->values.clear();
    data->rows.reserve(A.NumMyNonzeros() / 2 + A.NumMyRows());
    data->columns.reserve(A.NumMyNonzeros() / 2 + A.NumMyRows());
    data->values.reserve(A.NumMyNonzeros() / 2 + A.NumMyRows());
    for (int i = 0; i < A.NumMyRows(); ++i)
      {
        int     n;
        double *values;
        int    *indices;
        A.ExtractMyRowView(i, n, values, indices);
        const int row = A.GRID(i);
        for (int j = 0; j < n; ++j)
          {
            const int column = A.GCID(indices[j]);
            // The upper triangle; explicit zeros off the diagonal (the
            // constrained rows and columns) need not be factorised.
            if (column < row || (values[j] == 0. && column != row))
              continue;
            data->rows.push_back(row + 1);
            data->columns.push_back(column + 1);
            data->values.push_back(values[j]);
          }
      }
    DMUMPS_STRUC_C &id = data->id;
    id.n               = A.NumGlobalRows();
    id.nnz             = data->values.size();
    id.irn             = data->rows.data();
    id.jcn             = data->columns.data();
    id.a               = data->values.data();
  }



  void
  MumpsSolver::factorize(const TrilinosWrappers::SparseMatrix &matrix,
                         const bool positive_definite)
  {
    DMUMPS_STRUC_C &id = data->id;
    if (data->initialised)
      {
        id.job = -2;
        dmumps_c(&id);
      }
    id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
    id.par          = 1;
    id.sym          = positive_definite ? 1 : 2;
    id.job          = -1;
    dmumps_c(&id);
    data->initialised = true;
    // Silent; PORD is the only fill-reducing ordering in Debian's MUMPS
    // (METIS and SCOTCH requests silently become it).
    icntl(id, 1) = -1;
    icntl(id, 2) = -1;
    icntl(id, 3) = -1;
    icntl(id, 4) = 0;
    icntl(id, 7) = 4;
    // More workspace than the analysis estimates: a second pass after
    // INFOG(1) = -9 would cost a whole factorisation.
    icntl(id, 14) = 40;
    set_matrix(matrix);
    run(4, "analysis and factorisation");
  }



  void
  MumpsSolver::solve(double            *x,
                     const double      *b,
                     const unsigned int n_vectors) const
  {
    Assert(data->initialised, ExcMessage("factorize() first."));
    if (n_vectors == 0)
      return;
    DMUMPS_STRUC_C &id = data->id;
    std::copy(b, b + size() * n_vectors, x);
    icntl(id, 20) = 0;
    icntl(id, 30) = 0;
    id.nrhs       = n_vectors;
    id.lrhs       = id.n;
    id.rhs        = x;
    run(3, "solve");
  }



  void
  MumpsSolver::selected_entries(std::vector<int>    &pointers,
                                std::vector<int>    &indices,
                                std::vector<double> &values) const
  {
    static_assert(std::is_same_v<MUMPS_INT, int>,
                  "MUMPS with 32-bit integers (the header uses int)");
    DMUMPS_STRUC_C &id = data->id;
    icntl(id, 20)      = 0;
    icntl(id, 30)      = 1;
    id.nz_rhs          = indices.size();
    id.nrhs            = id.n;
    id.irhs_ptr        = pointers.data();
    id.irhs_sparse     = indices.data();
    id.rhs_sparse      = values.data();
    run(3, "entries of the inverse");
    icntl(id, 30) = 0;
  }



  FullMatrix<double>
  MumpsSolver::inverse_entries(const std::vector<unsigned int> &rows,
                               const std::vector<unsigned int> &columns) const
  {
    Assert(data->initialised, ExcMessage("factorize() first."));
    DMUMPS_STRUC_C    &id = data->id;
    const unsigned int m = rows.size(), n = columns.size();
    FullMatrix<double> result(m, n);
    if (m == 0 || n == 0)
      return result;

    // The requested entries as a sparse matrix in compressed columns over
    // all N columns of A^{-1}; MUMPS wants each column's rows once.
    std::vector<unsigned int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](unsigned int i, unsigned int j) {
      return columns[i] < columns[j];
    });
    std::vector<MUMPS_INT> pointers(id.n + 1, 0);
    for (const unsigned int j : columns)
      pointers[j + 1] = m;
    for (MUMPS_INT j = 0; j < id.n; ++j)
      pointers[j + 1] += pointers[j];
    std::vector<MUMPS_INT> indices(std::size_t(m) * n);
    std::vector<double>    values(indices.size());
    for (std::size_t c = 0, k = 0; c < n; ++c)
      {
        // Duplicate columns would be requested twice: skip them here and
        // copy below.
        if (c > 0 && columns[order[c]] == columns[order[c - 1]])
          continue;
        for (unsigned int i = 0; i < m; ++i, ++k)
          indices[k] = rows[i] + 1;
      }
    for (MUMPS_INT &p : pointers)
      ++p;

    selected_entries(pointers, indices, values);

    for (std::size_t c = 0, k = 0; c < n; ++c)
      {
        if (c > 0 && columns[order[c]] == columns[order[c - 1]])
          {
            for (unsigned int i = 0; i < m; ++i)
              result(i, order[c]) = result(i, order[c - 1]);
            continue;
          }
        for (unsigned int i = 0; i < m; ++i, ++k)
          result(i, order[c]) = values[k];
      }
    return result;
  }



  std::vector<std::vector<double>>
  MumpsSolver::inverse_entries(
    const std::vector<std::vector<unsigned int>> &rows_of_column) const
  {
    Assert(data->initialised, ExcMessage("factorize() first."));
    DMUMPS_STRUC_C &id = data->id;
    AssertDimension(rows_of_column.size(), static_cast<std::size_t>(id.n));
    std::vector<std::vector<double>> result(rows_of_column.size());
    std::vector<MUMPS_INT>           pointers(id.n + 1, 1), indices;
    for (MUMPS_INT j = 0; j < id.n; ++j)
      {
        for (const unsigned int i : rows_of_column[j])
          indices.push_back(i + 1);
        pointers[j + 1] = indices.size() + 1;
      }
    if (indices.empty())
      return result;
    std::vector<double> values(indices.size());

    selected_entries(pointers, indices, values);

    for (MUMPS_INT j = 0; j < id.n; ++j)
      result[j].assign(values.begin() + pointers[j] - 1,
                       values.begin() + pointers[j + 1] - 1);
    return result;
  }



  std::size_t
  MumpsSolver::size() const
  {
    return data->initialised ? data->id.n : 0;
  }
} // namespace mbfem

#include <mbfem/linear_algebra/sparse_lu.h>

#include <deal.II/base/exceptions.h>

#include <umfpack.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>

namespace mbfem
{
  namespace
  {
    /** UMFPACK's defaults, with @p ordering. */
    std::array<double, UMFPACK_CONTROL>
    control(const SparseLU::Ordering ordering)
    {
      std::array<double, UMFPACK_CONTROL> c;
      umfpack_dl_defaults(c.data());
      c[UMFPACK_ORDERING] = ordering == SparseLU::Ordering::metis ?
                              UMFPACK_ORDERING_METIS :
                              UMFPACK_ORDERING_AMD;
      return c;
    }

    void
    check(const long status, const char *step)
    {
      AssertThrow(status == UMFPACK_OK,
                  ExcMessage(std::string("UMFPACK's ") + step +
                             " failed with status " + std::to_string(status) +
                             " (umfpack.h lists the codes)."));
    }
  } // namespace



  SparseLU::SparseLU(const Ordering ordering)
    : ordering(ordering)
  {}



  SparseLU::~SparseLU()
  {
    clear_numeric();
    clear_symbolic();
  }



  void
  SparseLU::clear_symbolic()
  {
    if (symbolic != nullptr)
      umfpack_dl_free_symbolic(&symbolic);
    symbolic = nullptr;
  }



  void
  SparseLU::clear_numeric()
  {
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
    numeric = nullptr;
  }



  bool
  SparseLU::factorize(const SparseMatrix<double> &matrix, const bool drop_zeros)
  {
    Assert(matrix.m() == matrix.n(), ExcNotQuadratic());
    const long n = matrix.m();
    // A's rows as A^T's columns, sorted (deal.II keeps the diagonal first).
    std::vector<long>   start(n + 1, 0), index;
    std::vector<double> value;
    index.reserve(matrix.n_nonzero_elements());
    value.reserve(matrix.n_nonzero_elements());
    std::vector<std::pair<long, double>> row;
    for (long i = 0; i < n; ++i)
      {
        row.clear();
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          if (!drop_zeros || entry->value() != 0.)
            row.emplace_back(entry->column(), entry->value());
        std::sort(row.begin(), row.end());
        for (const auto &[column, v] : row)
          {
            index.push_back(column);
            value.push_back(v);
          }
        start[i + 1] = index.size();
      }
    const bool same_pattern =
      symbolic != nullptr && start == column_start && index == row_index;
    column_start.swap(start);
    row_index.swap(index);
    values.swap(value);

    const auto                       c = control(ordering);
    std::array<double, UMFPACK_INFO> info;
    clear_numeric();
    if (same_pattern)
      ++reused;
    else
      {
        clear_symbolic();
        check(umfpack_dl_symbolic(n,
                                  n,
                                  column_start.data(),
                                  row_index.data(),
                                  values.data(),
                                  &symbolic,
                                  c.data(),
                                  info.data()),
              "symbolic analysis");
        ++analysed;
      }
    const long status = umfpack_dl_numeric(column_start.data(),
                                           row_index.data(),
                                           values.data(),
                                           symbolic,
                                           &numeric,
                                           c.data(),
                                           info.data());
    if (status == UMFPACK_WARNING_singular_matrix)
      {
        clear_numeric();
        return false;
      }
    check(status, "numeric factorisation");
    factor_flops   = info[UMFPACK_FLOPS];
    factor_entries = info[UMFPACK_LNZ] + info[UMFPACK_UNZ];
    return true;
  }



  void
  SparseLU::set_ordering(const Ordering new_ordering)
  {
    if (new_ordering != ordering)
      clear_symbolic();
    ordering = new_ordering;
  }



  void
  SparseLU::solve(Vector<double> &x, const bool refine) const
  {
    Assert(numeric != nullptr, ExcMessage("SparseLU: nothing factorised."));
    Assert(x.size() + 1 == column_start.size(),
           ExcDimensionMismatch(x.size(), column_start.size() - 1));
    const Vector<double> b = x;
    auto                 c = control(ordering);
    if (!refine)
      c[UMFPACK_IRSTEP] = 0;
    std::array<double, UMFPACK_INFO> info;
    // The factors are of A^T: UMFPACK_Aat solves (A^T)^T x = A x = b.
    check(umfpack_dl_solve(UMFPACK_Aat,
                           column_start.data(),
                           row_index.data(),
                           values.data(),
                           x.begin(),
                           b.begin(),
                           numeric,
                           c.data(),
                           info.data()),
          "solve");
  }



  double
  SparseLU::substitutions_per_factorization() const
  {
    return factor_entries > 0. ? factor_flops / (2. * factor_entries) : 0.;
  }



  std::pair<unsigned int, unsigned int>
  SparseLU::symbolic_counts() const
  {
    return {reused, analysed};
  }
} // namespace mbfem

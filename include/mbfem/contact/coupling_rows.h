#ifndef mbfem_contact_coupling_rows_h
#define mbfem_contact_coupling_rows_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * A matrix stored by rows of its non-zero entries: P_hat, whose row of a
   * pair direction couples the modes of the pair's two blocks only (at
   * most 2 x 3 in 2D, 2 x 6 in 3D) however many blocks float. Dense, the
   * 1000-block wall's P_hat (13972 rows by 3036 modes) took 339 MB, twice
   * while it was built; a model of n blocks needed n^2 of it.
   */
  class CouplingRows
  {
  public:
    /** (column, value), columns ascending. */
    using Entry = std::pair<unsigned int, double>;

    CouplingRows() = default;

    /** Every entry of @p dense, zeros included (for tests' small blocks). */
    explicit CouplingRows(const FullMatrix<double> &dense);

    /** No rows, @p n_columns columns. */
    void
    reinit(const unsigned int n_columns);

    /** Appends a row; @p row's columns ascending and below n(). */
    void
    add_row(const std::vector<Entry> &row);

    unsigned int
    m() const
    {
      return row_start.size() - 1;
    }

    unsigned int
    n() const
    {
      return n_columns;
    }

    /** The stored entries of row @p r (zeros included where computed). */
    ArrayView<const Entry>
    row(const unsigned int r) const
    {
      AssertIndexRange(r, m());
      return make_array_view(entries.data() + row_start[r],
                             entries.data() + row_start[r + 1]);
    }

    /** The entry (@p r, @p column), 0 where none is stored. */
    double
    operator()(const unsigned int r, const unsigned int column) const
    {
      for (const auto &[c, value] : row(r))
        if (c == column)
          return value;
      return 0.;
    }

  private:
    unsigned int             n_columns = 0;
    std::vector<std::size_t> row_start = {0};
    std::vector<Entry>       entries;
  };
} // namespace mbfem

#endif

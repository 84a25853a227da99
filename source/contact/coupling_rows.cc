#include <mbfem/contact/coupling_rows.h>

namespace mbfem
{
  CouplingRows::CouplingRows(const FullMatrix<double> &dense)
  {
    reinit(dense.n());
    std::vector<Entry> row(dense.n());
    for (unsigned int i = 0; i < dense.m(); ++i)
      {
        for (unsigned int a = 0; a < dense.n(); ++a)
          row[a] = {a, dense(i, a)};
        add_row(row);
      }
  }



  void
  CouplingRows::reinit(const unsigned int n_columns_)
  {
    n_columns = n_columns_;
    row_start = {0};
    entries.clear();
  }



  void
  CouplingRows::add_row(const std::vector<Entry> &row)
  {
    for (unsigned int i = 0; i < row.size(); ++i)
      {
        AssertIndexRange(row[i].first, n_columns);
        Assert(i == 0 || row[i - 1].first < row[i].first, ExcInternalError());
      }
    entries.insert(entries.end(), row.begin(), row.end());
    row_start.push_back(entries.size());
  }
} // namespace mbfem

#include <mbfem/contact/newton_jacobian.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
#include <cmath>

namespace mbfem
{
  namespace internal
  {
    /**
     * NewtonJacobian::solve() factorises the nonzeros alone where more
     * than this fraction of the pattern's entries is zero.
     */
    constexpr double zero_fraction = 0.25;
  } // namespace internal

  namespace
  {
    bool
    all_finite(const Vector<double> &v)
    {
      return std::all_of(v.begin(), v.end(), [](const double x) {
        return std::isfinite(x);
      });
    }
  } // namespace



  void
  NewtonJacobian::reinit(const std::vector<Row> &rows_of_a,
                         const unsigned int      n,
                         const unsigned int      block_size,
                         const bool              mode_diagonal)
  {
    n_rows_of_a = rows_of_a.size();
    DynamicSparsityPattern dsp(n, n);
    if (mode_diagonal)
      for (unsigned int i = n_rows_of_a; i < n; ++i)
        dsp.add(i, i);
    for (unsigned int i = 0; i < n_rows_of_a; ++i)
      {
        const unsigned int first = i - i % block_size;
        for (unsigned int f = 0; f < block_size; ++f)
          dsp.add(i, first + f);
        // A pair's row takes the other rows of its pair (add_row_of_a()):
        // every row of a pair holds the columns of all of them.
        for (const auto &[column, value] : rows_of_a[i])
          {
            for (unsigned int f = 0; f < block_size; ++f)
              dsp.add(first + f, column);
            // The floating blocks' rows: the coupling's transpose.
            if (column >= n_rows_of_a)
              dsp.add(column, i);
          }
      }
    pattern.copy_from(dsp);
    a_matrix.reinit(pattern);
    jacobian.reinit(pattern);
    augmented.clear();
    augmented_pattern.reinit(0, 0, 0);
    for (unsigned int i = 0; i < n_rows_of_a; ++i)
      for (const auto &[column, value] : rows_of_a[i])
        a_matrix.add(i, column, value);
  }



  unsigned int
  NewtonJacobian::size() const
  {
    return pattern.n_rows();
  }



  void
  NewtonJacobian::multiply(const Vector<double> &u, Vector<double> &d) const
  {
    d.reinit(size());
    a_matrix.vmult(d, u);
  }



  void
  NewtonJacobian::clear_jacobian()
  {
    jacobian = 0.;
  }



  void
  NewtonJacobian::add(const unsigned int row,
                      const unsigned int column,
                      const double       value)
  {
    jacobian.add(row, column, value);
  }



  void
  NewtonJacobian::add_row_of_a(const unsigned int row,
                               const unsigned int source,
                               const double       factor)
  {
    for (auto entry = a_matrix.begin(source); entry != a_matrix.end(source);
         ++entry)
      if (entry->value() != 0.)
        jacobian.add(row, entry->column(), factor * entry->value());
  }



  bool
  NewtonJacobian::solve(Vector<double> &b)
  {
    // The pattern holds every entry the pairs' states could give: an open
    // pair's rows hold its blocks' flexibility columns as zeros. Where
    // many entries are zero, the LU of the nonzeros alone pays for a new
    // analysis (cube_5x5x5, about 43 % of the pairs open: its Newton run
    // 91 -> 55 s); where few are, the kept analysis wins (the jointed
    // slope, about 5 % open: increment 1 77 -> 114 s with the nonzeros
    // alone), hence the threshold.
    std::size_t zeros = 0;
    for (auto entry = jacobian.begin(); entry != jacobian.end(); ++entry)
      zeros += (entry->value() == 0.);
    const bool drop_zeros =
      zeros > internal::zero_fraction * jacobian.n_nonzero_elements();
    if (!lu.factorize(jacobian, drop_zeros))
      return false; // a zero pivot
    lu.solve(b);
    return all_finite(b);
  }



  bool
  NewtonJacobian::damped_least_squares(const Vector<double> &residual,
                                       const double          lambda,
                                       Vector<double>       &step)
  {
    // [I J; J^T -lambda D] [r; x] = [-F; 0]: r = -F - J x, and then
    // J^T (-F - J x) = lambda D x, D = diag(J^T J).
    const unsigned int  n = size();
    std::vector<double> column_norm(n, 0.);
    for (auto entry = jacobian.begin(); entry != jacobian.end(); ++entry)
      column_norm[entry->column()] += entry->value() * entry->value();

    if (augmented_pattern.n_rows() != 2 * n)
      {
        DynamicSparsityPattern dsp(2 * n, 2 * n);
        for (unsigned int i = 0; i < n; ++i)
          {
            dsp.add(i, i);
            dsp.add(n + i, n + i);
            for (auto entry = pattern.begin(i); entry != pattern.end(i);
                 ++entry)
              {
                dsp.add(i, n + entry->column());
                dsp.add(n + entry->column(), i);
              }
          }
        augmented_pattern.copy_from(dsp);
        augmented.reinit(augmented_pattern);
      }
    augmented = 0.;
    for (unsigned int i = 0; i < n; ++i)
      {
        augmented.add(i, i, 1.);
        augmented.add(n + i, n + i, -lambda * std::max(column_norm[i], 1e-300));
        for (auto entry = jacobian.begin(i); entry != jacobian.end(i); ++entry)
          {
            augmented.add(i, n + entry->column(), entry->value());
            augmented.add(n + entry->column(), i, entry->value());
          }
      }
    Vector<double> x(2 * n);
    for (unsigned int i = 0; i < n; ++i)
      x(i) = -residual(i);
    if (!augmented_lu.factorize(augmented))
      return false;
    augmented_lu.solve(x);
    step.reinit(n);
    for (unsigned int i = 0; i < n; ++i)
      step(i) = x(n + i);
    return all_finite(step);
  }
} // namespace mbfem

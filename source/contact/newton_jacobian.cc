#include <mbfem/base/hash.h>
#include <mbfem/contact/newton_jacobian.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace mbfem
{
  namespace internal
  {
    /**
     * NewtonJacobian::solve() factorises the nonzeros alone where more
     * than this fraction of the pattern's entries is zero.
     */
    constexpr double zero_fraction = 0.25;

    /**
     * GMRES's largest basis when it solves with old factors (n vectors of
     * the Jacobian's size).
     */
    constexpr unsigned int max_gmres_iterations = 50;

    /** GMRES's relative residual: the step is that of the LU to it. */
    constexpr double gmres_tolerance = 1e-12;
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
    lu.set_blocks(block_size, n_rows_of_a);
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
    factored_rows.clear();
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
    if (!all_finite(b))
      return false; // no solver makes a finite step of it
    // One pass over J: the rows changed since the factorisation, and the
    // hashes that a new one keeps.
    const std::vector<std::uint64_t> hashes = row_hashes();
    if (!factored_rows.empty())
      {
        const unsigned int n_changed = count_changed(hashes);
        if (n_changed == 0)
          {
            // The J factorised: its factors, as a new LU would give them.
            ++n_old_factors;
            lu.solve(b);
            return all_finite(b);
          }
        // GMRES converges as fast as a change of that many rows allows
        // only where the changes are small: where far more rows changed
        // than the budget has iterations (3D slip directions turn in
        // every slipping pair's rows; on cube_5x5x5 760 to 1800 rows,
        // GMRES failing in 9 of 11 tries), the factorisation comes at once.
        const unsigned int budget = gmres_budget();
        if (budget > 0 && !refactorize_next && n_changed <= 4 * budget)
          {
            const unsigned int used = solve_with_old_lu(b, budget, n_changed);
            if (used <= budget)
              {
                ++n_old_factors;
                // Past half its budget GMRES will soon need more: the next
                // solve factorises instead of trying it first.
                refactorize_next = (2 * used > budget);
                return all_finite(b);
              }
          }
      }
    refactorize_next = false;
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
    // An analysis per factorisation where the zeros are dropped: the
    // nested dissection of the merged graph (UMFPACK's METIS option builds
    // A^T A's pattern whole, which on the cube took more time than the
    // factorisation); where the analysis is kept, that option.
    lu.set_ordering(drop_zeros ? SparseLU::Ordering::nested_dissection :
                                 SparseLU::Ordering::metis);
    ++n_factorized;
    // No factors to reuse until this factorisation has succeeded.
    factored_rows.clear();
    if (!lu.factorize(jacobian, drop_zeros))
      return false; // a zero pivot
    factored_rows = hashes;
    lu.solve(b);
    return all_finite(b);
  }



  std::pair<unsigned int, unsigned int>
  NewtonJacobian::solve_counts() const
  {
    return {n_factorized, n_old_factors};
  }



  unsigned int
  NewtonJacobian::gmres_budget() const
  {
    // A substitution costs more time per flop than a factorisation
    // (memory against dense kernels): on the jointed slope's Jacobian a
    // factorisation is 222 substitutions' flops but 45 substitutions'
    // time. A tenth of the flop ratio keeps a try within about half a
    // factorisation.
    const double ratio = lu.substitutions_per_factorization();
    if (!(ratio > 0.))
      return 0;
    return static_cast<unsigned int>(
      std::min(ratio / 10., double(internal::max_gmres_iterations)));
  }



  std::vector<std::uint64_t>
  NewtonJacobian::row_hashes() const
  {
    // Each value's bits mixed into its row's hash: a row whose hash is
    // unchanged has (but for a collision, which costs GMRES iterations,
    // not accuracy) the values it had.
    std::vector<std::uint64_t> hashes(jacobian.m());
    for (unsigned int i = 0; i < jacobian.m(); ++i)
      {
        std::uint64_t hash = Hash::start;
        for (auto entry = jacobian.begin(i); entry != jacobian.end(i); ++entry)
          {
            const double  value = entry->value();
            std::uint64_t bits;
            std::memcpy(&bits, &value, sizeof(double));
            hash = Hash::add(hash, bits);
          }
        hashes[i] = hash;
      }
    return hashes;
  }



  unsigned int
  NewtonJacobian::count_changed(const std::vector<std::uint64_t> &hashes) const
  {
    unsigned int n_changed = 0;
    for (unsigned int i = 0; i < hashes.size(); ++i)
      n_changed += (hashes[i] != factored_rows[i]);
    return n_changed;
  }



  namespace
  {
    /** The old factors as GMRES's preconditioner: dst = J_0^{-1} src. */
    class OldFactors
    {
    public:
      explicit OldFactors(const SparseLU &lu)
        : lu(lu)
      {}

      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        dst = src;
        lu.solve(dst, false);
      }

    private:
      const SparseLU &lu;
    };
  } // namespace



  unsigned int
  NewtonJacobian::solve_with_old_lu(Vector<double>    &b,
                                    const unsigned int budget,
                                    const unsigned int n_changed) const
  {
    const unsigned int failed = budget + 1;
    const double       norm   = b.l2_norm();
    if (norm == 0.)
      return 0; // x = 0 = b
    // Rank n_changed: GMRES ends within n_changed + 1 iterations in exact
    // arithmetic; two more for the rounding of substitutions without
    // refinement. No restart: its basis holds them all.
    const unsigned int max_iterations = std::min(budget, n_changed + 3);
    SolverControl      control(max_iterations,
                          internal::gmres_tolerance * norm,
                          false,
                          false);
    SolverGMRES<Vector<double>> gmres(
      control,
      SolverGMRES<Vector<double>>::AdditionalData(max_iterations + 2, true));
    Vector<double> x(b.size());
    try
      {
        gmres.solve(jacobian, x, b, OldFactors(lu));
      }
    catch (const SolverControl::NoConvergence &)
      {
        return failed;
      }
    // The true residual, which GMRES's estimate is in exact arithmetic
    // only, within ten times the tolerance.
    Vector<double> residual(b.size());
    jacobian.vmult(residual, x);
    residual -= b;
    if (!(residual.l2_norm() <= 10. * internal::gmres_tolerance * norm))
      return failed;
    b = x;
    return control.last_step();
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

#include <mbfem/linear_algebra/inverse_norm.h>
#include <mbfem/linear_algebra/updated_lu.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace mbfem
{
  namespace internal
  {
    /**
     * How many base solutions UpdatedLU remembers: the load path solves
     * each state set at s = 0 and s = 1, the fast iteration at s = 1; two
     * more keep those of an earlier state set.
     */
    constexpr unsigned int n_remembered = 4;
  } // namespace internal



  bool
  UpdatedLU::factorize(const std::vector<Row> &rows)
  {
    const unsigned int n = rows.size();
    z.clear();
    z_norm.clear();
    base_solutions.clear();
    forget_change();
    is_factorized = false;

    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (const auto &[j, value] : rows[i])
        dsp.add(i, j);
    base.clear();
    pattern.copy_from(dsp);
    base.reinit(pattern);
    for (unsigned int i = 0; i < n; ++i)
      for (const auto &[j, value] : rows[i])
        base.add(i, j, value);
    base_norm = base.linfty_norm();

    ++n_factorizations;
    is_factorized = lu.factorize(base, true);
    if (is_factorized)
      estimate_base_condition();
    return is_factorized;
  }



  void
  UpdatedLU::estimate_base_condition()
  {
    Vector<double> column_sum(size());
    for (unsigned int i = 0; i < size(); ++i)
      for (auto entry = base.begin(i); entry != base.end(i); ++entry)
        column_sum(entry->column()) += std::abs(entry->value());
    base_l1_norm = column_sum.linfty_norm();
    base_inverse_l1_norm =
      inverse_norm_estimate(size(), {}, [this](Vector<double> &x) {
        substitute(x, false);
      });
  }



  double
  UpdatedLU::condition_bound() const
  {
    // A^{-1} = (I - Z S^{-1} D) A_0^{-1}, so
    // |A^{-1}|_1 <= |A_0^{-1}|_1 (1 + |Z|_1 |S^{-1}|_1 |D|_1), and
    // |A|_1 <= |A_0|_1 + |D|_1; each inverse's norm estimated from below.
    return (base_l1_norm + change_l1_norm) * base_inverse_l1_norm *
           (1. + z_l1_norm * capacitance_inverse_l1_norm * change_l1_norm);
  }



  void
  UpdatedLU::set_blocks(const unsigned int size, const unsigned int n_in_blocks)
  {
    lu.set_blocks(size, n_in_blocks);
  }



  bool
  UpdatedLU::factorized() const
  {
    return is_factorized;
  }



  unsigned int
  UpdatedLU::size() const
  {
    return base.m();
  }



  unsigned int
  UpdatedLU::rank() const
  {
    return changed.size();
  }



  unsigned int
  UpdatedLU::max_rank() const
  {
    // Half the flop ratio: a substitution takes some five times more time
    // per flop than a factorisation (on the slope the flop ratio is 222,
    // the time ratio 45), so a factorisation costs about as much time as
    // the substitutions of Z's columns for half as many rows.
    const double ratio = lu.substitutions_per_factorization();
    return static_cast<unsigned int>(std::clamp(ratio / 2., 8., 200.));
  }



  bool
  UpdatedLU::replace_rows(const std::vector<unsigned int> &indices,
                          const std::vector<Row>          &rows)
  {
    Assert(is_factorized, ExcMessage("UpdatedLU: nothing factorised."));
    AssertDimension(indices.size(), rows.size());
    // The last change, whose entries of S the new one reuses.
    std::vector<unsigned int> last_changed;
    std::vector<Row>          last_difference;
    FullMatrix<double>        last_entries;
    last_changed.swap(changed);
    last_difference.swap(difference);
    last_entries.swap(capacitance_entries);
    forget_change();
    const unsigned int m = indices.size();
    if (m == 0)
      return true;
    if (m > max_rank())
      return false;

    for (unsigned int a = 0; a < m; ++a)
      add_difference(indices[a], rows[a]);
    drop_unused_columns();
    compute_missing_columns();

    assemble_capacitance(last_changed, last_difference, last_entries);
    try
      {
        capacitance.compute_lu_factorization();
      }
    catch (const LACExceptions::ExcSingular &)
      {
        forget_change();
        return false;
      }
    set_change_norms();

    // A nearly singular S (S is I where nothing changed, so its inverse's
    // norm alone says how close A is to singular relative to A_0), or an A
    // that may be near its caller's limit of regular systems: refused, the
    // caller's own LU decides.
    if (!(capacitance_inverse_l1_norm < 1e10 && condition_bound() < 1e12))
      {
        forget_change();
        return false;
      }
    return true;
  }



  void
  UpdatedLU::add_difference(const unsigned int i, const Row &row)
  {
    // d = new row - old row, merged over the two sorted rows.
    Row old;
    for (auto entry = base.begin(i); entry != base.end(i); ++entry)
      if (entry->value() != 0.)
        old.emplace_back(entry->column(), entry->value());
    std::sort(old.begin(), old.end());
    Row    d;
    double norm = 0.;
    auto   p    = old.begin();
    for (const auto &[j, value] : row)
      {
        for (; p != old.end() && p->first < j; ++p)
          d.emplace_back(p->first, -p->second);
        double v = value;
        if (p != old.end() && p->first == j)
          v -= (p++)->second;
        if (v != 0.)
          d.emplace_back(j, v);
        norm += std::abs(value);
      }
    for (; p != old.end(); ++p)
      d.emplace_back(p->first, -p->second);
    changed.push_back(i);
    difference.push_back(std::move(d));
    changed_row_norm.push_back(norm);
  }



  void
  UpdatedLU::drop_unused_columns()
  {
    // Once there are twice as many columns as a change may have, so that
    // Z holds at most 3 max_rank() columns.
    if (z.size() <= 2 * max_rank())
      return;
    for (auto column = z.begin(); column != z.end();)
      if (std::find(changed.begin(), changed.end(), column->first) ==
          changed.end())
        {
          z_norm.erase(column->first);
          column = z.erase(column);
        }
      else
        ++column;
  }



  void
  UpdatedLU::compute_missing_columns()
  {
    // One unrefined substitution each: its errors are those of A_0's
    // factors, which the refinement in solve() corrects.
    for (const unsigned int i : changed)
      if (z.find(i) == z.end())
        {
          Vector<double> column(size());
          column(i) = 1.;
          substitute(column, false);
          z_norm[i] = column.l1_norm();
          z.emplace(i, std::move(column));
          ++n_columns;
        }
  }



  void
  UpdatedLU::set_change_norms()
  {
    capacitance_inverse_l1_norm =
      inverse_norm_estimate(changed.size(), {}, [this](Vector<double> &x) {
        capacitance.solve(x);
      });
    z_l1_norm = 0.;
    for (const unsigned int i : changed)
      z_l1_norm = std::max(z_l1_norm, z_norm.at(i));
    std::map<unsigned int, double> column_sum;
    for (const Row &d : difference)
      for (const auto &[j, value] : d)
        column_sum[j] += std::abs(value);
    change_l1_norm = 0.;
    for (const auto &[j, sum] : column_sum)
      change_l1_norm = std::max(change_l1_norm, sum);
  }



  void
  UpdatedLU::assemble_capacitance(const std::vector<unsigned int> &last_changed,
                                  const std::vector<Row>   &last_difference,
                                  const FullMatrix<double> &last_entries)
  {
    // S_ab = delta_ab + d_a . z_(i_b) depends on row i_a's difference and
    // on Z's column i_b only, and Z's columns stay until the next
    // factorisation: an entry whose row changed as before, against a
    // column of the last change, is the last change's. The load path
    // changes one pair more per call, so only S's new rows and columns
    // cost dot products, not all m^2 of them.
    const unsigned int        m = changed.size();
    std::vector<unsigned int> last_position(m, numbers::invalid_unsigned_int);
    std::vector<bool>         same_row(m, false);
    for (unsigned int a = 0; a < m; ++a)
      {
        const auto p =
          std::find(last_changed.begin(), last_changed.end(), changed[a]);
        if (p == last_changed.end())
          continue;
        last_position[a] = p - last_changed.begin();
        same_row[a]      = last_difference[last_position[a]] == difference[a];
      }
    capacitance_entries.reinit(m, m);
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int b = 0; b < m; ++b)
        {
          double value;
          if (same_row[a] && last_position[b] != numbers::invalid_unsigned_int)
            value = last_entries(last_position[a], last_position[b]);
          else
            {
              const Vector<double> &column = z.at(changed[b]);
              value                        = (a == b) ? 1. : 0.;
              for (const auto &[j, d] : difference[a])
                value += d * column(j);
            }
          capacitance_entries(a, b) = value;
        }
    capacitance.reinit(m, m);
    capacitance = capacitance_entries;
  }



  void
  UpdatedLU::forget_change()
  {
    changed.clear();
    difference.clear();
    changed_row_norm.clear();
    capacitance.reinit(0, 0);
    capacitance_entries.reinit(0, 0);
    change_l1_norm = z_l1_norm = capacitance_inverse_l1_norm = 0.;
  }



  void
  UpdatedLU::substitute(Vector<double> &x, const bool refine) const
  {
    lu.solve(x, refine);
    ++n_substitutions;
  }



  bool
  UpdatedLU::recall_base_solution(Vector<double> &x) const
  {
    std::vector<bool> is_changed(size(), false);
    for (const unsigned int i : changed)
      is_changed[i] = true;
    for (auto remembered = base_solutions.begin();
         remembered != base_solutions.end();
         ++remembered)
      {
        const auto &[b_0, y_0] = *remembered;
        bool same              = true;
        for (unsigned int j = 0; j < size() && same; ++j)
          same = is_changed[j] || x(j) == b_0(j);
        if (!same)
          continue;
        // y = A_0^{-1} (b_0 + sum_a (b - b_0)_(i_a) e_(i_a)).
        Vector<double> y = y_0;
        for (const unsigned int i : changed)
          if (x(i) != b_0(i))
            y.add(x(i) - b_0(i), z.at(i));
        x.swap(y);
        ++n_recalled;
        // The most recently used first: the one dropped is the one unused
        // the longest.
        std::rotate(base_solutions.begin(), remembered, remembered + 1);
        return true;
      }
    return false;
  }



  void
  UpdatedLU::apply_inverse(Vector<double> &x, const bool remember) const
  {
    if (!remember)
      substitute(x, false);
    else if (!recall_base_solution(x))
      {
        // Refined against A_0 (UMFPACK's own steps): every later solve
        // that recalls it starts from it.
        Vector<double> b = x;
        substitute(x, true);
        base_solutions.emplace(base_solutions.begin(), std::move(b), x);
        if (base_solutions.size() > internal::n_remembered)
          base_solutions.pop_back();
      }
    const unsigned int m = changed.size();
    if (m == 0)
      return;
    Vector<double> t(m);
    for (unsigned int a = 0; a < m; ++a)
      for (const auto &[j, d] : difference[a])
        t(a) += d * x(j);
    capacitance.solve(t);
    for (unsigned int b = 0; b < m; ++b)
      x.add(-t(b), z.at(changed[b]));
  }



  void
  UpdatedLU::vmult(Vector<double> &y, const Vector<double> &x) const
  {
    base.vmult(y, x);
    for (unsigned int a = 0; a < changed.size(); ++a)
      {
        double value = 0.;
        for (const auto &[j, d] : difference[a])
          value += d * x(j);
        y(changed[a]) += value;
      }
  }



  double
  UpdatedLU::infinity_norm() const
  {
    double norm = base_norm;
    for (const double row_norm : changed_row_norm)
      norm = std::max(norm, row_norm);
    return norm;
  }



  double
  UpdatedLU::l1_norm(const std::vector<bool> &columns) const
  {
    AssertDimension(columns.size(), size());
    Vector<double>    sum(size());
    std::vector<bool> is_changed(size(), false);
    for (const unsigned int i : changed)
      is_changed[i] = true;
    for (unsigned int i = 0; i < size(); ++i)
      if (!is_changed[i])
        for (auto entry = base.begin(i); entry != base.end(i); ++entry)
          sum(entry->column()) += std::abs(entry->value());
    // A changed row: its old entries plus its difference, column by column.
    for (unsigned int a = 0; a < changed.size(); ++a)
      {
        std::map<unsigned int, double> row;
        for (auto entry = base.begin(changed[a]); entry != base.end(changed[a]);
             ++entry)
          row[entry->column()] += entry->value();
        for (const auto &[j, d] : difference[a])
          row[j] += d;
        for (const auto &[j, value] : row)
          sum(j) += std::abs(value);
      }
    double norm = 0.;
    for (unsigned int j = 0; j < size(); ++j)
      if (columns[j])
        norm = std::max(norm, sum(j));
    return norm;
  }



  double
  UpdatedLU::solve(Vector<double> &x, const bool refine) const
  {
    Assert(is_factorized, ExcMessage("UpdatedLU: nothing factorised."));
    if (!refine)
      {
        apply_inverse(x);
        return 0.;
      }
    const Vector<double> b      = x;
    const double         a_norm = infinity_norm();
    Vector<double>       residual(b.size()), correction;
    double               error = 0.;
    apply_inverse(x, true);
    for (unsigned int step = 0;; ++step)
      {
        vmult(residual, x);
        residual.sadd(-1., 1., b);
        const double scale = a_norm * x.linfty_norm() + b.linfty_norm();
        error              = scale > 0. ? residual.linfty_norm() / scale : 0.;
        // Rounding in the residual itself is some n eps |A| |x|; a step
        // below ten times eps would not improve x.
        if (!std::isfinite(error) || error < 1e-15 || step == 2)
          break;
        correction = residual;
        apply_inverse(correction);
        x += correction;
      }
    return std::isfinite(error) ? error : std::numeric_limits<double>::max();
  }



  std::pair<unsigned int, unsigned int>
  UpdatedLU::counts() const
  {
    return {n_factorizations, n_columns};
  }



  std::pair<unsigned int, unsigned int>
  UpdatedLU::solve_counts() const
  {
    return {n_substitutions, n_recalled};
  }
} // namespace mbfem

#include <mbfem/contact/lemke_method.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace mbfem
{
  namespace
  {
    /** How Lemke's method ended. */
    enum class LemkeEnd
    {
      solution,
      ray,
      pivot_limit
    };

    /**
     * The tableau [B^-1 | -B^-1 M | -B^-1 1 | B^-1 q] of Lemke's method,
     * dense and row by row, with the basic variable of each row: w_i is
     * variable i, z_i is n + i, the artificial z_0 is 2 n.
     */
    class LemkeTableau
    {
    public:
      LemkeTableau(const FullMatrix<double> &M, const Vector<double> &q)
        : n(q.size())
        , width(2 * n + 2)
        , table(std::size_t(n) * width, 0.)
        , basis(n)
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            double *row = &table[std::size_t(i) * width];
            row[i]      = 1.;
            for (unsigned int j = 0; j < n; ++j)
              row[n + j] = -M(i, j);
            row[2 * n]     = -1.;
            row[2 * n + 1] = q(i);
          }
        std::iota(basis.begin(), basis.end(), 0u);
      }

      /**
       * Lemke's method with covering vector 1: z_0 enters on the row of
       * the most negative q, then the complement of each leaving variable,
       * until z_0 leaves (a solution) or no row bounds the entering one.
       */
      LemkeEnd
      run(const unsigned int max_pivots, unsigned int &pivots)
      {
        unsigned int row = 0;
        for (unsigned int i = 1; i < n; ++i)
          if (rhs(i) < rhs(row))
            row = i;
        unsigned int enter = 2 * n;
        for (;;)
          {
            pivot(row, enter);
            ++pivots;
            const unsigned int leave = basis[row];
            basis[row]               = enter;
            if (leave == 2 * n)
              return LemkeEnd::solution;
            if (pivots >= max_pivots)
              return LemkeEnd::pivot_limit;
            enter = (leave < n ? leave + n : leave - n);
            row   = ratio_test(enter);
            if (row == numbers::invalid_unsigned_int)
              {
                ray_variable = enter;
                return LemkeEnd::ray;
              }
          }
      }

      /**
       * At a ray, the variable that no row bounds: w_i as i, z_i as n + i.
       */
      unsigned int ray_variable = numbers::invalid_unsigned_int;

      /** The basic variable of each row (w_i as i, z_i as n + i). */
      const std::vector<unsigned int> &
      basic_variables() const
      {
        return basis;
      }

      /** z of the present basis. */
      Vector<double>
      z() const
      {
        Vector<double> z(n);
        for (unsigned int i = 0; i < n; ++i)
          if (basis[i] >= n && basis[i] < 2 * n)
            z(basis[i] - n) = rhs(i);
        return z;
      }

    private:
      double
      entry(const unsigned int i, const unsigned int j) const
      {
        return table[std::size_t(i) * width + j];
      }

      double
      rhs(const unsigned int i) const
      {
        return entry(i, width - 1);
      }

      /** Makes column @p enter the unit vector of row @p row. */
      void
      pivot(const unsigned int row, const unsigned int enter)
      {
        double      *pivot_row = &table[std::size_t(row) * width];
        const double p         = pivot_row[enter];
        Assert(p != 0., ExcInternalError());
        for (unsigned int j = 0; j < width; ++j)
          pivot_row[j] /= p;
        for (unsigned int i = 0; i < n; ++i)
          {
            double      *other  = &table[std::size_t(i) * width];
            const double factor = other[enter];
            if (i == row || factor == 0.)
              continue;
            for (unsigned int j = 0; j < width; ++j)
              other[j] -= factor * pivot_row[j];
            other[enter] = 0.;
          }
      }

      /**
       * The row that leaves when @p enter increases: the least ratio
       * rhs / column over the rows where the column is positive; on a tie
       * z_0's row, else the lexicographically least row of B^-1 / column,
       * which keeps degenerate pivoting from cycling (Murty 1988, ch. 2).
       */
      unsigned int
      ratio_test(const unsigned int enter) const
      {
        double largest = 1.;
        for (unsigned int i = 0; i < n; ++i)
          largest = std::max(largest, std::abs(entry(i, enter)));
        std::vector<unsigned int> tie;
        double                    least = 0.;
        for (unsigned int i = 0; i < n; ++i)
          {
            const double c = entry(i, enter);
            if (c <= 1e-12 * largest)
              continue;
            const double ratio = rhs(i) / c;
            if (tie.empty() ||
                ratio < least - 1e-12 * std::max(1., std::abs(least)))
              {
                tie   = {i};
                least = ratio;
              }
            else if (ratio <= least + 1e-12 * std::max(1., std::abs(least)))
              tie.push_back(i);
          }
        if (tie.empty())
          return numbers::invalid_unsigned_int;
        for (const unsigned int i : tie)
          if (basis[i] == 2 * n)
            return i;
        for (unsigned int j = 0; j < n && tie.size() > 1; ++j)
          {
            double smallest = std::numeric_limits<double>::max();
            for (const unsigned int i : tie)
              smallest = std::min(smallest, entry(i, j) / entry(i, enter));
            std::vector<unsigned int> kept;
            for (const unsigned int i : tie)
              if (entry(i, j) / entry(i, enter) <= smallest + 1e-14)
                kept.push_back(i);
            tie = kept;
          }
        return tie.front();
      }

      const unsigned int        n, width;
      std::vector<double>       table;
      std::vector<unsigned int> basis;
    };
  } // namespace



  template <int dim>
  LemkeMethod<dim>::LemkeMethod(const ContactProblem<dim> &contact_problem,
                                const unsigned int         variable_limit,
                                const unsigned int         pivots_per_variable)
    : problem(contact_problem)
    , n_directions(dim == 2 ? 2 : 8)
    , max_variables(variable_limit)
    , max_pivots_per_variable(pivots_per_variable)
    , broken(contact_problem.n_pairs, false)
  {
    Assert(problem.q.size() == problem.n_pairs * dim, ExcInternalError());
    // (Without floating modes G is empty: a FullMatrix with no columns
    // has no rows either.)
    Assert(problem.n_alpha == 0 || (problem.G.m() == problem.n_pairs * dim &&
                                    problem.G.n() == problem.n_alpha),
           ExcInternalError());
    Assert(problem.f.size() == problem.n_alpha, ExcInternalError());
    number_variables();
  }



  template <int dim>
  void
  LemkeMethod<dim>::number_variables()
  {
    variables.assign(problem.n_pairs, PairVariables());
    unsigned int next = 0;
    for (unsigned int k = 0; k < problem.n_pairs; ++k)
      {
        const auto &pair = problem.pairs[k];
        auto       &v    = variables[k];
        if (pair.tied)
          {
            v.tied = next;
            next += 2 * dim;
            continue;
          }
        if (!pair.held[0])
          v.normal = next++;
        // Friction only where no tangential direction is held (in 3D a
        // pair with one tangent held is left without; the fast iteration
        // checks it).
        if (std::none_of(pair.held.begin() + 1,
                         pair.held.end(),
                         [](const bool h) { return h; }))
          {
            v.shear = next;
            next += n_directions;
            v.lambda = next++;
            // The cone's r_N is max(r_N, 0): its own variable where the
            // pair can carry tension.
            if (v.normal != numbers::invalid_unsigned_int &&
                pair.joint.tensile_limit(pair.area, pair.broken) > 0.)
              v.compression = next++;
          }
      }
    alpha_plus  = next;
    n_variables = next + 2 * problem.n_alpha;
    variable_is_force.assign(n_variables, false);
    row_is_force.assign(n_variables, false);
    for (const auto &v : variables)
      {
        const auto set = [&](const unsigned int first,
                             const unsigned int count,
                             const bool         force_row) {
          if (first == numbers::invalid_unsigned_int)
            return;
          for (unsigned int i = first; i < first + count; ++i)
            {
              variable_is_force[i] = true;
              row_is_force[i]      = force_row;
            }
        };
        set(v.normal, 1, false);
        set(v.shear, n_directions, false);
        set(v.tied, 2 * dim, false);
        set(v.compression, 1, true);
        if (v.lambda != numbers::invalid_unsigned_int)
          row_is_force[v.lambda] = true; // the cone's room
      }
    for (unsigned int i = alpha_plus; i < n_variables; ++i)
      row_is_force[i] = true; // the floating blocks' equilibrium
  }



  template <int dim>
  unsigned int
  LemkeMethod<dim>::size() const
  {
    return n_variables;
  }



  template <int dim>
  Tensor<1, dim>
  LemkeMethod<dim>::direction(const unsigned int j) const
  {
    Tensor<1, dim> d;
    if (dim == 2)
      d[1] = (j == 0 ? 1. : -1.);
    else
      {
        const double angle = 2. * numbers::PI * j / n_directions;
        d[1]               = std::cos(angle);
        d[dim - 1]         = std::sin(angle);
      }
    return d;
  }



  template <int dim>
  void
  LemkeMethod<dim>::force_map(
    std::vector<std::vector<std::pair<unsigned int, double>>> &R,
    Vector<double>                                            &r0) const
  {
    R.assign(problem.n_pairs * dim, {});
    r0.reinit(problem.n_pairs * dim);
    for (unsigned int k = 0; k < problem.n_pairs; ++k)
      {
        const auto &v   = variables[k];
        const auto  row = [&](const unsigned int e) -> auto &
        {
          return R[k * dim + e];
        };
        if (v.tied != numbers::invalid_unsigned_int)
          for (unsigned int e = 0; e < dim; ++e)
            if (!problem.pairs[k].held[e])
              {
                row(e).emplace_back(v.tied + 2 * e, 1.);
                row(e).emplace_back(v.tied + 2 * e + 1, -1.);
              }
        if (v.normal != numbers::invalid_unsigned_int)
          {
            row(0).emplace_back(v.normal, 1.);
            r0(k * dim) = -problem.pairs[k].joint.tensile_limit(
              problem.pairs[k].area, problem.pairs[k].broken || broken[k]);
          }
        if (v.shear != numbers::invalid_unsigned_int)
          for (unsigned int j = 0; j < n_directions; ++j)
            for (unsigned int e = 1; e < dim; ++e)
              if (direction(j)[e] != 0.)
                row(e).emplace_back(v.shear + j, direction(j)[e]);
      }
  }



  template <int dim>
  void
  LemkeMethod<dim>::assemble(FullMatrix<double> &M, Vector<double> &q) const
  {
    // u = W r + G alpha + q with r = R z + r0 and alpha = z+ - z-: the
    // displacement of every pair direction as U z + u0.
    std::vector<std::vector<std::pair<unsigned int, double>>> R;
    Vector<double>                                            r0;
    force_map(R, r0);
    const unsigned int n_r = problem.n_pairs * dim;
    FullMatrix<double> U(n_r, n_variables);
    Vector<double>     u0(n_r);
    for (unsigned int i = 0; i < n_r; ++i)
      u0(i) = problem.q[i];
    for (const auto &[index, w] : problem.W)
      {
        for (const auto &[z, c] : R[index.second])
          U(index.first, z) += w * c;
        u0(index.first) += w * r0(index.second);
      }
    for (unsigned int i = 0; i < n_r; ++i)
      for (unsigned int a = 0; a < problem.n_alpha; ++a)
        {
          U(i, alpha_plus + a) += problem.G(i, a);
          U(i, alpha_plus + problem.n_alpha + a) -= problem.G(i, a);
        }
    M.reinit(n_variables, n_variables);
    q.reinit(n_variables);
    for (unsigned int k = 0; k < problem.n_pairs; ++k)
      add_pair_rows(k, U, u0, M, q);
    add_equilibrium_rows(R, r0, M, q);
  }



  template <int dim>
  void
  LemkeMethod<dim>::add_pair_rows(const unsigned int        k,
                                  const FullMatrix<double> &U,
                                  const Vector<double>     &u0,
                                  FullMatrix<double>       &M,
                                  Vector<double>           &q) const
  {
    const auto &v    = variables[k];
    const auto &pair = problem.pairs[k];
    // Row `row` of M and q: `sign` times the displacement of direction i.
    const auto add_row =
      [&](const unsigned int row, const unsigned int i, const double sign) {
        for (unsigned int j = 0; j < n_variables; ++j)
          M(row, j) += sign * U(i, j);
        q(row) += sign * u0(i);
      };
    if (v.tied != numbers::invalid_unsigned_int)
      for (unsigned int e = 0; e < dim; ++e)
        for (unsigned int side = 0; side < 2; ++side)
          {
            // u = 0 as two inequalities; a held direction's force is zero
            // (w = z).
            const unsigned int row = v.tied + 2 * e + side;
            if (pair.held[e])
              M(row, row) = 1.;
            else
              add_row(row, k * dim + e, side == 0 ? 1. : -1.);
          }
    if (v.normal != numbers::invalid_unsigned_int)
      add_row(v.normal, k * dim, 1.);
    if (v.shear == numbers::invalid_unsigned_int)
      return;
    for (unsigned int j = 0; j < n_directions; ++j)
      {
        for (unsigned int e = 1; e < dim; ++e)
          add_row(v.shear + j, k * dim + e, direction(j)[e]);
        M(v.shear + j, v.lambda) += 1.;
      }
    // The cone's room: c A + mu max(r_N, 0) - sum beta_j. Without a tension
    // limit r_N = z_N >= 0 already; with one, max(r_N, 0) is the variable
    // p >= 0 against p - z_N + sigma_t A >= 0 (so p = max(z_N - sigma_t A,
    // 0)).
    const bool               gone = pair.broken || broken[k];
    const double             t    = pair.joint.tensile_limit(pair.area, gone);
    const JointLaw::SlipLine line = pair.joint.slip_line(pair.area, gone);
    if (v.compression != numbers::invalid_unsigned_int)
      {
        M(v.compression, v.compression) = 1.;
        M(v.compression, v.normal)      = -1.;
        q(v.compression)                = t;
        M(v.lambda, v.compression) += line.slope;
      }
    else if (v.normal != numbers::invalid_unsigned_int)
      M(v.lambda, v.normal) += line.slope;
    for (unsigned int j = 0; j < n_directions; ++j)
      M(v.lambda, v.shear + j) -= 1.;
    q(v.lambda) = line.intercept;
  }



  template <int dim>
  void
  LemkeMethod<dim>::add_equilibrium_rows(
    const std::vector<std::vector<std::pair<unsigned int, double>>> &R,
    const Vector<double>                                            &r0,
    FullMatrix<double>                                              &M,
    Vector<double>                                                  &q) const
  {
    // G^T r + f = 0 as two inequalities, against alpha+ and alpha-.
    for (unsigned int a = 0; a < problem.n_alpha; ++a)
      {
        double f = problem.f[a];
        for (unsigned int i = 0; i < problem.n_pairs * dim; ++i)
          {
            f += problem.G(i, a) * r0(i);
            for (const auto &[z, c] : R[i])
              {
                M(alpha_plus + a, z) -= problem.G(i, a) * c;
                M(alpha_plus + problem.n_alpha + a, z) += problem.G(i, a) * c;
              }
          }
        q(alpha_plus + a)                   = -f;
        q(alpha_plus + problem.n_alpha + a) = f;
      }
  }



  template <int dim>
  bool
  LemkeMethod<dim>::solve(unsigned int &pivots)
  {
    if (n_variables > max_variables)
      {
        why = "was not tried: its problem has " + std::to_string(n_variables) +
              " variables, more than 'Contact/Lemke/Maximum variables' (" +
              std::to_string(max_variables) + ")";
        return false;
      }
    // Solved again each time a joint opens that has strength to lose. The
    // broken set only grows within the increment (as the fast iteration
    // breaks joints): a joint that one pass opens stays broken even if the
    // next closes it. The pivot limit is for all passes together.
    const unsigned int max_pivots =
      pivots + max_pivots_per_variable * n_variables;
    for (unsigned int pass = 0; pass <= problem.n_pairs; ++pass)
      {
        FullMatrix<double> M;
        Vector<double>     q, z;
        assemble(M, q);
        if (!solve_lcp(M, q, z, max_pivots, pivots))
          return false;
        set_answer(z);
        const std::vector<unsigned int> opened = newly_open();
        if (opened.empty())
          return true;
        for (const unsigned int k : opened)
          broken[k] = true;
      }
    why = "broke every joint and did not settle";
    return false;
  }



  template <int dim>
  bool
  LemkeMethod<dim>::solve_lcp(FullMatrix<double> &M,
                              Vector<double>     &q,
                              Vector<double>     &z,
                              const unsigned int  max_pivots,
                              unsigned int       &pivots)
  {
    // A positive diagonal scaling of rows and columns keeps the solutions:
    // forces in units of displacement (times the mean flexibility s), the
    // rows in units of force (the cones' room, the floating blocks'
    // equilibrium, the positive parts of r_N) times s, then everything over
    // the largest datum, so that the tableau's entries are of unit order
    // whatever the model's units.
    double s = 0.;
    for (unsigned int i = 0; i < problem.n_pairs * dim; ++i)
      {
        const auto w = problem.W.find({i, i});
        s += (w == problem.W.end() ? 0. : w->second);
      }
    s = (s > 0. ? s / (problem.n_pairs * dim) : 1.);
    for (unsigned int i = 0; i < n_variables; ++i)
      {
        const double row = (row_is_force[i] ? s : 1.);
        for (unsigned int j = 0; j < n_variables; ++j)
          M(i, j) *= row / (variable_is_force[j] ? s : 1.);
        q(i) *= row;
      }
    const double datum = q.linfty_norm();
    z.reinit(n_variables);
    if (datum == 0. || *std::min_element(q.begin(), q.end()) >= 0.)
      return true;
    q /= datum;
    LemkeTableau   tableau(M, q);
    const LemkeEnd end = tableau.run(max_pivots, pivots);
    if (end != LemkeEnd::solution)
      {
        why = (end == LemkeEnd::ray ? "ended on a secondary ray" :
                                      "reached its pivot limit") +
              std::string(" after ") + std::to_string(pivots) + " pivots" +
              (end == LemkeEnd::ray ?
                 describe_ray(tableau.ray_variable, tableau.basic_variables()) :
                 "");
        return false;
      }
    z = tableau.z();
    for (unsigned int j = 0; j < n_variables; ++j)
      z(j) *= datum / (variable_is_force[j] ? s : 1.);
    return true;
  }



  template <int dim>
  std::string
  LemkeMethod<dim>::describe_ray(const unsigned int               variable,
                                 const std::vector<unsigned int> &basic) const
  {
    // A ray of a free variable split in two (alpha+ and alpha-, or a tied
    // pair's force) whose twin is basic moves nothing but the split: an
    // artefact of the formulation in rounding, not of the problem.
    if (variable < n_variables || variable >= 2 * n_variables)
      return "";
    const unsigned int i    = variable - n_variables;
    unsigned int       twin = numbers::invalid_unsigned_int;
    if (i >= alpha_plus)
      twin = (i < alpha_plus + problem.n_alpha ? i + problem.n_alpha :
                                                 i - problem.n_alpha);
    for (const auto &pv : variables)
      if (pv.tied != numbers::invalid_unsigned_int && i >= pv.tied &&
          i < pv.tied + 2 * dim)
        twin = ((i - pv.tied) % 2 == 0 ? i + 1 : i - 1);
    if (twin == numbers::invalid_unsigned_int ||
        std::find(basic.begin(), basic.end(), n_variables + twin) ==
          basic.end())
      return "";
    return " (of a free variable split in two, its twin basic: an artefact "
           "of the formulation in rounding)";
  }



  template <int dim>
  void
  LemkeMethod<dim>::set_answer(const Vector<double> &z)
  {
    std::vector<std::vector<std::pair<unsigned int, double>>> R;
    const unsigned int n_r = problem.n_pairs * dim;
    force_map(R, r);
    for (unsigned int i = 0; i < n_r; ++i)
      for (const auto &[j, c] : R[i])
        r(i) += c * z(j);
    alpha.reinit(problem.n_alpha);
    for (unsigned int a = 0; a < problem.n_alpha; ++a)
      alpha(a) = z(alpha_plus + a) - z(alpha_plus + problem.n_alpha + a);
    u.reinit(n_r);
    for (unsigned int i = 0; i < n_r; ++i)
      {
        u(i) = problem.q[i];
        for (unsigned int a = 0; a < problem.n_alpha; ++a)
          u(i) += problem.G(i, a) * alpha(a);
      }
    for (const auto &[index, w] : problem.W)
      u(index.first) += w * r(index.second);
  }



  template <int dim>
  std::pair<double, double>
  LemkeMethod<dim>::scales() const
  {
    double displacement = 0.;
    for (const double q : problem.q)
      displacement = std::max(displacement, std::abs(q));
    return {r.linfty_norm(), std::max(displacement, u.linfty_norm())};
  }



  template <int dim>
  std::vector<unsigned int>
  LemkeMethod<dim>::newly_open() const
  {
    const double              gap = state_tolerance * scales().second;
    std::vector<unsigned int> opened;
    for (unsigned int k = 0; k < problem.n_pairs; ++k)
      {
        const auto &pair = problem.pairs[k];
        if (!(pair.broken || broken[k]) && pair.joint.has_strength() &&
            variables[k].normal != numbers::invalid_unsigned_int &&
            u(k * dim) > gap)
          opened.push_back(k);
      }
    return opened;
  }



  template <int dim>
  std::string
  LemkeMethod<dim>::failure() const
  {
    return why;
  }



  template <int dim>
  StateTrial<dim>
  LemkeMethod<dim>::answer_states(const StateTrial<dim> &committed) const
  {
    const auto [force_scale, displacement_scale] = scales();
    const double force_tolerance        = state_tolerance * force_scale;
    const double displacement_tolerance = state_tolerance * displacement_scale;
    StateTrial<dim> trial               = committed;
    for (unsigned int k = 0; k < problem.n_pairs; ++k)
      {
        const auto &pair = problem.pairs[k];
        const auto &v    = variables[k];
        if (v.tied != numbers::invalid_unsigned_int ||
            (v.normal == numbers::invalid_unsigned_int &&
             v.shear == numbers::invalid_unsigned_int))
          continue;
        trial.tensile_slip[k]        = false;
        trial.direction_stiffness[k] = 0.;
        trial.broken[k]              = trial.broken[k] || broken[k];
        if (v.normal != numbers::invalid_unsigned_int &&
            u(k * dim) > displacement_tolerance)
          {
            trial.state[k] = ContactState::open;
            continue;
          }
        Tensor<1, dim> slip;
        for (unsigned int e = 1; e < dim; ++e)
          slip[e] = u(k * dim + e);
        // A pair whose normal is held is read as closed (stick or slip),
        // where the Newton method reads it open: the fast iteration that
        // checks the answer decides either way.
        if (v.shear == numbers::invalid_unsigned_int ||
            slip.norm() <= displacement_tolerance)
          {
            trial.state[k] = ContactState::stick;
            continue;
          }
        const double r_n = r(k * dim);
        const double strength =
          pair.joint.shear_strength(r_n,
                                    pair.area,
                                    pair.broken || trial.broken[k]);
        trial.state[k]               = ContactState::slip;
        trial.slip_direction[k]      = slip / slip.norm();
        trial.tensile_slip[k]        = r_n < -force_tolerance;
        trial.direction_stiffness[k] = (dim == 3 ? strength / slip.norm() : 0.);
      }
    return trial;
  }



  template class LemkeMethod<2>;
  template class LemkeMethod<3>;
} // namespace mbfem

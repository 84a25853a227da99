#include <mbfem/contact/static_admissibility.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <ClpSimplex.hpp>
#include <CoinPackedMatrix.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>

namespace mbfem
{
  namespace
  {
    /**
     * Bounds of the strength-factor search: beyond them the answer is "at
     * least 1000" or "none even with 1000 times the strength", which is
     * all a user needs to read.
     */
    constexpr double largest_factor  = 1e3;
    constexpr double smallest_factor = 1e-3;
    /** Relative width at which the bisection on the factor stops. */
    constexpr double factor_tolerance = 1e-7;

    /** An LP in triplet form, as Clp loads it. */
    struct LinearProgram
    {
      std::vector<int>    rows, columns;
      std::vector<double> values;
      std::vector<double> column_lower, column_upper, objective;
      std::vector<double> row_lower, row_upper;

      unsigned int
      add_column(const double lower, const double upper, const double cost)
      {
        column_lower.push_back(lower);
        column_upper.push_back(upper);
        objective.push_back(cost);
        return column_lower.size() - 1;
      }

      unsigned int
      add_row(const double lower, const double upper)
      {
        row_lower.push_back(lower);
        row_upper.push_back(upper);
        return row_lower.size() - 1;
      }

      void
      add(const unsigned int row, const unsigned int column, const double a)
      {
        if (a == 0.)
          return;
        rows.push_back(row);
        columns.push_back(column);
        values.push_back(a);
      }
    };


    /**
     * The equilibrium rows of infeasibility()'s LP (row a = mode a) with
     * their phase-1 slacks; returns the scaled load's 1-norm.
     */
    double
    add_equilibrium_rows(LinearProgram             &lp,
                         const std::vector<double> &external_resultant,
                         const double               force_scale)
    {
      const double inf       = COIN_DBL_MAX;
      double       load_norm = 0.;
      for (unsigned int a = 0; a < external_resultant.size(); ++a)
        {
          const double b = -external_resultant[a] / force_scale;
          lp.add_row(b, b);
          load_norm += std::abs(b);
          // Slacks s+ and s-: the phase-1 objective.
          lp.add(a, lp.add_column(0., inf, 1.), 1.);
          lp.add(a, lp.add_column(0., inf, 1.), -1.);
        }
      return load_norm;
    }

    /**
     * The rows of the polygonal cone @p facets (JointLaw::polygonal_cone())
     * of a pair whose normal force is column @p first_column, its tangents
     * the next dim - 1.
     */
    template <int dim>
    void
    add_cone_facets(LinearProgram                          &lp,
                    const unsigned int                      first_column,
                    const std::vector<JointLaw::ConeFacet> &facets)
    {
      for (const JointLaw::ConeFacet &facet : facets)
        {
          const unsigned int row = lp.add_row(-COIN_DBL_MAX, facet.bound);
          lp.add(row, first_column, facet.normal);
          for (unsigned int d = 1; d < dim; ++d)
            lp.add(row, first_column + d, facet.tangent[d - 1]);
        }
    }

    /**
     * The force columns (normal, then tangents) of a pair with coupling
     * rows @p first_row ... + dim - 1, bounded as the pair allows: held
     * directions carry nothing, the normal of an untied pair at most the
     * tension @p tension, the rest anything. Returns the normal's column.
     */
    template <int dim>
    unsigned int
    add_force_columns(LinearProgram               &lp,
                      const CouplingRows          &coupling,
                      const unsigned int           first_row,
                      const bool                   tied,
                      const std::array<bool, dim> &held,
                      const double                 tension)
    {
      const double inf   = COIN_DBL_MAX;
      unsigned int first = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const bool         free  = tied && !held[d];
          const double       lower = held[d]           ? 0. :
                                     (d == 0 && !free) ? -tension :
                                                         -inf;
          const unsigned int c = lp.add_column(lower, held[d] ? 0. : inf, 0.);
          if (d == 0)
            first = c;
          for (const auto &[a, value] : coupling.row(first_row + d))
            lp.add(a, c, value);
        }
      return first;
    }

    /**
     * A pair with coupling rows @p first_row ... + dim - 1 that slides
     * along a mechanism with the unit slip @p slip (tangential
     * components): normal force N >= -@p tension, shear tau >= 0 against
     * the slip, at most the strength of @p law's facet against it (c A +
     * mu (N + sigma_t A), circumscribed), and in 3D a shear tau_perp across
     * the slip within |tau_perp| <= @p fan tau.
     */
    template <int dim>
    void
    add_sliding_pair(LinearProgram        &lp,
                     const CouplingRows   &coupling,
                     const unsigned int    first_row,
                     const JointLaw       &law,
                     const double          area,
                     const bool            broken,
                     const double          tension,
                     const Tensor<1, dim> &slip,
                     const double          fan)
    {
      const double       inf    = COIN_DBL_MAX;
      const unsigned int normal = lp.add_column(-tension, inf, 0.);
      const unsigned int shear  = lp.add_column(0., inf, 0.);
      // The rows of one pair have the same amplitudes (its blocks' modes).
      for (const auto &[a, value] : coupling.row(first_row))
        {
          lp.add(a, normal, value);
          double along = 0.;
          for (unsigned int d = 1; d < dim; ++d)
            along -= coupling(first_row + d, a) * slip[d];
          lp.add(a, shear, along);
        }
      // The facet against the slip: tau <= c A + mu (N + sigma_t A).
      const JointLaw::ConeFacet facet =
        law.cone_facet({{1., 0.}}, area, broken, true);
      const unsigned int strength = lp.add_row(-inf, facet.bound);
      lp.add(strength, shear, facet.tangent[0]);
      lp.add(strength, normal, facet.normal);
      if (dim == 3)
        {
          Tensor<1, dim> across;
          across[1]               = -slip[2];
          across[2]               = slip[1];
          const unsigned int turn = lp.add_column(-inf, inf, 0.);
          for (const auto &entry : coupling.row(first_row))
            {
              const unsigned int a     = entry.first;
              double             value = 0.;
              for (unsigned int d = 1; d < dim; ++d)
                value += coupling(first_row + d, a) * across[d];
              lp.add(a, turn, value);
            }
          for (const double sign : {1., -1.})
            {
              const unsigned int row = lp.add_row(-inf, 0.);
              lp.add(row, turn, sign);
              lp.add(row, shear, -fan);
            }
        }
    }

    /**
     * Clp's primal and dual tolerances. Its defaults (1e-7, on the problem
     * as its own scaling leaves it) let a solution it calls optimal break
     * this LP's rows by 1e-4 of the load: a 3D model of 107 pairs, whose
     * 64-sided cones make the LP highly degenerate, was "admissible" 1.2 %
     * above its strength factor (issue 65's 2 x 2 model, doc/
     * state_iteration.md). The rows are scaled by construction (the load's
     * largest entry 1, facets of unit normal), so the solve can ask for
     * two orders below the certificate's own feasibility_tolerance (1e-8).
     */
    constexpr double clp_tolerance = 1e-10;

    /**
     * The largest violation of a row or bound a solution may have for its
     * phase-1 optimum to be trusted: below feasibility_tolerance, so that
     * no "admissible" rests on forces that break the equilibrium rows.
     */
    constexpr double largest_violation = 1e-9;

    /** How far @p x breaks the rows and bounds of @p lp (absolute). */
    double
    violation(const LinearProgram &lp, const double *x)
    {
      std::vector<double> ax(lp.row_lower.size(), 0.);
      for (unsigned int i = 0; i < lp.values.size(); ++i)
        ax[lp.rows[i]] += lp.values[i] * x[lp.columns[i]];
      double worst = 0.;
      for (unsigned int r = 0; r < ax.size(); ++r)
        worst =
          std::max({worst, ax[r] - lp.row_upper[r], lp.row_lower[r] - ax[r]});
      for (unsigned int c = 0; c < lp.column_lower.size(); ++c)
        worst = std::max(
          {worst, x[c] - lp.column_upper[c], lp.column_lower[c] - x[c]});
      return worst;
    }

    /**
     * Loads @p lp into @p model and solves it with Clp's dual simplex,
     * again without Clp's scaling if the answer breaks the rows; throws
     * unless the answer is optimal and keeps to largest_violation.
     */
    void
    solve_phase_one(const LinearProgram &lp, ClpSimplex &model)
    {
      const CoinPackedMatrix matrix(true,
                                    lp.rows.data(),
                                    lp.columns.data(),
                                    lp.values.data(),
                                    lp.values.size());
      double                 broken = 0.;
      for (const int scaling : {3, 0})
        {
          model.setLogLevel(0);
          model.loadProblem(matrix,
                            lp.column_lower.data(),
                            lp.column_upper.data(),
                            lp.objective.data(),
                            lp.row_lower.data(),
                            lp.row_upper.data());
          model.scaling(scaling);
          model.setPrimalTolerance(clp_tolerance);
          model.setDualTolerance(clp_tolerance);
          model.dual();
          broken = violation(lp, model.primalColumnSolution());
          if (model.isProvenOptimal() && broken <= largest_violation)
            return;
        }
      // The slacks make every phase-1 LP feasible and bounded below by 0:
      // anything but an optimum that keeps to the rows is the solver's
      // failure, not the model's.
      AssertThrow(false,
                  ExcMessage("The statics certificate's linear program (Clp) "
                             "ended with status " +
                             std::to_string(model.status()) +
                             " and a solution that breaks its rows by " +
                             std::to_string(broken) + "."));
    }

    /**
     * The duals y of the equilibrium rows: -y is a virtual velocity of
     * the modes whose power, loads minus joints, is the optimum; scaled
     * to a largest entry of 1 and oriented so that the loads do work.
     */
    void
    mechanism_from_duals(const double              *dual,
                         const std::vector<double> &external_resultant,
                         std::vector<double>       &mechanism)
    {
      const unsigned int n_modes = external_resultant.size();
      mechanism.assign(n_modes, 0.);
      double largest = 0., work = 0.;
      for (unsigned int a = 0; a < n_modes; ++a)
        {
          mechanism[a] = -dual[a];
          largest      = std::max(largest, std::abs(dual[a]));
          work += external_resultant[a] * mechanism[a];
        }
      for (double &v : mechanism)
        v *= (work < 0. ? -1. : 1.) / (largest > 0. ? largest : 1.);
    }
  } // namespace



  template <int dim>
  StaticAdmissibility<dim>::StaticAdmissibility(
    std::vector<Candidate>     candidates_,
    const CouplingRows        &coupling_,
    const std::vector<double> &external_resultant_,
    const unsigned int         n_facets_)
    : candidates(std::move(candidates_))
    , coupling(coupling_)
    , external_resultant(external_resultant_)
    , n_facets(std::max(n_facets_, 4u))
  {
    AssertDimension(coupling.m(), candidates.size() * dim);
    AssertDimension(coupling.n(), external_resultant.size());
    force_scale = 0.;
    for (const double f : external_resultant)
      force_scale = std::max(force_scale, std::abs(f));
    if (!(force_scale > 0.))
      force_scale = 1.;
    for (unsigned int k = 0; k < candidates.size(); ++k)
      {
        bool touches = false;
        for (unsigned int i = 0; i < dim; ++i)
          for (const auto &[a, value] : coupling.row(k * dim + i))
            touches = touches || value != 0.;
        if (touches)
          active.push_back(k);
      }
  }



  template <int dim>
  std::pair<JointLaw, double>
  StaticAdmissibility<dim>::law_of(const Candidate &pair,
                                   const double     factor) const
  {
    // Strength reduction is JointLaw's: tan(phi), c and sigma_t over F.
    return {pair.joint.reduced(factor), pair.area / force_scale};
  }



  template <int dim>
  double
  StaticAdmissibility<dim>::infeasibility(const double         factor,
                                          const bool           circumscribed,
                                          std::vector<double> *mechanism,
                                          std::vector<double> *forces) const
  {
    LinearProgram lp;

    // Equilibrium rows first (row a = mode a), then the cones.
    const double load_norm =
      add_equilibrium_rows(lp, external_resultant, force_scale);

    // A polygon of n_facets sides around the circle of radius s: its
    // facets t . e_j <= kappa s touch the circle (kappa = 1) or pass
    // through its vertices on it (kappa = cos(pi / n)).
    const double kappa =
      (dim == 2 || circumscribed) ? 1. : std::cos(numbers::PI / n_facets);
    std::vector<unsigned int> first_column(active.size());
    for (unsigned int i = 0; i < active.size(); ++i)
      {
        const Candidate &pair  = candidates[active[i]];
        const auto [law, area] = law_of(pair, factor);
        first_column[i] =
          add_force_columns<dim>(lp,
                                 coupling,
                                 active[i] * dim,
                                 pair.tied,
                                 pair.held,
                                 law.tensile_limit(area, pair.broken));
        if (pair.tied)
          continue;
        // |r_t| <= c A + mu r_n (+ mu sigma_t A, circumscribed).
        add_cone_facets<dim>(lp,
                             first_column[i],
                             law.polygonal_cone(dim == 2 ? 2 : n_facets,
                                                area,
                                                pair.broken,
                                                circumscribed,
                                                kappa));
      }

    ClpSimplex model;
    solve_phase_one(lp, model);
    const double optimum =
      std::max(0., model.objectiveValue()) / std::max(load_norm, 1e-300);

    if (mechanism)
      mechanism_from_duals(model.dualRowSolution(),
                           external_resultant,
                           *mechanism);
    if (forces)
      {
        const double *x = model.primalColumnSolution();
        forces->assign(candidates.size() * dim, 0.);
        for (unsigned int i = 0; i < active.size(); ++i)
          for (unsigned int d = 0; d < dim; ++d)
            (*forces)[active[i] * dim + d] =
              x[first_column[i] + d] * force_scale;
      }
    return optimum;
  }



  template <int dim>
  double
  StaticAdmissibility<dim>::search_factor(
    const std::function<bool(double)> &admissible,
    bool                              &bounded)
  {
    // Bracket [lo, hi] with lo admissible and hi not, then bisect.
    double lo = 1., hi = 1.;
    bounded = false;
    if (admissible(1.))
      {
        for (hi = 2.; admissible(hi); hi *= 2.)
          {
            lo = hi;
            if (hi >= largest_factor)
              {
                bounded = true;
                return hi;
              }
          }
      }
    else
      {
        for (lo = 0.5; !admissible(lo); lo /= 2.)
          {
            hi = lo;
            if (lo <= smallest_factor)
              {
                bounded = true;
                return 0.;
              }
          }
      }
    while (hi - lo > factor_tolerance * hi)
      {
        const double middle            = 0.5 * (lo + hi);
        (admissible(middle) ? lo : hi) = middle;
      }
    return lo;
  }



  template <int dim>
  std::vector<double>
  StaticAdmissibility<dim>::sliding_mechanism(
    const std::vector<double> &associated,
    const double               factor,
    unsigned int              &freedom) const
  {
    freedom                           = 0;
    const unsigned int        n_modes = coupling.n();
    const std::vector<double> w       = pair_velocities(associated);
    double                    largest = 0.;
    for (const double x : w)
      largest = std::max(largest, std::abs(x));
    // Rows that must vanish: every direction of a pair at rest, the
    // normal of a pair that slides (its velocity on the dual cone,
    // w_n = mu |w_t|). Pairs that open (w_n > mu |w_t|) stay free.
    LAPACKFullMatrix<double> normal(n_modes, n_modes);
    const double             tolerance = 1e-6 * largest;
    for (const unsigned int k : active)
      {
        double tangential = 0.;
        for (unsigned int d = 1; d < dim; ++d)
          tangential += w[k * dim + d] * w[k * dim + d];
        tangential = std::sqrt(tangential);
        // The friction of the LP the duals came from.
        const auto [law, area] = law_of(candidates[k], factor);
        const double mu   = law.slip_line(area, candidates[k].broken).slope;
        const bool   rest = std::abs(w[k * dim]) + tangential <= tolerance;
        // (In 3D the polygon's dual cone reaches up to 1 / cos(pi / n)
        // beyond the circle's, between two facets.)
        const double polygon =
          (dim == 2 ? 1. : 1. / std::cos(numbers::PI / n_facets));
        const bool slide =
          w[k * dim] <= mu * tangential * polygon * (1. + 1e-6) + tolerance;
        for (unsigned int d = 0; d < dim; ++d)
          if (rest || (slide && d == 0))
            for (const auto &[a, x] : coupling.row(k * dim + d))
              for (const auto &[b, y] : coupling.row(k * dim + d))
                normal(a, b) += x * y;
      }
    // v minus its part in the row space of those rows.
    double scale = 0.;
    for (unsigned int a = 0; a < n_modes; ++a)
      scale = std::max(scale, normal(a, a));
    if (scale == 0.)
      return associated;
    Vector<double>     eigenvalues;
    FullMatrix<double> eigenvectors;
    normal.compute_eigenvalues_symmetric(1e-10 * scale,
                                         2. * n_modes * scale,
                                         1e-14 * scale,
                                         eigenvalues,
                                         eigenvectors);
    std::vector<double> sliding = associated;
    freedom                     = n_modes - eigenvalues.size();
    for (unsigned int i = 0; i < eigenvalues.size(); ++i)
      {
        double projection = 0.;
        for (unsigned int a = 0; a < n_modes; ++a)
          projection += eigenvectors(a, i) * associated[a];
        for (unsigned int a = 0; a < n_modes; ++a)
          sliding[a] -= projection * eigenvectors(a, i);
      }
    double size = 0., work = 0.;
    for (unsigned int a = 0; a < n_modes; ++a)
      {
        size = std::max(size, std::abs(sliding[a]));
        work += external_resultant[a] * sliding[a];
      }
    // Nothing left (a mechanism that only opens joints), or one the loads
    // do no work along: the associated one is the better description.
    if (size <= 1e-6 || work <= 0.)
      {
        freedom = 0;
        return associated;
      }
    for (double &v : sliding)
      v /= size;
    return sliding;
  }



  template <int dim>
  std::vector<double>
  StaticAdmissibility<dim>::pair_velocities(
    const std::vector<double> &mechanism) const
  {
    std::vector<double> w(candidates.size() * dim, 0.);
    for (const unsigned int k : active)
      for (unsigned int d = 0; d < dim; ++d)
        for (const auto &[a, value] : coupling.row(k * dim + d))
          w[k * dim + d] += value * mechanism[a];
    return w;
  }



  template <int dim>
  double
  StaticAdmissibility<dim>::mechanism_infeasibility(
    const double               factor,
    const std::vector<double> &mechanism,
    const unsigned int         freedom) const
  {
    const std::vector<double> w       = pair_velocities(mechanism);
    double                    largest = 0.;
    for (const double x : w)
      largest = std::max(largest, std::abs(x));
    const double tolerance = 1e-6 * largest;
    // 3D: unless the kinematics alone fix the mechanism's direction
    // (@p freedom = 1: a wedge on two planes), it comes from an LP over
    // polygonal cones and may lie up to half a facet's angle off the true
    // one (a block on a plane slides normal to the nearest facet), so the
    // shear may turn by that much from it: the set then still contains the
    // forces of the true motion.
    const double fan =
      (dim == 2 || freedom == 1) ? 0. : std::tan(numbers::PI / n_facets);

    LinearProgram lp;
    const double  load_norm =
      add_equilibrium_rows(lp, external_resultant, force_scale);
    for (const unsigned int k : active)
      {
        const Candidate &pair  = candidates[k];
        const auto [law, area] = law_of(pair, factor);
        const double tension   = law.tensile_limit(area, pair.broken);
        double       slip      = 0.;
        for (unsigned int d = 1; d < dim; ++d)
          slip += w[k * dim + d] * w[k * dim + d];
        slip                  = std::sqrt(slip);
        const double wn       = w[k * dim];
        bool         held_any = false;
        for (unsigned int d = 0; d < dim; ++d)
          held_any = held_any || pair.held[d];

        // A pair that opens along the mechanism carries nothing.
        if (!pair.tied && wn > tolerance)
          continue;
        const bool slides =
          !pair.tied && !held_any && slip > tolerance && wn >= -tolerance;
        if (!slides)
          {
            // At rest (or closing, or tied): anything its cone allows, as
            // in the statics LP with circumscribed cones.
            const unsigned int first = add_force_columns<dim>(
              lp, coupling, k * dim, pair.tied, pair.held, tension);
            if (!pair.tied)
              add_cone_facets<dim>(lp,
                                   first,
                                   law.polygonal_cone(dim == 2 ? 2 : n_facets,
                                                      area,
                                                      pair.broken,
                                                      true,
                                                      1.));
            continue;
          }
        Tensor<1, dim> s;
        for (unsigned int d = 1; d < dim; ++d)
          s[d] = w[k * dim + d] / slip;
        add_sliding_pair<dim>(
          lp, coupling, k * dim, law, area, pair.broken, tension, s, fan);
      }
    ClpSimplex model;
    solve_phase_one(lp, model);
    return std::max(0., model.objectiveValue()) / std::max(load_norm, 1e-300);
  }



  template <int dim>
  void
  StaticAdmissibility<dim>::add_mechanism_factor(Result &result) const
  {
    if (result.verdict == Verdict::none)
      result.limit_mechanism = result.mechanism;
    else if (!result.strength_factor_bounded)
      {
        // The mechanism just beyond the statics limit.
        std::vector<double> associated;
        ++result.n_solves;
        const double factor = result.strength_factor * 1.0001;
        if (infeasibility(factor, true, &associated) > feasibility_tolerance)
          result.limit_mechanism =
            sliding_mechanism(associated,
                              factor,
                              result.limit_mechanism_freedom);
      }
    if (result.limit_mechanism.empty())
      return;
    // The projection leaves the pairs that open free: if it drives one
    // into its neighbour, the motion is not one the blocks can make, and
    // limit equilibrium along it proves nothing.
    const std::vector<double> w       = pair_velocities(result.limit_mechanism);
    double                    largest = 0.;
    for (const double x : w)
      largest = std::max(largest, std::abs(x));
    for (const unsigned int k : active)
      if (!candidates[k].tied && !candidates[k].held[0] &&
          w[k * dim] < -1e-6 * largest)
        {
          result.limit_mechanism.clear();
          return;
        }
    result.mechanism_factor = search_factor(
      [&](const double factor) {
        ++result.n_solves;
        return mechanism_infeasibility(factor,
                                       result.limit_mechanism,
                                       result.limit_mechanism_freedom) <=
               feasibility_tolerance;
      },
      result.mechanism_factor_bounded);
  }



  template <int dim>
  typename StaticAdmissibility<dim>::Result
  StaticAdmissibility<dim>::solve(const bool with_mechanism_factor) const
  {
    const auto start = std::chrono::steady_clock::now();
    Result     result;
    result.n_candidates = active.size();
    if (coupling.n() == 0)
      {
        result.strength_factor         = largest_factor;
        result.strength_factor_bounded = true;
        return result;
      }

    std::vector<double> mechanism;
    result.infeasibility = infeasibility(1., true, &mechanism);
    result.n_solves      = 1;
    if (result.infeasibility > feasibility_tolerance)
      {
        result.verdict              = Verdict::none;
        result.associated_mechanism = mechanism;
        result.mechanism =
          sliding_mechanism(mechanism, 1., result.limit_mechanism_freedom);
      }
    else
      {
        ++result.n_solves;
        const double inner = infeasibility(1., false, nullptr, &result.forces);
        result.verdict = (inner <= feasibility_tolerance ? Verdict::admissible :
                                                           Verdict::undecided);
      }
    result.strength_factor = search_factor(
      [&](const double factor) {
        ++result.n_solves;
        return infeasibility(factor, true) <= feasibility_tolerance;
      },
      result.strength_factor_bounded);
    if (with_mechanism_factor)
      add_mechanism_factor(result);
    result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    return result;
  }



  template class StaticAdmissibility<2>;
  template class StaticAdmissibility<3>;
} // namespace mbfem

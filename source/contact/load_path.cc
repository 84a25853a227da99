#include <mbfem/contact/load_path.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

// The load path: the terminating method of the contact state iteration
// (doc/state_iteration.md, doc/decisions.md). Within one increment the load
// goes from the last converged state (s = 0) to the increment's load
// (s = 1). With the states fixed the interface system is linear, so its
// solution is affine in s; the path follows it to the first s where a pair's
// condition of the joint law fails, switches that pair there, and goes on:
// a parametric principal pivoting method on the incremental frictional
// problem (Klarbring's 2D LCP, Murty's parametric LCP), with the states as
// the pivots. A switch happens where the quantity that decides it is zero,
// so the path is continuous except where a pair breaks; it ends at s = 1
// with the solution, or at a state that leaves a rigid motion free (a
// mechanism) with the fraction of the increment it reached.

namespace mbfem
{
  namespace internal
  {
    /** What made a pair switch on the path. */
    enum class Condition : unsigned char
    {
      none,
      tension,      // closed: r_N reached -sigma_t A
      friction,     // stick: |r_T| reached c A + mu r_N
      reversal,     // slip: the slip increment reached zero
      tensile_flag, // slip with tensile strength: r_N changed sign
      closure       // open: the gap reached zero
    };

    /** Samples of a segment searched for the first sign change. */
    constexpr unsigned int n_samples = 32;
    /**
     * A condition fails where its margin (force over the largest force,
     * displacement over the largest displacement) is below this: check()'s
     * tolerance.
     */
    constexpr double tolerance = state_tolerance;

    /**
     * At most 20 switches per pair on one path (plus 100 for few pairs):
     * each switch changes one pair's state where its condition is reached,
     * and a path that needs more has met a cycle that the other caps did
     * not catch ('Contact/Maximum iterations' quotes this).
     */
    constexpr unsigned int switches_per_pair = 20, extra_switches = 100;
    /**
     * At most 2 switches per pair (plus 50) at one load: the 3D stacked
     * beams of p = 2 with one refined (369 mortar pairs) made 7480
     * switches at s below 1e-15 (250 s) before a cap ended them.
     */
    constexpr unsigned int switches_per_pair_at_one_load = 2,
                           extra_switches_at_one_load    = 50;
    /**
     * An event more than this beyond the last one (in s, the fraction of
     * the increment) is at a new load: the states seen at the old one are
     * forgotten, and the check for a state met twice at one load starts
     * afresh.
     */
    constexpr double new_load = 1e-9;
    /**
     * Where the segment's start x_0 or d_0 is over this many times what
     * the segment holds (a load that cancels the start's), interpolating
     * s_a loses the digits: s_a is solved for itself.
     */
    constexpr double interpolation_headroom = 100.;
    /**
     * Newton steps on the 3D slip directions at a segment's start. The
     * directions settle in a few; after this many the path goes on with
     * the last ones (the state check at the end decides).
     */
    constexpr unsigned int max_direction_steps = 25;
    /**
     * A slip increment below this times the segment's displacement scale
     * has no direction to read (the pair keeps its own).
     */
    constexpr double no_slip = 1e-6;
    /** Bisection steps on a crossing in [0, 1]: 2^-60 is below rounding. */
    constexpr unsigned int bisection_steps = 60;
    /**
     * Where a condition is clearly failed after its crossing (to read the
     * direction of a new slip there): 1 % of the rest of the segment, at
     * least 1e-3 of it.
     */
    constexpr double failed_beyond = 0.01, failed_beyond_at_least = 1e-3;
    /**
     * A motion component below this times the largest is none: a pair
     * that closes after moving less while open sticks; the mechanism
     * reverses a pair's slip only beyond it; the first pair to close
     * slips only if it moves more.
     */
    constexpr double negligible_motion = 1e-6;
    /** The loads do work on a mechanism's motion beyond this (relative). */
    constexpr double no_work = 1e-8;
    /**
     * An open pair closes along a mechanism only head-on enough that the
     * blocks move at most 100 times its gap (1 / 1e-2): a grazing closure
     * would be a large rigid motion, beyond the method's small
     * displacements.
     */
    constexpr double head_on = 1e-2;
  } // namespace internal


  using namespace internal;



  template <int dim>
  struct LoadPath<dim>::Segment
  {
    double         s_a = 0.;
    Vector<double> x_a, d_a, x_1, d_1;
    double         force_scale = 1e-300, displacement_scale = 1e-300;

    /** rho and d of pair @p k at t in [0, 1] (s = s_a + t (1 - s_a)). */
    void
    at(const unsigned int k,
       const double       t,
       Tensor<1, dim>    &rho,
       Tensor<1, dim>    &d) const
    {
      for (unsigned int i = 0; i < dim; ++i)
        {
          const unsigned int j = k * dim + i;
          rho[i]               = x_a(j) + t * (x_1(j) - x_a(j));
          d[i]                 = d_a(j) + t * (d_1(j) - d_a(j));
        }
    }

    /** d_N of pair @p k at t, as at() gives it. */
    double
    normal_displacement(const unsigned int k, const double t) const
    {
      const unsigned int j = k * dim;
      return d_a(j) + t * (d_1(j) - d_a(j));
    }
  };



  template <int dim>
  struct LoadPath<dim>::Event
  {
    unsigned int pair      = numbers::invalid_unsigned_int;
    Condition    condition = Condition::none;
    double       t         = 2.; // where the margin reaches zero
    double       t_failed  = 2.; // a point where it is below -tolerance
  };



  template <int dim>
  LoadPath<dim>::LoadPath(
    const std::vector<ContactPair<dim>>      &pairs,
    const std::vector<std::array<bool, dim>> &held,
    const RigidCoupling<dim>                 &coupling,
    const StateCheck<dim>                    &checks,
    const MechanismTest<dim>                 &mechanisms,
    const Trial                              &committed,
    const std::vector<Tensor<1, dim>>        &committed_displacement,
    const IncrementLoads                     &start_loads,
    const IncrementLoads                     &full_loads,
    IncrementLoads                           &loads,
    const typename FastIteration<dim>::Solve &solve)
    : pairs(pairs)
    , held(held)
    , coupling(coupling)
    , checks(checks)
    , mechanisms(mechanisms)
    , committed(committed)
    , committed_displacement(committed_displacement)
    , start_loads(start_loads)
    , full_loads(full_loads)
    , loads(loads)
    , solve(solve)
  {}



  template <int dim>
  typename LoadPath<dim>::Outcome
  LoadPath<dim>::run(const std::string &head)
  {
    Trial trial = committed;
    std::fill(trial.direction_stiffness.begin(),
              trial.direction_stiffness.end(),
              0.);
    double                s        = 0.;
    unsigned int          switches = 0;
    std::set<std::string> seen_here; // states met at this s
    const unsigned int    max_switches =
      switches_per_pair * pairs.size() + extra_switches;
    const unsigned int max_switches_at_one_load =
      switches_per_pair_at_one_load * pairs.size() + extra_switches_at_one_load;
    Segment segment;
    // Every pair's normal gap at the present s (for close_along()).
    std::vector<double> gap(pairs.size());
    for (unsigned int k = 0; k < pairs.size(); ++k)
      gap[k] = pairs[k].initial_gap + committed_displacement[k][0];
    for (;;)
      {
        if (!solve_segment(trial, s, segment) ||
            (dim == 3 && !correct_directions(trial, segment)))
          {
            loads.set_fraction(start_loads, full_loads, 1.);
            const unsigned int n = mend_mechanism(trial, gap);
            switches += n;
            if (n > 0 && seen_here.insert(checks.signature(trial)).second &&
                switches <= max_switches)
              continue;
            return singular_end(trial, head, s, switches);
          }
        const Event event = first_event(trial, segment);
        if (event.pair == numbers::invalid_unsigned_int)
          break;
        const double s_event = s + event.t * (1. - s);
        if (s_event > s + new_load)
          seen_here.clear();
        s = s_event;
        for (unsigned int k = 0; k < pairs.size(); ++k)
          gap[k] =
            pairs[k].initial_gap + segment.normal_displacement(k, event.t);
        switch_state(trial, segment, event);
        ++switches;
        // At one load the path may also wander without repeating a state:
        // the 3D stacked beams of p = 2 with one refined (369 mortar pairs)
        // made 7480 switches at s below 1e-15 (250 s) before the cap below
        // ended them, and Newton's method then concluded in 23 steps.
        if (!seen_here.insert(checks.signature(trial)).second ||
            seen_here.size() > max_switches_at_one_load ||
            switches > max_switches)
          return cycle_end(trial, head, event.pair, s, switches);
      }
    Outcome end;
    end.reached_end = true;
    end.iterations  = switches;
    end.states      = trial;
    end.s           = 1.;
    return end;
  }



  template <int dim>
  std::string
  LoadPath<dim>::how_far(const double s, const unsigned int switches)
  {
    std::ostringstream text;
    text << " (the load path held up to s = " << std::setprecision(6) << s
         << " of this increment, after " << switches << " state switches)";
    return text.str();
  }



  template <int dim>
  bool
  LoadPath<dim>::solve_segment(Trial &trial, const double s_a, Segment &segment)
  {
    // With the states fixed the solution is affine in s: solved at s = 0
    // and s = 1, whose right-hand sides change only in the rows of pairs
    // that switched (on the sparse path UpdatedLU then needs no
    // substitution for A_0^{-1} b), and interpolated at s_a.
    segment.s_a = s_a;
    Vector<double> x_0, d_0;
    loads.set_fraction(start_loads, full_loads, 0.);
    if (!solve(trial, x_0, d_0))
      return false;
    loads.set_fraction(start_loads, full_loads, 1.);
    if (!solve(trial, segment.x_1, segment.d_1))
      return false;
    segment.x_a = x_0;
    segment.d_a = d_0;
    if (s_a > 0.) // at s_a = 0, no 0 * x_1 (NaN where x_1 overflowed)
      {
        segment.x_a.sadd(1. - s_a, s_a, segment.x_1);
        segment.d_a.sadd(1. - s_a, s_a, segment.d_1);
        // The interpolation's rounding is relative to x_0 and d_0: where
        // they are over a hundred times what the segment holds (a load
        // that cancels the start's), s_a is solved for itself.
        const auto larger = [](const Vector<double> &a,
                               const Vector<double> &b,
                               const Vector<double> &c) {
          return a.linfty_norm() > interpolation_headroom *
                                     std::max(b.linfty_norm(), c.linfty_norm());
        };
        if (larger(x_0, segment.x_a, segment.x_1) ||
            larger(d_0, segment.d_a, segment.d_1))
          {
            loads.set_fraction(start_loads, full_loads, s_a);
            const bool solved = solve(trial, segment.x_a, segment.d_a);
            loads.set_fraction(start_loads, full_loads, 1.);
            if (!solved)
              return false;
          }
      }

    const unsigned int n_r = pairs.size() * dim;
    segment.force_scale = segment.displacement_scale = 1e-300;
    for (unsigned int i = 0; i < n_r; ++i)
      {
        segment.force_scale        = std::max({segment.force_scale,
                                               std::abs(segment.x_a(i)),
                                               std::abs(segment.x_1(i))});
        segment.displacement_scale = std::max({segment.displacement_scale,
                                               std::abs(segment.d_a(i)),
                                               std::abs(segment.d_1(i))});
      }
    for (const double f : full_loads.resultant)
      segment.force_scale = std::max(segment.force_scale, std::abs(f));
    for (const auto &pair : pairs)
      segment.displacement_scale =
        std::max(segment.displacement_scale, pair.initial_gap);
    return true;
  }



  template <int dim>
  bool
  LoadPath<dim>::correct_directions(Trial &trial, Segment &segment)
  {
    // 3D: the slip direction is an unknown of the slip state. Newton on it
    // at the segment's start, as the fast iteration does (pair_equations):
    // the direction of the slip increment, and the weight of its
    // linearisation (c A + mu r_N) / |slip increment|.
    for (unsigned int iteration = 0; iteration < max_direction_steps;
         ++iteration)
      {
        double change = 0.;
        for (unsigned int k = 0; k < pairs.size(); ++k)
          {
            if (trial.state[k] != ContactState::slip)
              continue;
            Tensor<1, dim> rho, d, v;
            segment.at(k, 0., rho, d);
            for (unsigned int e = 1; e < dim; ++e)
              v[e] = d[e] - committed_displacement[k][e];
            if (v.norm() < no_slip * segment.displacement_scale)
              continue;
            const Tensor<1, dim> s = v / v.norm();
            change = std::max(change, (s - trial.slip_direction[k]).norm());
            trial.slip_direction[k] = s;
            trial.direction_stiffness[k] =
              pairs[k].joint.shear_strength(rho[0],
                                            pairs[k].area,
                                            trial.broken[k],
                                            trial.tensile_slip[k]) /
              v.norm();
          }
        if (change < direction_tolerance)
          return true;
        if (!solve_segment(trial, segment.s_a, segment))
          return false;
      }
    return true;
  }



  template <int dim>
  struct LoadPath<dim>::Margin
  {
    double    value     = std::numeric_limits<double>::max();
    Condition condition = Condition::none;
  };



  template <int dim>
  typename LoadPath<dim>::Margin
  LoadPath<dim>::state_margin(const Trial       &trial,
                              const Segment     &segment,
                              const unsigned int k,
                              const double       t) const
  {
    const double   F = segment.force_scale, D = segment.displacement_scale;
    const auto    &pair = pairs[k];
    Tensor<1, dim> rho, d;
    segment.at(k, t, rho, d);
    Margin     worst;
    const auto consider = [&](const double value, const Condition c) {
      if (value < worst.value)
        worst = {value, c};
    };
    const double tension = pair.joint.tensile_limit(pair.area, trial.broken[k]);
    const double tension_margin =
      pair.joint.tension_margin(rho[0], pair.area, trial.broken[k]);
    Tensor<1, dim> r_t, increment;
    for (unsigned int e = 1; e < dim; ++e)
      {
        r_t[e]       = rho[e];
        increment[e] = d[e] - committed_displacement[k][e];
      }
    switch (trial.state[k])
      {
        case ContactState::stick:
          consider(tension_margin / F, Condition::tension);
          consider(pair.joint.friction_margin(
                     rho[0], r_t.norm(), pair.area, trial.broken[k]) /
                     F,
                   Condition::friction);
          break;
        case ContactState::slip:
          consider(tension_margin / F, Condition::tension);
          consider(increment * trial.slip_direction[k] / D,
                   Condition::reversal);
          if (tension > 0.)
            consider((trial.tensile_slip[k] ? -rho[0] : rho[0]) / F,
                     Condition::tensile_flag);
          break;
        case ContactState::open:
          consider((pair.initial_gap + d[0]) / D, Condition::closure);
          break;
      }
    return worst;
  }



  template <int dim>
  bool
  LoadPath<dim>::may_fail(const Trial       &trial,
                          const Segment     &segment,
                          const unsigned int k) const
  {
    // Every margin of state_margin() is affine in t, or (friction) c A +
    // mu max(r_N, 0) - |r_T| with r_N and r_T affine: concave wherever r_N
    // keeps its sign. Their minimum is then concave between 0, the point
    // where r_N changes sign and 1, and so at least the smaller of its
    // values there: where none of them fails, no sample can.
    const auto fails_at = [&](const double t) {
      return state_margin(trial, segment, k, t).value < -tolerance;
    };
    if (fails_at(0.) || fails_at(1.))
      return true;
    const double r_0 = segment.x_a(k * dim), r_1 = segment.x_1(k * dim);
    return (r_0 < 0.) != (r_1 < 0.) && fails_at(r_0 / (r_0 - r_1));
  }



  template <int dim>
  typename LoadPath<dim>::Event
  LoadPath<dim>::first_event(const Trial &trial, const Segment &segment) const
  {
    const auto margin = [&](const unsigned int k, const double t) {
      return state_margin(trial, segment, k, t);
    };

    Event first;
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        if (pairs[k].tied || checks.all_held(k))
          continue;
        if (!may_fail(trial, segment, k))
          continue;
        // The first sample where the margin fails, then bisection to where
        // it crosses zero.
        double       low = 0., high = -1.;
        const Margin m_0       = margin(k, 0.);
        Condition    condition = m_0.condition;
        if (m_0.value < -tolerance)
          high = 0.;
        for (unsigned int j = 1; j <= n_samples && high < 0.; ++j)
          {
            const double t = double(j) / n_samples;
            const Margin m = margin(k, t);
            if (m.value < -tolerance)
              {
                high      = t;
                condition = m.condition;
              }
            else
              low = t;
          }
        if (high < 0. || high > first.t)
          continue;
        double crossing = high;
        if (high > 0.)
          {
            for (unsigned int b = 0; b < bisection_steps; ++b)
              {
                const double middle = 0.5 * (low + high);
                if (margin(k, middle).value < 0.)
                  high = middle;
                else
                  low = middle;
              }
            crossing = high;
          }
        if (crossing < first.t)
          {
            first.pair      = k;
            first.condition = condition;
            first.t         = crossing;
            // Where the condition is clearly failed: the direction of a
            // new slip, or the slip of a pair that closes, is read there.
            first.t_failed =
              std::min(1.,
                       crossing + std::max(failed_beyond_at_least,
                                           failed_beyond * (1. - crossing)));
          }
      }
    return first;
  }



  template <int dim>
  void
  LoadPath<dim>::switch_state(Trial         &trial,
                              const Segment &segment,
                              const Event   &event) const
  {
    const unsigned int k    = event.pair;
    const auto        &pair = pairs[k];
    Tensor<1, dim>     rho, d, rho_failed, d_failed;
    segment.at(k, event.t, rho, d);
    segment.at(k, event.t_failed, rho_failed, d_failed);
    Tensor<1, dim> increment;
    for (unsigned int e = 1; e < dim; ++e)
      increment[e] = d[e] - committed_displacement[k][e];
    const double D = segment.displacement_scale;

    switch (event.condition)
      {
        case Condition::tension:
          // Breaking is history: a pair that reaches its tensile strength
          // loses it and its cohesion for good, here and in later
          // increments; its force drops to zero (the one jump of the path).
          if (!trial.broken[k] && pair.joint.has_strength())
            trial.broken[k] = true;
          trial.state[k]        = ContactState::open;
          trial.tensile_slip[k] = false;
          break;
        case Condition::friction:
          {
            // Slips against its force, read where it exceeds the strength.
            Tensor<1, dim> r_t;
            for (unsigned int e = 1; e < dim; ++e)
              r_t[e] = rho_failed[e];
            trial.state[k] = ContactState::slip;
            if (r_t.norm() > 0.)
              trial.slip_direction[k] = -r_t / r_t.norm();
            trial.direction_stiffness[k] = 0.;
            trial.tensile_slip[k] =
              rho[0] < 0. &&
              pair.joint.tensile_limit(pair.area, trial.broken[k]) > 0.;
            break;
          }
        case Condition::reversal:
          trial.state[k] = ContactState::stick;
          break;
        case Condition::tensile_flag:
          trial.tensile_slip[k] = !trial.tensile_slip[k];
          break;
        case Condition::closure:
          // A pair that closes after moving tangentially while open cannot
          // stick (that would undo the motion): it slips on, in the
          // direction it was moving. One that closes where it opened
          // sticks.
          if (increment.norm() > negligible_motion * D)
            {
              trial.state[k]               = ContactState::slip;
              trial.slip_direction[k]      = increment / increment.norm();
              trial.direction_stiffness[k] = 0.;
            }
          else
            trial.state[k] = ContactState::stick;
          trial.tensile_slip[k] = false;
          break;
        case Condition::none:
          Assert(false, ExcInternalError());
      }
  }



  template <int dim>
  unsigned int
  LoadPath<dim>::mend_mechanism(Trial &trial, std::vector<double> &gap) const
  {
    // A mechanism whose motion would reverse the slip of some pairs is not
    // the limit: those pairs stick, and the path goes on from the same s.
    // Nor is one along which a gap closes: the blocks move until it does.
    const Vector<double> free_motion = mechanisms.motion(trial);
    if (free_motion.size() == 0)
      return 0;
    const unsigned int n = unload_against(trial, free_motion);
    if (n == 0 && close_along(trial, free_motion, gap))
      return 1;
    return n;
  }



  template <int dim>
  unsigned int
  LoadPath<dim>::unload_against(Trial                &trial,
                                const Vector<double> &motion) const
  {
    // The tangential relative motion of each slipping pair under the
    // mechanism's motion, against its slip direction.
    std::vector<double> along(pairs.size(), 0.);
    double              largest = 0.;
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        if (trial.state[k] != ContactState::slip)
          continue;
        Tensor<1, dim> w;
        for (unsigned int e = 1; e < dim; ++e)
          if (!held[k][e])
            for (const auto &[a, value] : coupling.row(k * dim + e))
              w[e] += value * motion(a);
        along[k] = w * trial.slip_direction[k];
        largest  = std::max(largest, w.norm());
      }
    unsigned int n_switched = 0;
    for (unsigned int k = 0; k < pairs.size(); ++k)
      if (along[k] < -negligible_motion * largest)
        {
          trial.state[k] = ContactState::stick;
          ++n_switched;
        }
    return n_switched;
  }



  template <int dim>
  bool
  LoadPath<dim>::close_along(Trial                &trial,
                             const Vector<double> &motion,
                             std::vector<double>  &gap) const
  {
    // Only a motion the loads drive: without work, MechanismTest::motion()
    // names a free motion of either sign.
    double work = 0., load = 0.;
    for (unsigned int a = 0; a < coupling.n_modes(); ++a)
      {
        work += loads.resultant[a] * motion(a);
        load += loads.resultant[a] * loads.resultant[a];
      }
    if (!(work > no_work * std::sqrt(load) * motion.l2_norm()))
      return false;
    // The relative motion of each open pair along the mechanism, and the
    // amplitude at which it closes its gap.
    unsigned int                first     = numbers::invalid_unsigned_int;
    double                      amplitude = std::numeric_limits<double>::max();
    Tensor<1, dim>              first_motion;
    double                      largest = 0.;
    std::vector<Tensor<1, dim>> w(pairs.size());
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        for (unsigned int e = 0; e < dim; ++e)
          if (!held[k][e])
            for (const auto &[a, value] : coupling.row(k * dim + e))
              w[k][e] += value * motion(a);
        largest = std::max(largest, w[k].norm());
      }
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        // Only pairs the motion closes head-on enough that the blocks move
        // at most 100 times the gap: a grazing closure would be a large
        // rigid motion, beyond the small displacements of the method.
        if (trial.state[k] != ContactState::open || pairs[k].tied ||
            held[k][0] || !(w[k][0] < -head_on * largest))
          continue;
        const double closes = std::max(gap[k], 0.) / -w[k][0];
        if (closes < amplitude)
          {
            amplitude    = closes;
            first        = k;
            first_motion = w[k];
          }
      }
    if (first == numbers::invalid_unsigned_int)
      return false;
    // The gaps once the blocks have moved so far.
    for (unsigned int k = 0; k < pairs.size(); ++k)
      gap[k] += amplitude * w[k][0];
    Tensor<1, dim> slip;
    for (unsigned int e = 1; e < dim; ++e)
      slip[e] = first_motion[e];
    if (slip.norm() > negligible_motion * largest && amplitude > 0.)
      {
        trial.state[first]               = ContactState::slip;
        trial.slip_direction[first]      = slip / slip.norm();
        trial.direction_stiffness[first] = 0.;
      }
    else
      trial.state[first] = ContactState::stick;
    trial.tensile_slip[first] = false;
    return true;
  }



  template <int dim>
  typename LoadPath<dim>::Outcome
  LoadPath<dim>::cycle_end(const Trial       &trial,
                           const std::string &head,
                           const unsigned int pair,
                           const double       s,
                           const unsigned int switches) const
  {
    Outcome cycle;
    cycle.iterations = switches;
    cycle.states     = trial;
    cycle.s          = s;
    cycle.failure    = head +
                    ": the load path cannot continue: the states of "
                    "pair " +
                    std::to_string(pair) +
                    " and its neighbours cycle at one load" +
                    how_far(s, switches) + ".";
    return cycle;
  }



  template <int dim>
  typename LoadPath<dim>::Outcome
  LoadPath<dim>::singular_end(const Trial       &trial,
                              const std::string &head,
                              const double       s,
                              const unsigned int switches) const
  {
    Outcome           end;
    const std::string motion = mechanisms.describe(trial);
    end.iterations           = switches;
    end.states               = trial;
    end.s                    = s;
    end.no_equilibrium       = !motion.empty();
    if (end.no_equilibrium)
      end.failure =
        head + ": no equilibrium" + how_far(s, switches) + "." + motion;
    else
      end.failure = head + ": the interface system is singular" +
                    how_far(s, switches) +
                    ", and no rigid motion is free: check for pairs "
                    "whose nodes are both fixed in some direction.";
    return end;
  }



  template class LoadPath<2>;
  template class LoadPath<3>;
} // namespace mbfem

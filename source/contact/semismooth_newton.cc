#include <mbfem/contact/newton_jacobian.h>
#include <mbfem/contact/semismooth_newton.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>

// The semismooth Newton method of the contact state iteration
// (doc/state_iteration.md, doc/decisions.md): by default the third method,
// tried where the fast iteration and the load path both fail. The increment is
// written as one nonsmooth system in (rho, alpha), the joint law by Alart and
// Curnier's projections:
//
//   normal:     r_N - max(0, r_N - eps g) = 0      (g the gap),
//   tangential: r_T - proj_{|r| <= R}(r_T - eps v) = 0,
//               R = c A + mu max(0, r_N - eps g),  v the slip increment,
//   floating blocks: P^T r + F_e = 0,
//
// solved by Newton's method on its generalised Jacobian with a
// backtracking line search, its Jacobian sparse (NewtonJacobian). In 3D the
// slip direction is part of the projection, so it may turn freely within the
// increment (which the load path, holding it over a segment, cannot follow).
// Its answer gives the states, which ContactSolver's fast iteration then solves
// and checks, so that the result is the same discrete problem, with the same
// tolerances, as the other methods'.

namespace mbfem
{
  namespace internal
  {
    /** Armijo's sufficient decrease of the line search. */
    constexpr double armijo = 1e-4;
    /** Step halvings of the line search before it gives up on the step. */
    constexpr unsigned int max_halvings = 30;
    /**
     * A Newton step cut to less than this fraction of its length by the
     * trust length (so longer than 1e6 times the data or the iterate)
     * comes from a Jacobian singular but for rounding: the line search
     * takes it down to min_step only, and its failure counts as a
     * singular Jacobian (solve_system() then hands over to the springs
     * where they follow, else to Levenberg and Marquardt's step).
     */
    constexpr double singular_cut = 1e-3;
    /**
     * The shortest such step the line search takes, as a fraction of
     * Newton's full step. The jointed slope's increment 3 took 30 of them
     * in a row that left the merit the same to six digits (t times the
     * cut down to 1e-18). Other steps halve down to max_halvings as
     * before: on the 1013-block wall, sending those to Levenberg and
     * Marquardt's step instead cost 64 s of augmented LUs (34,016
     * unknowns) in one step.
     */
    constexpr double min_step = 1e-6;
    /** A Newton step is cut to this times the larger of |u| and the data. */
    constexpr double trust_factor = 1e3;
    /** Levenberg-Marquardt's smallest damping (relative to diag J^T J). */
    constexpr double initial_damping = 1e-10;
    /**
     * Levenberg-Marquardt's largest damping. Beyond it a step is below
     * 1e-4 of a gradient step scaled by diag J^T J; where no damping up to
     * it decreases the merit, the iterate is at a point that larger ones
     * do not leave either (the 1013-block wall: the merit unchanged to six
     * digits from 1e16 to 1e19, after 30 augmented LUs of 4.3 s each), and
     * the springs of solve_proximal() take over sooner.
     */
    constexpr double max_damping = 1e4;
  } // namespace internal

  namespace
  {
    /** @p x to three significant digits, for messages. */
    std::string
    short_number(const double x)
    {
      std::ostringstream text;
      text << std::setprecision(3) << x;
      return text.str();
    }
  } // namespace



  template <int dim>
  SemismoothNewton<dim>::SemismoothNewton(
    const StateMethodParameters              &parameters,
    const std::vector<ContactPair<dim>>      &pairs,
    const CondensedSystem<dim>               &system,
    const RigidCoupling<dim>                 &coupling,
    const std::vector<std::array<bool, dim>> &held,
    const IncrementLoads                     &loads,
    const StateTrial<dim>                    &committed,
    const std::vector<Tensor<1, dim>>        &committed_displacement)
    : max_iterations(parameters.newton_max_iterations)
    , tolerance(parameters.newton_tolerance)
    , proximal_stiffness(parameters.proximal_stiffness)
    , proximal_steps(parameters.proximal_steps)
    , pairs(pairs)
    , condensed(system)
    , coupling(coupling)
    , held(held)
    , loads(loads)
    , committed(committed)
    , committed_displacement(committed_displacement)
    , n_pairs(pairs.size())
  {}



  template <int dim>
  struct SemismoothNewton<dim>::System
  {
    /** d = Delta_F + A u, u = (rho * scale, alpha): A's rows are those of
     * [C_hat / scale, P_hat]; and the Jacobian. */
    NewtonJacobian linear;
    /** P_hat's column of each floating mode, as (row, value). */
    std::vector<NewtonJacobian::Row> coupling_column;
    /** Pairs broken before or during this increment (history). */
    std::vector<bool> broken;
    Vector<double>    u, d, residual;
    /** Whether evaluate() assembles the Jacobian too. */
    bool assemble = false;
    /** Why solve_system() stopped short, for failure(). */
    std::string failure;
    /**
     * The proximal iteration's springs on the floating modes (stiffness
     * relative to the contacts', 0: none) and their anchors.
     */
    double         spring = 0.;
    Vector<double> anchor;
    /** Whether the Jacobian's pattern holds the springs' entries. */
    bool pattern_has_springs = false;

    void
    add_unit(const unsigned int row, const unsigned int column, const double c)
    {
      if (assemble)
        linear.add(row, column, c);
    }

    /** The Jacobian's row += c times the derivative of d(source). */
    void
    add_displacement(const unsigned int row,
                     const unsigned int source,
                     const double       c)
    {
      if (assemble)
        linear.add_row_of_a(row, source, c);
    }
  };



  template <int dim>
  bool
  SemismoothNewton<dim>::is_bilateral(const unsigned int       k,
                                      const std::vector<bool> &broken) const
  {
    // A joint with strength that is closed at the increment's start stays
    // closed until it breaks (the outer loop of solve() breaks
    // it): its force may be tensile. One open at the start (across a gap)
    // is unilateral.
    return !broken[k] && pairs[k].joint.has_strength() &&
           committed.state[k] != ContactState::open;
  }



  template <int dim>
  double
  SemismoothNewton<dim>::radius(const unsigned int k,
                                const double       xi,
                                const System      &system) const
  {
    // Cohesion only for a joint held closed; the polishing fast iteration
    // checks the real strength.
    const auto &pair = pairs[k];
    return pair.joint.disc_radius(xi,
                                  pair.area,
                                  is_bilateral(k, system.broken),
                                  condensed.scale());
  }



  template <int dim>
  void
  SemismoothNewton<dim>::pair_residual(const unsigned int k,
                                       System            &system) const
  {
    const auto           &pair = pairs[k];
    const unsigned int    r0   = k * dim;
    const Vector<double> &u = system.u, &d = system.d;
    Vector<double>       &F = system.residual;
    for (unsigned int e = 0; e < dim; ++e)
      if (held[k][e])
        {
          F(r0 + e) = u(r0 + e);
          system.add_unit(r0 + e, r0 + e, 1.);
        }
    const double gap = pair.initial_gap + d(r0);
    if (pair.tied)
      {
        for (unsigned int e = 0; e < dim; ++e)
          if (!held[k][e])
            {
              F(r0 + e) =
                (e == 0 ? gap : d(r0 + e) - committed_displacement[k][e]);
              system.add_displacement(r0 + e, r0 + e, 1.);
            }
        return;
      }

    // Normal: closed (g = 0) or open (r_N = 0); xi the augmented normal
    // force that sets the friction disc's radius.
    const bool bilateral  = is_bilateral(k, system.broken);
    double     xi         = 0.;
    bool       xi_has_gap = false;
    if (!held[k][0])
      {
        const double w = u(r0) - gap;
        if (bilateral || w > 0.)
          {
            F(r0) = gap;
            system.add_displacement(r0, r0, 1.);
            xi         = bilateral ? u(r0) : w;
            xi_has_gap = !bilateral;
          }
        else
          {
            F(r0) = u(r0);
            system.add_unit(r0, r0, 1.);
          }
      }
    tangential_residual(k, xi, xi_has_gap, system);
  }



  template <int dim>
  void
  SemismoothNewton<dim>::tangential_residual(const unsigned int k,
                                             const double       xi,
                                             const bool         xi_has_gap,
                                             System            &system) const
  {
    const auto           &pair = pairs[k];
    const unsigned int    r0   = k * dim;
    const double          R    = radius(k, xi, system);
    const double          dR   = pair.joint.disc_slope(xi);
    const Vector<double> &u = system.u, &d = system.d;
    Vector<double>       &F = system.residual;

    // z = r_T - eps v over the tangential directions not held.
    Tensor<1, dim> z, v;
    for (unsigned int e = 1; e < dim; ++e)
      if (!held[k][e])
        {
          v[e] = d(r0 + e) - committed_displacement[k][e];
          z[e] = u(r0 + e) - v[e];
        }
    const double z_norm = z.norm();
    for (unsigned int e = 1; e < dim; ++e)
      {
        if (held[k][e])
          continue;
        const unsigned int row = r0 + e;
        if (JointLaw::in_disc(z_norm, R))
          {
            // Stuck: no slip increment.
            F(row) = v[e];
            system.add_displacement(row, row, 1.);
          }
        else if (z_norm > 0.)
          {
            // Slipping: r_T = R z / |z|.
            const Tensor<1, dim> n = z / z_norm;
            F(row)                 = u(row) - R * n[e];
            system.add_unit(row, row, 1.);
            for (unsigned int l = 1; l < dim; ++l)
              if (!held[k][l])
                {
                  const double m =
                    ((e == l ? 1. : 0.) - n[e] * n[l]) * R / z_norm;
                  system.add_unit(row, r0 + l, -m);
                  system.add_displacement(row, r0 + l, m);
                }
            if (xi > 0.)
              {
                system.add_unit(row, r0, -n[e] * dR);
                if (xi_has_gap)
                  system.add_displacement(row, r0, n[e] * dR);
              }
          }
        else
          {
            F(row) = u(row); // no strength and no motion: no force
            system.add_unit(row, row, 1.);
          }
      }
  }



  template <int dim>
  double
  SemismoothNewton<dim>::evaluate(System &system) const
  {
    const unsigned int n_r = n_pairs * dim;
    system.linear.multiply(system.u, system.d);
    for (unsigned int i = 0; i < n_r; ++i)
      system.d(i) += loads.displacement(i);
    system.residual.reinit(n_r + coupling.n_modes());
    if (system.assemble)
      system.linear.clear_jacobian();
    for (unsigned int k = 0; k < n_pairs; ++k)
      pair_residual(k, system);
    // The floating blocks' equilibrium, P^T r + F_e = 0, times scale.
    for (unsigned int a = 0; a < coupling.n_modes(); ++a)
      {
        double value = condensed.scale() * loads.resultant[a];
        for (const auto &[j, c] : system.coupling_column[a])
          {
            value += c * system.u(j);
            system.add_unit(n_r + a, j, c);
          }
        if (system.spring > 0.)
          {
            value -= system.spring * (system.u(n_r + a) - system.anchor(a));
            system.add_unit(n_r + a, n_r + a, -system.spring);
          }
        system.residual(n_r + a) = value;
      }
    return 0.5 * (system.residual * system.residual);
  }



  template <int dim>
  bool
  SemismoothNewton<dim>::solve_system(System       &system,
                                      unsigned int &iterations,
                                      bool         *stopped_singular) const
  {
    const unsigned int n_r = n_pairs * dim;
    // The scale of the residual and of a step: the increment's data, not
    // the iterate (a near-singular step can make the iterate huge).
    double reference = 1e-300;
    for (unsigned int i = 0; i < n_r; ++i)
      reference = std::max(reference, std::abs(loads.displacement(i)));
    for (const double f : loads.resultant)
      reference = std::max(reference, condensed.scale() * std::abs(f));
    for (const auto &pair : pairs)
      reference = std::max(reference, pair.initial_gap);

    double damping = internal::initial_damping;
    for (unsigned int it = 0; it < max_iterations; ++it)
      {
        system.assemble    = true;
        const double merit = evaluate(system);
        system.assemble    = false;
        if (system.residual.linfty_norm() <= tolerance * reference)
          return true;
        ++iterations;
        // Newton's step where it decreases 1/2 |F|^2 (with backtracking,
        // and no longer than the trust length), else Levenberg and
        // Marquardt's, which always can.
        const double trust =
          internal::trust_factor * std::max(reference, system.u.linfty_norm());
        const double residual = system.residual.linfty_norm();
        bool         singular = false;
        if (line_search(system, merit, trust, singular))
          continue;
        // The first try at a singular Jacobian, where springs follow:
        // mostly a floating block that its pairs' states leave without
        // support, which Levenberg-Marquardt's step does not mend (on the
        // wall of 1013 blocks it failed at every damping, 15
        // factorisations of the augmented system) and the springs of
        // solve_proximal() hold.
        if (singular && stopped_singular != nullptr)
          {
            *stopped_singular = true;
            system.failure =
              "its Jacobian was singular at step " + std::to_string(it + 1);
            return false;
          }
        if (!levenberg_marquardt_step(system, merit, damping))
          {
            system.failure = "no step decreased its residual (" +
                             short_number(residual / reference) +
                             " of the data) after " + std::to_string(it + 1) +
                             " iterations";
            return false;
          }
      }
    // The last step's residual, which the loop has not tested.
    evaluate(system);
    if (system.residual.linfty_norm() <= tolerance * reference)
      return true;
    system.failure =
      "it reached 'Contact/Semismooth Newton/Maximum iterations' (" +
      std::to_string(max_iterations) + ") with its residual at " +
      short_number(system.residual.linfty_norm() / reference) +
      " of the data (tolerance " + short_number(tolerance) + ")";
    return false;
  }



  template <int dim>
  bool
  SemismoothNewton<dim>::solve_proximal(System               &system,
                                        const Vector<double> &start,
                                        unsigned int         &iterations) const
  {
    const unsigned int n_r = n_pairs * dim;
    if (proximal_stiffness == 0. || coupling.n_modes() == 0)
      return false;
    const std::string stalled = system.failure;
    std::string       why     = "its blocks did not settle after " +
                      std::to_string(proximal_steps) +
                      " moves of the springs' anchors";
    // Once per solve(): later breaks reuse the pattern with the springs.
    if (!system.pattern_has_springs)
      set_matrix(system, true);
    system.u      = start;
    system.spring = proximal_stiffness;
    system.anchor.reinit(coupling.n_modes());
    bool converged = false;
    for (unsigned int step = 0; step < proximal_steps; ++step)
      {
        for (unsigned int a = 0; a < coupling.n_modes(); ++a)
          system.anchor(a) = system.u(n_r + a);
        if (!solve_system(system, iterations))
          {
            why = system.failure;
            break;
          }
        // The springs' largest force, against the largest contact force.
        double moved = 0.;
        for (unsigned int a = 0; a < coupling.n_modes(); ++a)
          moved =
            std::max(moved, std::abs(system.u(n_r + a) - system.anchor(a)));
        if (system.spring * moved <= tolerance * scales(system).first)
          {
            system.spring = 0.;
            converged     = solve_system(system, iterations);
            why           = system.failure + " (once the springs were off)";
            break;
          }
      }
    system.spring = 0.;
    if (!converged)
      system.failure = stalled + "; held by springs, " + why;
    return converged;
  }



  template <int dim>
  bool
  SemismoothNewton<dim>::line_search(System      &system,
                                     const double merit,
                                     const double trust,
                                     bool        &singular) const
  {
    // A nearly singular Jacobian can give a step of NaNs: solve() says so.
    Vector<double> step(system.residual);
    step *= -1.;
    singular = !system.linear.solve(step);
    if (singular)
      return false;
    // Armijo's test for the step taken, t times the (cut) Newton step:
    // the decrease predicted by the linearisation is 2 t cut merit.
    const double cut = std::min(1., trust / step.linfty_norm());
    step *= cut;

    const Vector<double> start         = system.u;
    double               t             = 1.;
    const bool           near_singular = cut < internal::singular_cut;
    for (unsigned int h = 0; h <= internal::max_halvings &&
                             (!near_singular || t * cut >= internal::min_step);
         ++h, t *= 0.5)
      {
        system.u = start;
        system.u.add(t, step);
        if (evaluate(system) <= (1. - 2. * internal::armijo * t * cut) * merit)
          return true;
      }
    // Back to the start, with its residual (the fallback step needs it).
    system.u = start;
    evaluate(system);
    // A step far beyond the trust length that decreases nothing: the
    // Jacobian is singular in all but rounding, which the springs mend
    // as they do an exactly singular one.
    singular = near_singular;
    return false;
  }



  template <int dim>
  bool
  SemismoothNewton<dim>::levenberg_marquardt_step(System      &system,
                                                  const double merit,
                                                  double      &damping) const
  {
    // (J^T J + lambda diag(J^T J)) step = -J^T F, lambda raised tenfold
    // until the merit decreases (up to max_damping) and lowered after a
    // success. F at the start: evaluate() overwrites system.residual with
    // that of each rejected try.
    const Vector<double> start = system.u, residual = system.residual;
    for (; damping <= internal::max_damping; damping *= 10.)
      {
        Vector<double> step;
        if (system.linear.damped_least_squares(residual, damping, step))
          {
            system.u = start;
            system.u += step;
            if (evaluate(system) < merit)
              {
                damping = std::max(damping / 10., internal::initial_damping);
                return true;
              }
          }
      }
    system.u = start;
    return false;
  }



  template <int dim>
  std::pair<double, double>
  SemismoothNewton<dim>::scales(const System &system) const
  {
    // As check_scales(), in the units of u: the largest force (of the
    // pairs and the floating blocks' loads) and displacement.
    double force = 1e-300, displacement = 1e-300;
    for (unsigned int i = 0; i < n_pairs * dim; ++i)
      {
        force        = std::max(force, std::abs(system.u(i)));
        displacement = std::max(displacement, std::abs(system.d(i)));
      }
    for (const double f : loads.resultant)
      force = std::max(force, condensed.scale() * std::abs(f));
    for (const auto &pair : pairs)
      displacement = std::max(displacement, pair.initial_gap);
    return {force, displacement};
  }



  template <int dim>
  StateTrial<dim>
  SemismoothNewton<dim>::states(const System &system) const
  {
    const double scale = condensed.scale();
    // check()'s relative tolerance: a slip increment below it is none.
    const auto [force_scale, displacement_scale] = scales(system);
    const double force_tolerance        = state_tolerance * force_scale;
    const double displacement_tolerance = state_tolerance * displacement_scale;
    StateTrial<dim> trial               = committed;
    trial.broken                        = system.broken;
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const auto        &pair = pairs[k];
        const unsigned int r0   = k * dim;
        if (pair.tied || std::all_of(held[k].begin(),
                                     held[k].end(),
                                     [](bool h) { return h; }))
          continue;
        const double gap             = pair.initial_gap + system.d(r0);
        const double w               = held[k][0] ? 0. : system.u(r0) - gap;
        const bool   bilateral       = is_bilateral(k, system.broken);
        trial.tensile_slip[k]        = false;
        trial.direction_stiffness[k] = 0.;
        if (!bilateral && w <= 0.)
          {
            trial.state[k] = ContactState::open;
            continue;
          }
        const double   xi = bilateral ? system.u(r0) : w;
        const double   R  = radius(k, xi, system);
        Tensor<1, dim> z, v, r_t;
        for (unsigned int e = 1; e < dim; ++e)
          if (!held[k][e])
            {
              v[e]   = system.d(r0 + e) - committed_displacement[k][e];
              r_t[e] = system.u(r0 + e);
              z[e]   = r_t[e] - v[e];
            }
        if (JointLaw::in_disc(z.norm(), R) ||
            v.norm() <= displacement_tolerance)
          {
            trial.state[k] = ContactState::stick;
            continue;
          }
        trial.state[k]               = ContactState::slip;
        trial.slip_direction[k]      = v / v.norm();
        trial.tensile_slip[k]        = system.u(r0) < -force_tolerance;
        trial.direction_stiffness[k] = dim == 3 ? (R / scale) / v.norm() : 0.;
      }
    return trial;
  }



  template <int dim>
  unsigned int
  SemismoothNewton<dim>::worst_tension(const System &system) const
  {
    // The joint in tension beyond its limit by the most (relative to the
    // largest force, with check()'s tolerance): it breaks first.
    unsigned int worst  = numbers::invalid_unsigned_int;
    double       excess = 0.;
    const double force  = scales(system).first;
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const auto &pair = pairs[k];
        if (pair.tied || held[k][0] || !is_bilateral(k, system.broken))
          continue;
        const double over = -pair.joint.tension_margin(system.u(k * dim),
                                                       pair.area,
                                                       false,
                                                       condensed.scale()) /
                            force;
        if (over > state_tolerance && over > excess)
          {
            excess = over;
            worst  = k;
          }
      }
    return worst;
  }



  template <int dim>
  void
  SemismoothNewton<dim>::set_matrix(System &system, const bool springs) const
  {
    // A's rows: C_hat / scale where two pairs share a block (H_b of each
    // block they share), and P_hat of the pair's blocks' modes.
    const unsigned int               n_r = n_pairs * dim;
    std::vector<NewtonJacobian::Row> rows(n_r);
    system.coupling_column.assign(coupling.n_modes(), {});
    std::vector<int> entry_of(n_r + coupling.n_modes(), -1);
    std::vector<int> every_column(n_r);
    std::iota(every_column.begin(), every_column.end(), 0);
    condensed.request_columns(
      std::vector<unsigned int>(every_column.begin(), every_column.end()));
    for (unsigned int i = 0; i < n_r; ++i)
      {
        auto &row = rows[i];
        condensed.add_row(i / dim,
                          i % dim,
                          1.,
                          every_column,
                          [&](const unsigned int column, const double value) {
                            if (entry_of[column] < 0)
                              {
                                entry_of[column] = row.size();
                                row.emplace_back(column, 0.);
                              }
                            row[entry_of[column]].second += value;
                          });
        for (const auto &[a, value] : coupling.row(i))
          if (value != 0.)
            {
              row.emplace_back(n_r + a, value);
              system.coupling_column[a].emplace_back(i, value);
            }
        for (const auto &[column, value] : row)
          entry_of[column] = -1;
      }
    system.linear.reinit(rows, n_r + coupling.n_modes(), dim, springs);
    system.pattern_has_springs = springs;
  }


  template <int dim>
  SemismoothNewton<dim>::~SemismoothNewton() = default;



  template <int dim>
  bool
  SemismoothNewton<dim>::solve_system_or_springs(System       &system,
                                                 unsigned int &iterations) const
  {
    const Vector<double> before = system.u;
    const bool springs = proximal_stiffness > 0. && coupling.n_modes() > 0;
    bool       stopped_singular = false;
    bool       solved =
      solve_system(system, iterations, springs ? &stopped_singular : nullptr);
    if (solved || solve_proximal(system, before, iterations))
      return true;
    if (!stopped_singular)
      return false;
    // The springs did not conclude either: the first try once more from
    // its start, this time with Levenberg-Marquardt's steps past a
    // singular Jacobian (which can also be a degenerate pair's rows).
    const std::string first = system.failure;
    system.u                = before;
    solved                  = solve_system(system, iterations);
    if (!solved)
      system.failure =
        first + "; then with Levenberg-Marquardt's steps, " + system.failure;
    return solved;
  }



  template <int dim>
  bool
  SemismoothNewton<dim>::solve(const Vector<double> &start,
                               unsigned int         &iterations)
  {
    const unsigned int n_r = n_pairs * dim;
    const unsigned int n   = n_r + coupling.n_modes();
    answer                 = std::make_unique<System>();
    System &system         = *answer;
    system.broken          = committed.broken;
    set_matrix(system);
    system.u.reinit(n);
    if (start.size() == n)
      for (unsigned int i = 0; i < n; ++i)
        system.u(i) = start(i) * (i < n_r ? condensed.scale() : 1.);

    // Joints break one at a time, the one furthest beyond its tensile
    // limit first, and the system is solved again from where it was.
    for (unsigned int breaks = 0; breaks <= n_pairs; ++breaks)
      {
        if (!solve_system_or_springs(system, iterations))
          return false;
        const unsigned int worst = worst_tension(system);
        if (worst == numbers::invalid_unsigned_int)
          break;
        system.broken[worst] = true;
      }
    return true;
  }



  template <int dim>
  std::string
  SemismoothNewton<dim>::failure() const
  {
    return answer ? answer->failure : std::string();
  }



  template <int dim>
  StateTrial<dim>
  SemismoothNewton<dim>::answer_states() const
  {
    Assert(answer, ExcInternalError());
    return states(*answer);
  }



  template class SemismoothNewton<2>;
  template class SemismoothNewton<3>;
} // namespace mbfem

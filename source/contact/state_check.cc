#include <mbfem/contact/state_check.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace mbfem
{
  namespace internal
  {
    /**
     * Where the flexibility is on demand, the open pairs a trial closes:
     * those penetrating at least this fraction of the deepest
     * (StateCheck::limit_closing()). On the 1377-pair stacked beams,
     * 0.5 closed 476 pairs in the first trial and computed 7752 of the
     * 8262 columns over 19 trials; 0.9 closes 102 and needs 612 columns
     * and 5 trials.
     */
    constexpr double closing_fraction = 0.9;
  } // namespace internal



  template <int dim>
  StateCheck<dim>::StateCheck(
    const std::vector<ContactPair<dim>>      &pairs,
    const std::vector<std::array<bool, dim>> &held,
    const std::vector<Tensor<1, dim>>        &committed_displacement,
    const IncrementLoads                     &loads,
    const RigidCoupling<dim>                 &coupling,
    const CondensedSystem<dim>               *condensed)
    : pairs(pairs)
    , held(held)
    , committed_displacement(committed_displacement)
    , loads(loads)
    , coupling(coupling)
    , condensed(condensed)
  {}



  template <int dim>
  typename StateCheck<dim>::Trial
  StateCheck<dim>::check(const Trial          &trial,
                         const Vector<double> &solution,
                         const Vector<double> &displacement,
                         std::vector<double>  &violation,
                         double               &direction_change) const
  {
    const Scales scales = this->scales(solution, displacement);
    Trial        next   = trial;
    violation.assign(pairs.size(), 0.);
    direction_change = 0.;
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        if (all_held(k))
          continue;
        if (pairs[k].tied)
          continue; // stays stuck
        switch (trial.state[k])
          {
            case ContactState::stick:
              check_stick(k, trial, solution, scales, next, violation[k]);
              break;
            case ContactState::slip:
              check_slip(k,
                         trial,
                         solution,
                         displacement,
                         scales,
                         next,
                         violation[k],
                         direction_change);
              break;
            case ContactState::open:
              check_open(k, displacement, scales, next, violation[k]);
              break;
          }
      }
    limit_closing(trial, violation, next);
    return next;
  }


  template <int dim>
  void
  StateCheck<dim>::limit_closing(const Trial               &trial,
                                 const std::vector<double> &violation,
                                 Trial                     &next) const
  {
    // Where the flexibility is on demand, a closing pair costs columns of
    // its blocks' flexibility: close only the pairs that penetrate nearly
    // as deep as the deepest, those that would touch first if the load
    // grew from the trial's (the load path's first event, approximately),
    // so that the pairs that these push apart never need theirs.
    // Only between immobile blocks: where a block can move rigidly, a
    // trial that closes some of its pairs and opens others may need all
    // its closings to hold it.
    if (condensed == nullptr)
      return;
    const auto closing = [&](const unsigned int k) {
      return trial.state[k] == ContactState::open &&
             next.state[k] != ContactState::open && condensed->on_demand(k) &&
             immobile(k);
    };
    double deepest = 0.;
    for (unsigned int k = 0; k < pairs.size(); ++k)
      if (closing(k))
        deepest = std::max(deepest, violation[k]);
    for (unsigned int k = 0; k < pairs.size(); ++k)
      if (closing(k) && violation[k] < internal::closing_fraction * deepest)
        next.state[k] = ContactState::open;
  }


  template <int dim>
  bool
  StateCheck<dim>::all_held(const unsigned int k) const
  {
    return std::all_of(held[k].begin(), held[k].end(), [](const bool h) {
      return h;
    });
  }



  template <int dim>
  bool
  StateCheck<dim>::immobile(const unsigned int k) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      for (const auto &[a, value] : coupling.row(k * dim + d))
        if (value != 0.)
          return false;
    return true;
  }


  template <int dim>
  typename StateCheck<dim>::Trial
  StateCheck<dim>::open_on_demand(
    const Trial          &trial,
    const Vector<double> &committed_solution) const
  {
    // A pair that starts stuck (no gap) without force yet, between blocks
    // that cannot move rigidly, and whose blocks' flexibility is on
    // demand starts the iteration open: the closing rule closes it if the
    // load presses it, and only then are its columns computed. (With a
    // floating block, all pairs open may leave it unheld: not there.)
    if (condensed == nullptr)
      return trial;
    Trial start = trial;
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        // A joint with cohesion or tensile strength stays stuck: opened,
        // it would lose its strength without breaking.
        if (trial.state[k] != ContactState::stick || trial.broken[k] ||
            pairs[k].tied || pairs[k].initial_gap != 0. ||
            pairs[k].joint.has_strength() || !immobile(k) ||
            !condensed->on_demand(k) || all_held(k))
          continue;
        bool fresh = true;
        for (unsigned int d = 0; d < dim; ++d)
          fresh = fresh && (committed_solution.size() == 0 ||
                            committed_solution(k * dim + d) == 0.);
        if (fresh)
          start.state[k] = ContactState::open;
      }
    return start;
  }


  template <int dim>
  typename StateCheck<dim>::Scales
  StateCheck<dim>::scales(const Vector<double> &solution,
                          const Vector<double> &displacement) const
  {
    const unsigned int n_r = pairs.size() * dim;

    // Scales of the tolerances: what both formulations know (not Delta_F,
    // which only the condensed one computes), so that they decide alike.
    double force_scale = 1e-300, displacement_scale = 1e-300;
    for (unsigned int i = 0; i < n_r; ++i)
      {
        force_scale = std::max(force_scale, std::abs(solution(i)));
        displacement_scale =
          std::max(displacement_scale, std::abs(displacement(i)));
      }
    for (const double f : loads.resultant)
      force_scale = std::max(force_scale, std::abs(f));
    for (const auto &pair : pairs)
      displacement_scale = std::max(displacement_scale, pair.initial_gap);
    Scales scales;
    scales.force                  = force_scale;
    scales.displacement           = displacement_scale;
    scales.force_tolerance        = state_tolerance * force_scale;
    scales.displacement_tolerance = state_tolerance * displacement_scale;
    return scales;
  }


  template <int dim>
  void
  StateCheck<dim>::break_open(const unsigned int k,
                              const Trial       &trial,
                              const double       r_n,
                              const double       tension_limit,
                              const Scales      &scales,
                              Trial             &next,
                              double            &violation) const
  {
    const auto &pair = pairs[k];
    next.state[k]    = ContactState::open;
    if (!trial.broken[k] && pair.joint.has_strength())
      next.broken[k] = true;
    next.tensile_slip[k] = false;
    violation            = (-tension_limit - r_n) / scales.force;
  }


  template <int dim>
  void
  StateCheck<dim>::check_stick(const unsigned int    k,
                               const Trial          &trial,
                               const Vector<double> &solution,
                               const Scales         &scales,
                               Trial                &next,
                               double               &violation) const
  {
    const auto  &pair = pairs[k];
    const double tension_limit =
      pair.joint.tensile_limit(pair.area, trial.broken[k]);
    const double   r_n = solution(k * dim);
    Tensor<1, dim> r_t;
    for (unsigned int d = 1; d < dim; ++d)
      r_t[d] = solution(k * dim + d);
    const double r_t_norm = r_t.norm();
    if (pair.joint.breaks(
          r_n, pair.area, trial.broken[k], scales.force_tolerance))
      break_open(k, trial, r_n, tension_limit, scales, next, violation);
    else if (pair.joint.slips(r_n,
                              r_t_norm,
                              pair.area,
                              trial.broken[k],
                              scales.force_tolerance))
      {
        next.state[k]               = ContactState::slip;
        next.slip_direction[k]      = -r_t / r_t_norm;
        next.direction_stiffness[k] = 0.;
        next.tensile_slip[k]        = r_n < 0.;
        violation                   = -pair.joint.friction_margin(r_n,
                                                r_t_norm,
                                                pair.area,
                                                trial.broken[k]) /
                    scales.force;
      }
  }


  template <int dim>
  void
  StateCheck<dim>::check_slip(const unsigned int    k,
                              const Trial          &trial,
                              const Vector<double> &solution,
                              const Vector<double> &displacement,
                              const Scales         &scales,
                              Trial                &next,
                              double               &violation,
                              double               &direction_change) const
  {
    const auto  &pair = pairs[k];
    const double tension_limit =
      pair.joint.tensile_limit(pair.area, trial.broken[k]);
    const double   r_n = solution(k * dim);
    Tensor<1, dim> d_t, increment_t;
    for (unsigned int d = 1; d < dim; ++d)
      {
        d_t[d]         = displacement(k * dim + d);
        increment_t[d] = d_t[d] - committed_displacement[k][d];
      }
    const double along = increment_t * trial.slip_direction[k];
    // A slip increment against the assumed direction (2D: a reversed sign;
    // 3D: more than 90 degrees off) or none at all means the pair sticks.
    const bool sticks =
      along < -scales.displacement_tolerance ||
      (dim == 3 && increment_t.norm() < scales.displacement_tolerance);
    if (pair.joint.breaks(
          r_n, pair.area, trial.broken[k], scales.force_tolerance))
      break_open(k, trial, r_n, tension_limit, scales, next, violation);
    else if (sticks)
      {
        next.state[k] = ContactState::stick;
        violation     = std::abs(along) / scales.displacement;
      }
    else
      {
        if (dim == 3)
          {
            // Next Newton step about this slip increment.
            const Tensor<1, dim> s = increment_t / increment_t.norm();
            direction_change =
              std::max(direction_change, (s - trial.slip_direction[k]).norm());
            next.slip_direction[k] = s;
            next.direction_stiffness[k] =
              pair.joint.shear_strength(r_n,
                                        pair.area,
                                        trial.broken[k],
                                        trial.tensile_slip[k]) /
              increment_t.norm();
          }
        const bool tensile = r_n < -scales.force_tolerance;
        if (tensile != trial.tensile_slip[k])
          {
            next.tensile_slip[k] = tensile;
            violation            = std::abs(r_n) / scales.force;
          }
      }
  }


  template <int dim>
  void
  StateCheck<dim>::check_open(const unsigned int    k,
                              const Vector<double> &displacement,
                              const Scales         &scales,
                              Trial                &next,
                              double               &violation) const
  {
    const double gap = pairs[k].initial_gap + displacement(k * dim);
    if (gap < -scales.displacement_tolerance)
      {
        next.state[k] = ContactState::stick;
        violation     = -gap / scales.displacement;
      }
  }


  template <int dim>
  std::string
  StateCheck<dim>::signature(const Trial &trial) const
  {
    std::string s(pairs.size(), ' ');
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        // In 2D the slip sign is part of the state; in 3D the direction is
        // a continuous unknown, iterated separately.
        char c = (trial.state[k] == ContactState::stick ? 'k' :
                  trial.state[k] == ContactState::open  ? 'o' :
                  dim == 3                              ? 's' :
                  trial.slip_direction[k][1] > 0        ? '+' :
                                                          '-');
        if (trial.broken[k])
          c = static_cast<char>(std::toupper(c));
        if (trial.tensile_slip[k])
          c = 't';
        s[k] = c;
      }
    return s;
  }


  template class StateCheck<2>;
  template class StateCheck<3>;
} // namespace mbfem

#include <mbfem/base/exceptions.h>
#include <mbfem/contact/contact_solver.h>
#include <mbfem/contact/lemke_method.h>
#include <mbfem/contact/semismooth_newton.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace mbfem
{
  std::string
  to_string(const ContactState state)
  {
    switch (state)
      {
        case ContactState::stick:
          return "stick";
        case ContactState::slip:
          return "slip";
        default:
          return "open";
      }
  }



  std::string
  to_string(const ContactFormulation formulation)
  {
    return formulation == ContactFormulation::condensed ? "condensed" :
                                                          "monolithic";
  }



  template <int dim>
  ContactSolver<dim>::ContactSolver(
    std::vector<ContactPair<dim>>              pairs,
    const unsigned int                         max_iterations,
    const ContactFormulation                   formulation,
    const std::string                         &solver_package,
    const ContactSolverParameters::StateSystem state_system)
    : contact_pairs(std::move(pairs))
    , max_iterations(max_iterations)
    , n_pairs(contact_pairs.size())
    , contact_formulation(formulation)
  {
    if (formulation == ContactFormulation::monolithic)
      {
        auto new_system =
          std::make_unique<MonolithicSystem<dim>>(contact_pairs,
                                                  solver_package);
        monolithic = new_system.get();
        system     = std::move(new_system);
      }
    else
      {
        auto new_system = std::make_unique<CondensedSystem<dim>>(contact_pairs,
                                                                 coupling,
                                                                 state_system);
        condensed       = new_system.get();
        system          = std::move(new_system);
      }
    committed.state.resize(n_pairs);
    committed.broken.assign(n_pairs, false);
    committed.tensile_slip.assign(n_pairs, false);
    committed.slip_direction.assign(n_pairs, Tensor<1, dim>());
    committed.direction_stiffness.assign(n_pairs, 0.);
    for (unsigned int k = 0; k < n_pairs; ++k)
      committed.state[k] =
        (contact_pairs[k].initial_gap > 0. ? ContactState::open :
                                             ContactState::stick);
    committed_displacement.assign(n_pairs, Tensor<1, dim>());
    current              = committed;
    current_displacement = committed_displacement;
    initial              = committed;
    for (const auto &pair : contact_pairs)
      nominal_joints.push_back(pair.joint);
    state_check = std::make_unique<const StateCheck<dim>>(
      contact_pairs, held, committed_displacement, loads, coupling, condensed);
  }



  template <int dim>
  void
  ContactSolver<dim>::report_progress(std::ostream *out, const double seconds)
  {
    progress.out      = out;
    progress.interval = seconds;
    progress.in_place = (out == &std::cout && isatty(STDOUT_FILENO) == 1);
    if (progress.in_place)
      progress.interval = 1.;
  }



  template <int dim>
  void
  ContactSolver<dim>::start_progress(const unsigned int increment)
  {
    progress.start(increment);
  }



  template <int dim>
  void
  ContactSolver<dim>::end_progress()
  {
    progress.clear();
  }



  template <int dim>
  std::string
  ContactSolver<dim>::count_states(const Trial &trial) const
  {
    std::array<unsigned int, 3> n = {{0, 0, 0}};
    for (const auto state : trial.state)
      ++n[static_cast<unsigned int>(state)];
    return "stick/slip/open " + std::to_string(n[0]) + "/" +
           std::to_string(n[1]) + "/" + std::to_string(n[2]);
  }



  void
  StateProgress::start(const unsigned int k)
  {
    clear();
    increment = k;
    solves    = 0;
    clock.restart();
    next = in_place ? 2. : interval;
  }



  void
  StateProgress::clear()
  {
    if (shown)
      *out << "\r\033[K" << std::flush;
    shown = false;
  }



  void
  StateProgress::step(const std::string &method, const std::string &states)
  {
    ++solves;
    if (out == nullptr || clock.wall_time() < next)
      return;
    next = clock.wall_time() + interval;
    *out << (in_place ? "\r" : "") << "    ... increment " << increment << ": "
         << solves << " state solves in " << static_cast<int>(clock.wall_time())
         << " s, " << method << ", now " << states;
    if (in_place)
      *out << "\033[K" << std::flush;
    else
      *out << std::endl;
    shown = in_place;
  }



  template <int dim>
  void
  ContactSolver<dim>::change_nominal_joints(
    const std::function<void(const ContactPair<dim> &, JointLaw &)> &change)
  {
    for (unsigned int k = 0; k < n_pairs; ++k)
      change(contact_pairs[k], nominal_joints[k]);
  }



  template <int dim>
  void
  ContactSolver<dim>::restart(const double factor,
                              const bool   reduce_tensile_strength)
  {
    AssertThrow(factor > 0., ExcInternalError());
    strength_factor = factor;
    reduce_tension  = reduce_tensile_strength;
    for (unsigned int k = 0; k < n_pairs; ++k)
      contact_pairs[k].joint =
        nominal_joints[k].reduced(factor, reduce_tensile_strength);
    committed = initial;
    committed_displacement.assign(n_pairs, Tensor<1, dim>());
    committed_solution.reinit(0);
    committed_solved     = false;
    current              = committed;
    current_displacement = committed_displacement;
    current_solution.reinit(0);
    method          = "fast";
    fast_iterations = 0;
    path_switches   = 0;
    path_broken.clear();
    last_concluded.reset();
  }



  template <int dim>
  ContactFormulation
  ContactSolver<dim>::formulation() const
  {
    return contact_formulation;
  }



  template <int dim>
  void
  ContactSolver<dim>::setup(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks)
  {
    coupling.setup(blocks, contact_pairs);
    system->setup(blocks);
    held = system->held();
    setup_statics(blocks);
  }



  template <int dim>
  void
  ContactSolver<dim>::setup(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    const std::vector<bool>                        &present)
  {
    AssertThrow(condensed, ExcInternalError());
    coupling.setup(blocks, contact_pairs, present);
    system->setup(blocks);
    held = system->held();
    setup_statics(blocks);
  }



  template <int dim>
  std::vector<PairEquation<dim>>
  ContactSolver<dim>::pair_equations(const Trial &trial) const
  {
    std::vector<PairEquation<dim>> equations(n_pairs * dim);
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const auto        &pair  = contact_pairs[k];
        const ContactState state = trial.state[k];
        // Slip: |r_T| = c A + mu r_N, as the coefficients of r_N and 1.
        const JointLaw::SlipLine line =
          pair.joint.slip_line(pair.area,
                               trial.broken[k],
                               trial.tensile_slip[k]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            PairEquation<dim> &eq = equations[k * dim + d];
            if (held[k][d] || state == ContactState::open)
              eq.force_coefficients[d] = 1.; // no force
            else if (d == 0 || state == ContactState::stick)
              {
                // Closed: gap zero (normal); stuck: no tangential increment.
                eq.displacement_coefficients[d] = 1.;
                eq.value =
                  (d == 0 ? -pair.initial_gap : committed_displacement[k][d]);
              }
            else
              {
                // Slip: r_T = -(c A + mu r_N) s. In 3D s = v/|v|, v the
                // slip increment, linearised about the last iterate (Newton
                // on the direction):
                //   r_T + mu s r_N + beta (I - s s^T) v = -c A s,
                // which is the slip law itself once (I - s s^T) v = 0.
                const double s           = trial.slip_direction[k][d];
                eq.force_coefficients[d] = 1.;
                eq.force_coefficients[0] += line.slope * s;
                eq.value          = -line.intercept * s;
                const double beta = trial.direction_stiffness[k];
                for (unsigned int e = 1; e < dim && beta > 0.; ++e)
                  {
                    const double m =
                      (d == e ? 1. : 0.) - s * trial.slip_direction[k][e];
                    eq.displacement_coefficients[e] = beta * m;
                    eq.value += beta * m * committed_displacement[k][e];
                  }
              }
          }
      }
    return equations;
  }



  template <int dim>
  bool
  ContactSolver<dim>::solve_trial(const Trial    &trial,
                                  Vector<double> &solution,
                                  Vector<double> &displacement)
  {
    const std::vector<PairEquation<dim>> equations = pair_equations(trial);
    progress.step(method, count_states(trial));
    // Monolithic: a block the states cannot hold makes the whole system
    // singular; say so before a sparse LU returns noise.
    if (monolithic && !mechanisms.unheld_blocks(trial).empty())
      return false;
    return system->solve(equations, loads, solution, displacement);
  }



  template <int dim>
  typename FastIteration<dim>::Solve
  ContactSolver<dim>::trial_solve()
  {
    return [this](const Trial &trial, Vector<double> &x, Vector<double> &d) {
      return solve_trial(trial, x, d);
    };
  }



  template <int dim>
  void
  ContactSolver<dim>::set_increment_data(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks)
  {
    // Data of this increment: Delta_F in the frames (condensed) or the
    // loads of the monolithic system, and F_e.
    system->set_load(blocks, loads);
    loads.resultant = coupling.load_resultant(blocks);
  }



  template <int dim>
  void
  ContactSolver<dim>::set_state_methods(const StateMethodParameters &parameters)
  {
    Assert(!parameters.methods.empty(), ExcInternalError());
    Assert(!parameters.continuation_factors.empty(), ExcInternalError());
    method_parameters = parameters;
  }



  template <int dim>
  void
  ContactSolver<dim>::commit()
  {
    // 3D: the direction a pair just slipped in is the first guess of the
    // next increment's Newton iteration on the direction.
    if (dim == 3)
      for (unsigned int k = 0; k < n_pairs; ++k)
        if (current.state[k] == ContactState::slip)
          {
            const Tensor<1, dim> v = slip_increment(k);
            if (v.norm() > 0.)
              current.slip_direction[k] = v / v.norm();
          }
    committed              = current;
    committed_displacement = current_displacement;
    committed_solution     = current_solution;
    committed_solved       = true;
  }



  template <int dim>
  Tensor<1, dim>
  ContactSolver<dim>::slip_increment(const unsigned int k) const
  {
    Tensor<1, dim> v = current_displacement[k] - committed_displacement[k];
    v[0]             = 0.;
    return v;
  }



  template <int dim>
  double
  ContactSolver<dim>::misalignment() const
  {
    double largest = 0.;
    for (unsigned int k = 0; k < n_pairs; ++k)
      if (current.state[k] == ContactState::slip)
        {
          const Tensor<1, dim> v = slip_increment(k);
          if (v.norm() == 0.)
            continue;
          const double cosine =
            std::min(1.,
                     std::max(-1., v * current.slip_direction[k] / v.norm()));
          largest = std::max(largest, std::acos(cosine) * 180. / numbers::PI);
        }
    return largest;
  }



  template <int dim>
  void
  ContactSolver<dim>::forces_on_block(
    const unsigned int                    b,
    std::vector<types::global_dof_index> &dofs,
    std::vector<double>                  &forces) const
  {
    dofs.clear();
    forces.clear();
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const Tensor<1, dim> r = force(k);
        for (const int sign : {-1, 1})
          {
            const auto &side = contact_pairs[k].side(sign);
            if (side.block != b)
              continue;
            for (const auto &node : side.nodes)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  dofs.push_back(node.dofs[c]);
                  forces.push_back(sign * node.weight * r[c]);
                }
          }
      }
  }



  template <int dim>
  std::vector<double>
  ContactSolver<dim>::floating_amplitudes(const unsigned int b) const
  {
    std::vector<double> alpha(coupling.n_modes(b));
    for (unsigned int a = 0; a < coupling.n_modes(b); ++a)
      alpha[a] = current_solution(n_pairs * dim + coupling.offset(b) + a);
    return alpha;
  }



  template <int dim>
  void
  ContactSolver<dim>::block_solution(const unsigned int b,
                                     const Block<dim>  &block,
                                     Vector<double>    &solution) const
  {
    Assert(monolithic, ExcInternalError());
    monolithic->block_solution(b, block, solution);
  }



  template <int dim>
  const std::vector<ContactPair<dim>> &
  ContactSolver<dim>::pairs() const
  {
    return contact_pairs;
  }



  template <int dim>
  Tensor<1, dim>
  ContactSolver<dim>::local_force(const unsigned int k) const
  {
    Tensor<1, dim> rho;
    if (current_solution.size() > 0)
      for (unsigned int d = 0; d < dim; ++d)
        rho[d] = current_solution(k * dim + d);
    return rho;
  }



  template <int dim>
  Tensor<1, dim>
  ContactSolver<dim>::force(const unsigned int k) const
  {
    // r = R^T rho
    const Tensor<1, dim> rho = local_force(k);
    Tensor<1, dim>       r;
    for (unsigned int i = 0; i < dim; ++i)
      r += rho[i] * contact_pairs[k].frame[i];
    return r;
  }



  template <int dim>
  double
  ContactSolver<dim>::gap(const unsigned int k) const
  {
    return contact_pairs[k].initial_gap + current_displacement[k][0];
  }



  template <int dim>
  Tensor<1, dim>
  ContactSolver<dim>::slip(const unsigned int k) const
  {
    Tensor<1, dim> s = current_displacement[k];
    if (!start_displacement.empty())
      s -= start_displacement[k];
    s[0] = 0.;
    return s;
  }



  template <int dim>
  double
  ContactSolver<dim>::starting_gap(const unsigned int k) const
  {
    return contact_pairs[k].initial_gap +
           (start_displacement.empty() ? 0. : start_displacement[k][0]);
  }



  template <int dim>
  ContactState
  ContactSolver<dim>::state(const unsigned int k) const
  {
    return current.state[k];
  }



  template <int dim>
  bool
  ContactSolver<dim>::broken(const unsigned int k) const
  {
    return current.broken[k];
  }



  template <int dim>
  unsigned int
  ContactSolver<dim>::count(const ContactState state) const
  {
    return std::count(current.state.begin(), current.state.end(), state);
  }



  template <int dim>
  typename StaticAdmissibility<dim>::Result
  ContactSolver<dim>::certify(const bool with_mechanism_factor,
                              const bool unbroken) const
  {
    return certify_with(unbroken ? std::vector<bool>(n_pairs, false) :
                                   current.broken,
                        with_mechanism_factor);
  }



  template <int dim>
  std::optional<typename StaticAdmissibility<dim>::Result>
  ContactSolver<dim>::certify_path_breaking() const
  {
    // The load path's breaks first (it ran first, from an equilibrium),
    // then De Saxce's fixed point's: the first that leaves statics no
    // forces is the verdict, else the first that broke anything.
    std::optional<typename StaticAdmissibility<dim>::Result> first;
    for (unsigned int i = 0; i < path_broken.size(); ++i)
      {
        const BrokenRecord       &record = path_broken[i];
        std::vector<unsigned int> broke;
        for (unsigned int k = 0; k < record.broken.size(); ++k)
          if (record.broken[k] && !current.broken[k] &&
              contact_pairs[k].joint.has_strength())
            broke.push_back(k);
        if (broke.empty())
          continue;
        auto               result = certify_with(record.broken, false);
        std::ostringstream text;
        text << record.by << " broke " << broke.size()
             << " pair(s) whose cohesion or tensile strength the certificate "
                "above counts:";
        for (unsigned int j = 0; j < broke.size() && j < 10; ++j)
          text << "\n      pair " << broke[j] << " at ("
               << contact_pairs[broke[j]].a.point << ")";
        if (broke.size() > 10)
          text << "\n      ... and " << broke.size() - 10 << " more";
        text << "\n    Without their strength, " << result.description;
        result.description = text.str();
        if (result.verdict == StaticAdmissibility<dim>::Verdict::none)
          {
            path_record = i;
            return result;
          }
        if (!first)
          {
            path_record = i;
            first       = result;
          }
      }
    return first;
  }



  template <int dim>
  std::string
  ContactSolver<dim>::path_breaking_method() const
  {
    return path_record < path_broken.size() &&
               !path_broken[path_record].load_path ?
             "De Saxce's fixed point" :
             "the load path";
  }



  template <int dim>
  typename StaticAdmissibility<dim>::Result
  ContactSolver<dim>::certify_with(const std::vector<bool> &broken,
                                   const bool with_mechanism_factor) const
  {
    using Certificate = StaticAdmissibility<dim>;
    typename Certificate::Result result =
      statics(broken).solve(with_mechanism_factor);

    std::ostringstream text;
    text << std::fixed << std::setprecision(6);
    const std::string lp = "a rigid-block linear program over the " +
                           std::to_string(result.n_candidates) +
                           " candidate pairs of the floating blocks" +
                           (dim == 3 ? " (cones as polygons of 64 sides)" : "");
    const std::string factor =
      (result.strength_factor_bounded ?
         (result.strength_factor > 1. ? "above 1000" : "below 0.001") :
         std::to_string(result.strength_factor));
    switch (result.verdict)
      {
        case Certificate::Verdict::admissible:
          text << "statically admissible contact forces exist (" << lp
               << "): the joints' strength could be divided by up to " << factor
               << " (strength factor).";
          break;
        case Certificate::Verdict::undecided:
          text << "the statics certificate cannot decide: forces exist in "
                  "the circumscribed cones but not in the inscribed ones ("
               << lp << "); strength factor at most " << factor << ".";
          break;
        case Certificate::Verdict::none:
          text << "no statically admissible contact forces exist (" << lp
               << "): no forces within the pairs' Mohr-Coulomb cones "
                  "balance the floating blocks' loads; strength factor "
               << factor
               << ": admissible forces exist only with the joints' strength "
                  "multiplied by "
               << (result.strength_factor > 0. ?
                     std::to_string(1. / result.strength_factor) :
                     std::string("more than 1000"))
               << ". Mechanism (a virtual velocity along which the loads "
                  "do more work than the joints can dissipate):";
          text << describe_mechanism(result.mechanism);
          break;
      }
    text << describe_mechanism_factor(result);
    result.description = text.str();
    return result;
  }



  template <int dim>
  void
  ContactSolver<dim>::setup_statics(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks)
  {
    statics_owner.clear();
    statics_areas.clear();
    statics_rows.reset();
    const bool any_split = std::any_of(contact_pairs.begin(),
                                       contact_pairs.end(),
                                       [](const auto &pair) {
                                         return !pair.cross_point_pairs.empty();
                                       });
    // Without a split pair the candidates are the pairs, and the
    // coupling's own rows serve: nothing is copied.
    std::vector<ContactPair<dim>> split;
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const auto &pair = contact_pairs[k];
        if (pair.cross_point_pairs.empty())
          {
            statics_owner.push_back(k);
            statics_areas.push_back(pair.area);
            if (any_split)
              split.push_back(pair);
          }
        else
          for (const auto &one : pair.cross_point_pairs)
            {
              statics_owner.push_back(k);
              statics_areas.push_back(one.area);
              split.push_back(one);
            }
      }
    if (any_split)
      statics_rows =
        std::make_unique<CouplingRows>(coupling.rows_of(blocks, split));
  }



  template <int dim>
  StaticAdmissibility<dim>
  ContactSolver<dim>::statics(const std::vector<bool> &broken) const
  {
    // Every node-to-node pair a merged pair stands for at a point of three
    // or more blocks is a candidate of its own (ContactPair::
    // cross_point_pairs), with the merged pair's law (strength reduction
    // divides it), broken flag and held directions.
    using Certificate        = StaticAdmissibility<dim>;
    const CouplingRows &rows = statics_rows ? *statics_rows : coupling.matrix();
    std::vector<typename Certificate::Candidate> candidates(
      statics_owner.size());
    for (unsigned int i = 0; i < statics_owner.size(); ++i)
      {
        const unsigned int k = statics_owner[i];
        candidates[i].joint  = contact_pairs[k].joint;
        candidates[i].area   = statics_areas[i];
        candidates[i].broken = broken[k];
        candidates[i].tied   = contact_pairs[k].tied;
        if (k < held.size())
          candidates[i].held = held[k];
      }
    std::vector<double> resultant = loads.resultant;
    resultant.resize(coupling.n_modes(), 0.);
    return Certificate(std::move(candidates), rows, resultant);
  }



  template <int dim>
  void
  ContactSolver<dim>::set_early_verdict(const bool on)
  {
    early_verdict = on;
  }



  template <int dim>
  std::string
  ContactSolver<dim>::describe_mechanism_factor(
    const typename StaticAdmissibility<dim>::Result &result) const
  {
    if (result.limit_mechanism.empty())
      return "";
    std::ostringstream text;
    text << std::fixed << std::setprecision(6) << "\n    Limit equilibrium";
    if (result.verdict == StaticAdmissibility<dim>::Verdict::none)
      text << " along that mechanism,";
    else
      text << " along the mechanism of the statics limit"
           << describe_mechanism(result.limit_mechanism) << ",";
    text << " with the shear of every sliding pair against its slip (at "
            "most c A + mu N, N >= 0, with tensile strength sigma_t: at most "
            "c A + mu (N + sigma_t A)), open pairs carrying nothing and those "
            "at rest anything in their cone: the joints' strength could be "
            "divided by "
         << (result.mechanism_factor_bounded ?
               (result.mechanism_factor > 1. ?
                  std::string("above 1000") :
                  std::string("not even 0.001 (no strength up to 1000 "
                              "times the given one holds the loads)")) :
               "up to " + std::to_string(result.mechanism_factor))
         << " (mechanism factor"
         << (dim == 3 && result.limit_mechanism_freedom != 1 ?
               "; shear within pi/64 of the mechanism's slip, as the LP "
               "fixes its direction to that" :
               "")
         << ").";
    return text.str();
  }



  template <int dim>
  void
  ContactSolver<dim>::set_flexibility_columns(
    const ContactSolverParameters::FlexibilityColumns columns)
  {
    if (condensed != nullptr)
      condensed->set_flexibility_columns(columns);
  }



  template <int dim>
  std::pair<std::size_t, std::size_t>
  ContactSolver<dim>::columns_on_demand() const
  {
    return condensed != nullptr ? condensed->columns_on_demand() :
                                  std::pair<std::size_t, std::size_t>();
  }



  template <int dim>
  const std::string &
  ContactSolver<dim>::last_method() const
  {
    return method;
  }



  template <int dim>
  std::string
  ContactSolver<dim>::describe_mechanism(
    const std::vector<double> &mechanism) const
  {
    // Each block's motion as a combination of its rigid-body modes
    // (translations, then rotations in units of the block's diameter).
    std::vector<Vector<double>> motion(coupling.n_blocks());
    double                      largest = 0.;
    for (unsigned int b = 0; b < coupling.n_blocks(); ++b)
      {
        if (coupling.n_modes(b) == 0)
          continue;
        motion[b].reinit(coupling.modes(b)[0].size());
        for (unsigned int a = 0; a < coupling.n_modes(b); ++a)
          motion[b].add(mechanism[coupling.offset(b) + a],
                        coupling.modes(b)[a]);
        largest = std::max(largest, motion[b].linfty_norm());
      }
    std::ostringstream text;
    text << std::fixed << std::setprecision(4);
    for (unsigned int b = 0; b < coupling.n_blocks(); ++b)
      {
        if (coupling.n_modes(b) == 0 ||
            motion[b].linfty_norm() <= 1e-6 * largest)
          continue;
        Tensor<1, dim> translation;
        for (unsigned int d = 0; d < dim; ++d)
          translation[d] = motion[b](d);
        // Rotation per unit translation, or the rotation alone.
        const double length = translation.norm();
        text << "\n      " << coupling.block_name(b) << ": ";
        if (length > 1e-6 * motion[b].linfty_norm())
          text << "translation along (" << translation / length << "), "
               << "rotation per unit translation ";
        else
          text << "no translation, rotation ";
        text << (dim == 2 ? "about z " : "(");
        for (unsigned int d = dim; d < motion[b].size(); ++d)
          text << (d > dim ? " " : "")
               << motion[b](d) / (length > 1e-6 * motion[b].linfty_norm() ?
                                    length :
                                    motion[b].linfty_norm());
        text << (dim == 2 ? "" : ")")
             << " (rotations in units of the block's diameter)";
      }
    return text.str();
  }



  template <int dim>
  bool
  ContactSolver<dim>::has_strength_to_lose() const
  {
    for (unsigned int k = 0; k < n_pairs; ++k)
      if (contact_pairs[k].joint.has_strength() && !committed.broken[k])
        return true;
    return false;
  }



  template <int dim>
  std::vector<std::string>
  ContactSolver<dim>::blocks_without_stuck_pairs() const
  {
    std::vector<std::string> names;
    for (unsigned int b = 0; b < coupling.n_blocks(); ++b)
      {
        if (coupling.n_modes(b) == 0)
          continue;
        bool touched = false, stuck = false;
        for (unsigned int k = 0; k < n_pairs; ++k)
          if (contact_pairs[k].a.block == b || contact_pairs[k].b.block == b)
            {
              touched = true;
              stuck   = stuck || current.state[k] == ContactState::stick;
            }
        if (touched && !stuck)
          names.push_back(coupling.block_name(b));
      }
    return names;
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  ContactSolver<dim>::last_iterations() const
  {
    return {fast_iterations, path_switches};
  }



  template class ContactSolver<2>;
  template class ContactSolver<3>;
} // namespace mbfem

// The state iteration of an increment: the methods of 'Contact/State
// method' in their order until one concludes, and the glue between them
// (the load path's start, the polishing of another method's states by the
// fast iteration, the refusal of answers that leave a mechanism). Each
// method is its own class (fast_iteration, load_path, semismooth_newton,
// lemke_method); ContactSolver's entry point and results are in
// contact_solver.cc.

#include <mbfem/base/exceptions.h>
#include <mbfem/contact/contact_solver.h>
#include <mbfem/contact/lemke_method.h>
#include <mbfem/contact/semismooth_newton.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace mbfem
{
  template <int dim>
  unsigned int
  ContactSolver<dim>::solve_increment(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    const unsigned int                              increment,
    const bool                                      from_last_solve)
  {
    set_increment_data(blocks);

    // The methods in their order until one concludes (by default the fast
    // iteration, which concludes nearly every increment in a few solves,
    // then the load path, the semismooth Newton method, Lemke's method and
    // the load continuation; the last increment's concluding method first
    // by default). The verdict where none does: "no equilibrium" if
    // a method met one (the last such), else the last failure of the fast
    // iteration or the load path, else the others'.
    const std::vector<StateMethod> methods = increment_methods(from_last_solve);
    method                                 = methods.front();
    fast_iterations                        = 0;
    path_switches                          = 0;
    path_broken.clear();
    StateMethodOutcome verdict;
    bool               verdict_is_primary = false;
    // Why Lemke's method, the semismooth Newton method and the
    // continuation failed, said after the verdict where it is another
    // method's.
    std::vector<std::string> secondary;
    for (const StateMethod m : methods)
      {
        method = m; // the one running, for the progress line
        const StateMethodOutcome outcome =
          run_method(m, increment, from_last_solve, m != methods.back());
        if (m == StateMethod::fast)
          fast_iterations = outcome.iterations;
        if (outcome.converged)
          {
            path_switches  = (m == StateMethod::fast ? 0 : outcome.iterations);
            last_concluded = m;
            // The increment has an equilibrium: nothing for
            // certify_path_breaking() to say, whatever fails after it.
            path_broken.clear();
            return fast_iterations + path_switches;
          }
        const bool primary =
          m == StateMethod::fast || m == StateMethod::load_path;
        if (!primary)
          secondary.push_back(outcome.failure);
        // A trial of strength reduction: before the costly methods, the
        // certificate with the joints as the increment found them.
        // (Its first LP alone: the verdict, no strength factor.)
        if (early_verdict && m == StateMethod::load_path &&
            m != methods.back() && coupling.n_modes() > 0)
          AssertThrow(statics(committed.broken).infeasibility(1., true) <=
                        StaticAdmissibility<dim>::feasibility_tolerance,
                      Exceptions::ExcNoEquilibrium(
                        outcome.failure +
                        "\n    The statics certificate, with the joints as "
                        "they were at the start of the increment, admits no "
                        "forces: no equilibrium."));
        if (outcome.no_equilibrium ||
            (!verdict.no_equilibrium && (primary || !verdict_is_primary)))
          {
            verdict            = outcome;
            verdict_is_primary = verdict_is_primary || primary;
          }
      }
    for (const std::string &failure : secondary)
      if (failure != verdict.failure)
        verdict.failure += "\n    " + failure;
    AssertThrow(!verdict.no_equilibrium,
                Exceptions::ExcNoEquilibrium(verdict.failure));
    AssertThrow(false, Exceptions::ExcIncrementNotConverged(verdict.failure));
    return 0;
  }



  template <int dim>
  std::vector<StateMethod>
  ContactSolver<dim>::increment_methods(const bool from_last_solve) const
  {
    if (monolithic)
      return {StateMethod::fast};
    std::vector<StateMethod> methods = method_parameters.methods;
    // A repeated solve whose fast iteration starts from the last solve's
    // states (the plastic Newton method's later passes) keeps the listed
    // order: the load path and Newton's method do not read those states.
    if (from_last_solve)
      return methods;
    // The last increment's concluding method first, the others after it
    // in their order, where it is one whose work grows with what the
    // increment changes: the load path (a switch per state change) and
    // Newton's method (from the last answer). Lemke's method pivots
    // through the whole problem again (0.5 to 0.8 pivots per variable),
    // and the continuation is the fast iteration at other loads.
    if (method_parameters.last_concluded_first && last_concluded &&
        (*last_concluded == StateMethod::load_path ||
         *last_concluded == StateMethod::semismooth_newton))
      {
        const auto last =
          std::find(methods.begin(), methods.end(), *last_concluded);
        if (last != methods.end())
          std::rotate(methods.begin(), last, last + 1);
      }
    return methods;
  }



  template <int dim>
  StateMethodOutcome
  ContactSolver<dim>::run_method(const StateMethod  m,
                                 const unsigned int increment,
                                 const bool         from_last_solve,
                                 const bool         followed)
  {
    StateMethodOutcome outcome;
    const std::string  head = "Load increment " + std::to_string(increment);
    if (m == StateMethod::fast)
      {
        // Its answer is refused where the states leave a mechanism (every
        // pair that could resist a rigid motion slips): such an equilibrium
        // exists only exactly at a limit, and in 3D the linearised slip
        // direction can make the system regular with an unbounded slip
        // instead.
        const auto fast = fast_iteration(
          from_last_solve ?
            current :
            state_check->open_on_demand(committed, committed_solution),
          increment,
          followed ? method_parameters.fast_stall_iterations : 0);
        outcome.iterations = fast.iterations;
        outcome.converged =
          fast.converged &&
          (monolithic || mechanisms.describe(current).empty());
        outcome.no_equilibrium = fast.no_equilibrium;
        outcome.failure        = fast.failure;
        if (fast.converged && !outcome.converged)
          outcome.failure = head +
                            ": the fast iteration's states leave a "
                            "mechanism:" +
                            mechanisms.describe(current);
        return outcome;
      }
    if (m == StateMethod::load_path)
      return run_load_path(increment);

    // Lemke's method, the semismooth Newton method and the load
    // continuation: where they fail, the states stay as the methods before them
    // left them. The continuation scales the increment's load from the path's
    // start (set again, as the same, if the path ran).
    set_path_start();
    set_load_fraction(1.);
    const Trial                       trial        = current;
    const Vector<double>              solution     = current_solution;
    const std::vector<Tensor<1, dim>> displacement = current_displacement;
    outcome =
      (m == StateMethod::semismooth_newton ? semismooth_newton(increment) :
       m == StateMethod::lemke             ? lemke(increment) :
                                             load_continuation(increment));
    if (!outcome.converged)
      {
        current              = trial;
        current_solution     = solution;
        current_displacement = displacement;
      }
    return outcome;
  }



  template <int dim>
  StateMethodOutcome
  ContactSolver<dim>::run_load_path(const unsigned int increment)
  {
    // The path does not conclude where in 3D it pivots in a cycle at one
    // load, where from zero load every event is at s = 0+, or where it
    // stops at a mechanism (below a limit it can take a branch that ends
    // there, doc/state_iteration.md). It may stop part way: the next
    // method starts from the increment's full load.
    set_path_start();
    LoadPath<dim> path(contact_pairs,
                       held,
                       coupling,
                       *state_check,
                       mechanisms,
                       committed,
                       committed_displacement,
                       start_loads,
                       full_loads,
                       loads,
                       trial_solve());
    const auto    end = path.run("Load increment " + std::to_string(increment));
    StateMethodOutcome outcome;
    outcome.iterations     = end.iterations;
    outcome.no_equilibrium = end.no_equilibrium;
    outcome.failure        = end.failure;
    path_switches          = end.iterations;
    // Where the path reached s = 1 it found its states there: the second
    // certificate is for a path that stopped.
    if (end.reached_end)
      finish_path(end.states, increment, outcome);
    else
      {
        path_broken = end.states.broken;
        path_reach  = end.s;
      }
    set_load_fraction(1.);
    return outcome;
  }



  template <int dim>
  void
  ContactSolver<dim>::finish_path(const Trial        &states,
                                  const unsigned int  increment,
                                  StateMethodOutcome &outcome)
  {
    const std::string head = "Load increment " + std::to_string(increment);
    // At s = 1: the states the path ended with, solved and checked as the
    // fast iteration does (in 3D its Newton on the slip directions ends
    // there too).
    set_load_fraction(1.);
    const auto        polish  = fast_iteration(states, increment);
    const std::string reached = LoadPath<dim>::how_far(1., outcome.iterations);
    if (!polish.converged)
      {
        outcome.failure =
          head +
          ": the load path reached the end of the "
          "increment" +
          reached + ", but its states do not settle there: " + polish.failure;
        return;
      }
    const std::string motion = mechanisms.describe(current);
    if (!motion.empty())
      {
        outcome.no_equilibrium = true;
        outcome.failure = head + ": no equilibrium" + reached + "." + motion;
        return;
      }
    outcome.iterations += polish.iterations;
    outcome.converged = true;
  }



  template <int dim>
  void
  ContactSolver<dim>::set_path_start()
  {
    // The start: the load for which the committed solution is exact with
    // the present C_hat, P_hat (these change between Newton's passes).
    const unsigned int n_r  = n_pairs * dim;
    full_loads.displacement = loads.displacement;
    full_loads.resultant    = loads.resultant;
    Vector<double> start(n_r + coupling.n_modes());
    if (committed_solution.size() == start.size())
      start = committed_solution;
    loads.displacement.reinit(n_r);
    start_loads.displacement = condensed->relative_displacement(start, loads);
    start_loads.displacement *= -1.;
    for (unsigned int k = 0; k < n_pairs; ++k)
      for (unsigned int i = 0; i < dim; ++i)
        start_loads.displacement(k * dim + i) += committed_displacement[k][i];
    start_loads.resultant.assign(coupling.n_modes(), 0.);
    for (unsigned int j = 0; j < n_r; ++j)
      for (const auto &[a, value] : coupling.row(j))
        start_loads.resultant[a] -= value * start(j);
  }



  template <int dim>
  void
  ContactSolver<dim>::set_load_fraction(const double s)
  {
    loads.set_fraction(start_loads, full_loads, s);
  }



  namespace
  {
    /**
     * A 3D answer with every pair of a block slipping stands if its largest
     * slip increment is below this times the largest elastic relative
     * displacement (0.63 and 1.35 on the 3D incline at 0.999 of its limit,
     * in 10 increments and in one); the unbounded slips it refuses beyond
     * a limit are orders of magnitude larger (|u| of 1e7 m on issue 20's
     * wedge).
     */
    constexpr double elastic_slip_factor = 1e3;

    /** "Load increment 3: the semismooth Newton method did not ...". */
    std::string
    method_failure(const unsigned int increment,
                   const std::string &method,
                   const std::string &why)
    {
      return "Load increment " + std::to_string(increment) + ": " + method +
             " " + why + (!why.empty() && why.back() == '.' ? "" : ".");
    }
  } // namespace



  template <int dim>
  StateMethodOutcome
  ContactSolver<dim>::semismooth_newton(const unsigned int increment)
  {
    // From the last increment's answer, solved for these pairs and not
    // all zero, as any incremental Newton method: its states are near the
    // new ones (the cube's push: 13 steps from it against 14 from the
    // bonded answer, the same states, and no factorisation of the bonded
    // system, the densest of all: 2.4e10 flops on the cube). Else (a
    // run's or a stage's first increment, whose new pairs hold no force)
    // from the increment's bonded answer (every pair stuck): Newton is
    // local, and from an unloaded state it can end at an indeterminate
    // answer, every pair slipping around a spinning block, which exists
    // below the limit but is not what the load drives.
    Vector<double> start;
    if (committed_solved && committed_solution.linfty_norm() > 0.)
      start = committed_solution;
    else
      {
        Vector<double> displacement;
        Trial          bonded = committed;
        std::fill(bonded.state.begin(),
                  bonded.state.end(),
                  ContactState::stick);
        if (!solve_trial(bonded, start, displacement))
          start = committed_solution;
      }

    SemismoothNewton<dim> newton(method_parameters,
                                 contact_pairs,
                                 *condensed,
                                 coupling,
                                 held,
                                 loads,
                                 committed,
                                 committed_displacement);
    StateMethodOutcome    outcome;
    if (newton.solve(start, outcome.iterations))
      settle(newton.answer_states(), increment, outcome);
    else
      outcome.failure = "did not converge: " + newton.failure();
    if (!outcome.converged)
      outcome.failure = method_failure(increment,
                                       "the semismooth Newton method",
                                       outcome.failure);
    return outcome;
  }



  template <int dim>
  StateMethodOutcome
  ContactSolver<dim>::lemke(const unsigned int increment)
  {
    // The problem without W first: the method's size says whether W, the
    // costly part, is needed at all.
    ContactProblem<dim> problem =
      condensed_problem(increment, 0., false, false);
    LemkeMethod<dim> method(problem,
                            method_parameters.lemke_max_variables,
                            method_parameters.lemke_pivots_per_variable);
    if (method.size() <= method_parameters.lemke_max_variables)
      condensed->add_entries(problem.W);
    StateMethodOutcome outcome;
    if (method.solve(outcome.iterations))
      settle(method.answer_states(committed), increment, outcome);
    else
      outcome.failure = method.failure();
    if (!outcome.converged)
      outcome.failure =
        method_failure(increment, "Lemke's method", outcome.failure);
    return outcome;
  }



  template <int dim>
  void
  ContactSolver<dim>::settle(const Trial        &states,
                             const unsigned int  increment,
                             StateMethodOutcome &outcome)
  {
    const auto polish = fast_iteration(states, increment);
    outcome.iterations += polish.iterations;
    if (!polish.converged)
      {
        outcome.failure = "found an answer, but its states did not settle "
                          "in the fast iteration that checks them";
        return;
      }
    const std::string moving = refused_mechanism();
    if (!moving.empty())
      {
        outcome.failure = "found an answer, but it was refused: its states "
                          "leave a mechanism:" +
                          moving;
        return;
      }
    outcome.converged = true;
  }



  template <int dim>
  std::string
  ContactSolver<dim>::refused_mechanism() const
  {
    // In 3D a block can be in equilibrium with every pair slipping below
    // its limit: the slip directions, spread by the block's elastic
    // deformation, hold it. MechanismTest ignores that (it counts a slipping
    // pair as no resistance), so such states name a mechanism. The answer
    // stands if its slip is of the order of the blocks' deformation: the
    // fast iteration's check has verified the forces within every pair's
    // strength and the equilibrium is solved, so it is statically
    // admissible; what is refused is the unbounded slip (1e7 m on issue
    // 20's wedge) with which a linearised direction can make such states
    // regular beyond a limit.
    const std::string moving = mechanisms.describe(current);
    if (moving.empty() || (dim == 3 && slip_is_elastic()))
      return "";
    return moving;
  }



  template <int dim>
  bool
  ContactSolver<dim>::slip_is_elastic() const
  {
    // The deformation part of d: Delta_F + C_hat rho, without the rigid
    // motions P_hat alpha.
    Vector<double> forces(current_solution);
    for (unsigned int a = 0; a < coupling.n_modes(); ++a)
      forces(n_pairs * dim + a) = 0.;
    const double elastic =
      condensed->relative_displacement(forces, loads).linfty_norm();
    double slip = 0.;
    for (unsigned int k = 0; k < n_pairs; ++k)
      if (current.state[k] == ContactState::slip)
        slip = std::max(slip, slip_increment(k).norm());
    return slip <= elastic_slip_factor * elastic;
  }



  template <int dim>
  StateMethodOutcome
  ContactSolver<dim>::load_continuation(const unsigned int increment)
  {
    // The increment's load scaled up (its data extrapolated past s = 1),
    // where a gap that a block must close by a rigid motion weighs less
    // against the deformation, then brought back to s = 1 in steps, the
    // fast iteration at each from the states of the last. Issue 20's
    // toppling pair with a tenth of its weight in increment 1: the fast
    // iteration concludes at ten times that load, and each step back in
    // one iteration.
    StateMethodOutcome outcome;
    Trial              trial  = committed;
    bool               solved = true;
    for (const double s : method_parameters.continuation_factors)
      {
        set_load_fraction(s);
        const auto step = fast_iteration(trial, increment);
        outcome.iterations += step.iterations;
        solved = step.converged;
        if (!solved)
          break;
        trial = current;
      }
    set_load_fraction(1.);
    outcome.converged = solved && refused_mechanism().empty();
    if (!outcome.converged)
      outcome.failure =
        method_failure(increment, "the load continuation", "did not conclude");
    return outcome;
  }



  template <int dim>
  typename FastIteration<dim>::Outcome
  ContactSolver<dim>::fast_iteration(const Trial       &trial,
                                     const unsigned int increment,
                                     const unsigned int stall_iterations)
  {
    const FastIteration<dim> iteration(*state_check,
                                       mechanisms,
                                       contact_pairs,
                                       max_iterations,
                                       stall_iterations);
    const auto               outcome =
      iteration.run(trial,
                    trial_solve(),
                    "Load increment " + std::to_string(increment));
    if (outcome.converged)
      {
        accept(outcome.states, outcome.solution, outcome.displacement);
        solved_slip_direction = outcome.solved_slip_direction;
      }
    return outcome;
  }



  template <int dim>
  void
  ContactSolver<dim>::accept(const Trial          &trial,
                             const Vector<double> &solution,
                             const Vector<double> &displacement)
  {
    current               = trial;
    current_solution      = solution;
    solved_slip_direction = trial.slip_direction;
    current_displacement.assign(n_pairs, Tensor<1, dim>());
    for (unsigned int k = 0; k < n_pairs; ++k)
      for (unsigned int i = 0; i < dim; ++i)
        current_displacement[k][i] = displacement(k * dim + i);
  }


  // Every member defined in this file (contact_solver.cc instantiates the
  // class with the members defined there).
#define MBFEM_INSTANTIATE(dim)                                                  \
  template unsigned int ContactSolver<dim>::solve_increment(                    \
    const std::vector<std::unique_ptr<Block<dim>>> &,                           \
    const unsigned int,                                                         \
    const bool);                                                                \
  template StateMethodOutcome ContactSolver<dim>::run_method(                   \
    const StateMethod, const unsigned int, const bool, const bool);             \
  template StateMethodOutcome ContactSolver<dim>::run_load_path(                \
    const unsigned int);                                                        \
  template void ContactSolver<dim>::finish_path(const Trial &,                  \
                                                const unsigned int,             \
                                                StateMethodOutcome &);          \
  template void ContactSolver<dim>::set_path_start();                           \
  template void ContactSolver<dim>::set_load_fraction(const double);            \
  template StateMethodOutcome ContactSolver<dim>::semismooth_newton(            \
    const unsigned int);                                                        \
  template StateMethodOutcome ContactSolver<dim>::lemke(const unsigned int);    \
  template void               ContactSolver<dim>::settle(const Trial &,         \
                                           const unsigned int,    \
                                           StateMethodOutcome &); \
  template std::string        ContactSolver<dim>::refused_mechanism() const;    \
  template bool               ContactSolver<dim>::slip_is_elastic() const;      \
  template StateMethodOutcome ContactSolver<dim>::load_continuation(            \
    const unsigned int);                                                        \
  template FastIteration<dim>::Outcome ContactSolver<dim>::fast_iteration(      \
    const Trial &, const unsigned int, const unsigned int);                     \
  template void ContactSolver<dim>::accept(const Trial &,                       \
                                           const Vector<double> &,              \
                                           const Vector<double> &);
  MBFEM_INSTANTIATE(2)
  MBFEM_INSTANTIATE(3)
#undef MBFEM_INSTANTIATE
} // namespace mbfem

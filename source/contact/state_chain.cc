// The state iteration of an increment: the methods of 'Contact/State
// method' in their order until one concludes, and the glue between them
// (the load path's start, the polishing of another method's states by the
// fast iteration, the refusal of answers that leave a mechanism). Each
// method is its own class (StateMethodInterface, registered in
// state_method_registry.cc) working through an IncrementContext;
// ContactSolver's entry point and results are in contact_solver.cc.

#include <mbfem/base/exceptions.h>
#include <mbfem/contact/contact_solver.h>
#include <mbfem/contact/increment_context.h>

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
    const std::vector<const StateMethodEntry<dim> *> methods =
      increment_methods(from_last_solve);
    method          = methods.front()->name;
    fast_iterations = 0;
    path_switches   = 0;
    path_broken.clear();
    StateMethodOutcome verdict;
    bool               verdict_is_primary = false;
    // Why Lemke's method, the semismooth Newton method and the
    // continuation failed, said after the verdict where it is another
    // method's.
    std::vector<std::string> secondary;
    for (const StateMethodEntry<dim> *m : methods)
      {
        method = m->name; // the one running, for the progress line
        const StateMethodTraits  traits = m->traits;
        IncrementContext<dim>    context(*this,
                                      increment,
                                      from_last_solve,
                                      m != methods.back());
        const StateMethodOutcome outcome = m->create()->run(context);
        if (traits.polishes)
          fast_iterations = outcome.iterations;
        if (outcome.converged)
          {
            path_switches  = (traits.polishes ? 0 : outcome.iterations);
            last_concluded = m->name;
            // The increment has an equilibrium: nothing for
            // certify_path_breaking() to say, whatever fails after it.
            path_broken.clear();
            return fast_iterations + path_switches;
          }
        if (outcome.stopped_short)
          path_broken.push_back({outcome.stopped_broken,
                                 outcome.stopped_by,
                                 m->name == "load path"});
        if (!traits.primary)
          secondary.push_back(outcome.failure);
        if (traits.certificate_after_failure && m != methods.back())
          early_statics_verdict(outcome);
        const bool primary = traits.primary;
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
  void
  ContactSolver<dim>::early_statics_verdict(
    const StateMethodOutcome &outcome) const
  {
    // A trial of strength reduction: before the costly methods, the
    // certificate with the joints as the increment found them.
    // (Its first LP alone: the verdict, no strength factor.)
    if (early_verdict && coupling.n_modes() > 0)
      AssertThrow(statics(committed.broken).infeasibility(1., true) <=
                    StaticAdmissibility<dim>::feasibility_tolerance,
                  Exceptions::ExcNoEquilibrium(
                    outcome.failure +
                    "\n    The statics certificate, with the joints as "
                    "they were at the start of the increment, admits no "
                    "forces: no equilibrium."));
  }



  template <int dim>
  std::vector<const StateMethodEntry<dim> *>
  ContactSolver<dim>::increment_methods(const bool from_last_solve) const
  {
    std::vector<const StateMethodEntry<dim> *> methods;
    if (monolithic)
      {
        for (const auto &entry : registered_state_methods<dim>())
          if (entry.traits.monolithic)
            methods.push_back(&entry);
        return methods;
      }
    for (const std::string &name : method_parameters.methods)
      methods.push_back(&registered_state_method<dim>(name));
    // A repeated solve whose fast iteration starts from the last solve's
    // states (the plastic Newton method's later passes) keeps the listed
    // order: the load path and Newton's method do not read those states.
    if (from_last_solve)
      return methods;
    // The last increment's concluding method first, the others after it
    // in their order, where it is one whose work grows with what the
    // increment changes (StateMethodTraits::resumes_first: the load path,
    // a switch per state change, and Newton's method, from the last
    // answer).
    if (method_parameters.last_concluded_first && last_concluded &&
        registered_state_method<dim>(*last_concluded).traits.resumes_first)
      {
        const auto last = std::find_if(methods.begin(),
                                       methods.end(),
                                       [&](const StateMethodEntry<dim> *m) {
                                         return m->name == *last_concluded;
                                       });
        if (last != methods.end())
          std::rotate(methods.begin(), last, last + 1);
      }
    return methods;
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
#define MBFEM_INSTANTIATE(dim)                                             \
  template unsigned int ContactSolver<dim>::solve_increment(               \
    const std::vector<std::unique_ptr<Block<dim>>> &,                      \
    const unsigned int,                                                    \
    const bool);                                                           \
  template FastIteration<dim>::Outcome ContactSolver<dim>::fast_iteration( \
    const Trial &, const unsigned int, const unsigned int);                \
  template void ContactSolver<dim>::accept(const Trial &,                  \
                                           const Vector<double> &,         \
                                           const Vector<double> &);
  MBFEM_INSTANTIATE(2)
  MBFEM_INSTANTIATE(3)
#undef MBFEM_INSTANTIATE
} // namespace mbfem

#include <mbfem/contact/increment_context.h>
#include <mbfem/contact/newton_state_method.h>
#include <mbfem/contact/semismooth_newton.h>

#include <algorithm>

namespace mbfem
{
  template <int dim>
  std::string
  NewtonStateMethod<dim>::name()
  {
    return "semismooth Newton";
  }



  template <int dim>
  std::string
  NewtonStateMethod<dim>::description()
  {
    return "the increment as one nonsmooth system with a sparse Jacobian, "
           "its states then checked by a fast solve (condensed only).";
  }



  template <int dim>
  StateMethodTraits
  NewtonStateMethod<dim>::traits()
  {
    StateMethodTraits traits;
    traits.resumes_first = true;
    return traits;
  }



  template <int dim>
  Vector<double>
  NewtonStateMethod<dim>::start(IncrementContext<dim> &increment)
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
    if (increment.committed_solved() &&
        increment.committed_solution().linfty_norm() > 0.)
      return increment.committed_solution();
    Vector<double>  start, displacement;
    StateTrial<dim> bonded = increment.committed();
    std::fill(bonded.state.begin(), bonded.state.end(), ContactState::stick);
    if (!increment.trial_solve()(bonded, start, displacement))
      start = increment.committed_solution();
    return start;
  }



  template <int dim>
  StateMethodOutcome
  NewtonStateMethod<dim>::run(IncrementContext<dim> &increment)
  {
    increment.set_path_start();
    increment.set_load_fraction(1.);
    typename IncrementContext<dim>::StatesGuard states(increment);

    SemismoothNewton<dim> newton(increment.parameters(),
                                 increment.pairs(),
                                 increment.condensed(),
                                 increment.coupling(),
                                 increment.held(),
                                 increment.loads(),
                                 increment.committed(),
                                 increment.committed_displacement());
    StateMethodOutcome    outcome;
    if (newton.solve(start(increment), outcome.iterations))
      increment.settle(newton.answer_states(), outcome);
    else
      outcome.failure = "did not converge: " + newton.failure();
    if (outcome.converged)
      states.keep();
    else
      outcome.failure = increment.method_failure("the semismooth Newton method",
                                                 outcome.failure);
    return outcome;
  }



  template class NewtonStateMethod<2>;
  template class NewtonStateMethod<3>;
} // namespace mbfem

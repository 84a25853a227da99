#include <mbfem/contact/continuation_state_method.h>
#include <mbfem/contact/increment_context.h>

namespace mbfem
{
  template <int dim>
  std::string
  ContinuationStateMethod<dim>::name()
  {
    return "load continuation";
  }



  template <int dim>
  std::string
  ContinuationStateMethod<dim>::description()
  {
    return "the fast iteration at each of 'Load continuation/Load factors' "
           "times the increment's load (by default ten times, then back to "
           "it in steps; condensed only).";
  }



  template <int dim>
  StateMethodTraits
  ContinuationStateMethod<dim>::traits()
  {
    // Not resumed first: it is the fast iteration at other loads.
    return StateMethodTraits();
  }



  template <int dim>
  StateMethodOutcome
  ContinuationStateMethod<dim>::run(IncrementContext<dim> &increment)
  {
    // The increment's load scaled up (its data extrapolated past s = 1),
    // where a gap that a block must close by a rigid motion weighs less
    // against the deformation, then brought back to s = 1 in steps, the
    // fast iteration at each from the states of the last. Issue 20's
    // toppling pair with a tenth of its weight in increment 1: the fast
    // iteration concludes at ten times that load, and each step back in
    // one iteration. The load is scaled from the path's start.
    increment.set_path_start();
    increment.set_load_fraction(1.);
    typename IncrementContext<dim>::StatesGuard states(increment);

    StateMethodOutcome outcome;
    StateTrial<dim>    trial  = increment.committed();
    bool               solved = true;
    for (const double s : increment.parameters().continuation_factors)
      {
        increment.set_load_fraction(s);
        const auto step = increment.fast_iteration(trial);
        outcome.iterations += step.iterations;
        solved = step.converged;
        if (!solved)
          break;
        trial = increment.current();
      }
    increment.set_load_fraction(1.);
    outcome.converged = solved && increment.refused_mechanism().empty();
    if (outcome.converged)
      states.keep();
    else
      outcome.failure =
        increment.method_failure("the load continuation", "did not conclude");
    return outcome;
  }



  template class ContinuationStateMethod<2>;
  template class ContinuationStateMethod<3>;
} // namespace mbfem

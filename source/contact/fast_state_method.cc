#include <mbfem/contact/fast_state_method.h>
#include <mbfem/contact/increment_context.h>

namespace mbfem
{
  template <int dim>
  std::string
  FastStateMethod<dim>::name()
  {
    return "fast";
  }



  template <int dim>
  std::string
  FastStateMethod<dim>::description()
  {
    return "assume states, solve, check, switch every pair that fails its "
           "check.";
  }



  template <int dim>
  StateMethodTraits
  FastStateMethod<dim>::traits()
  {
    StateMethodTraits traits;
    traits.polishes   = true;
    traits.primary    = true;
    traits.monolithic = true;
    return traits;
  }



  template <int dim>
  StateMethodOutcome
  FastStateMethod<dim>::run(IncrementContext<dim> &increment)
  {
    // Its answer is refused where the states leave a mechanism (every pair
    // that could resist a rigid motion slips): such an equilibrium exists
    // only exactly at a limit, and in 3D the linearised slip direction can
    // make the system regular with an unbounded slip instead.
    const auto fast = increment.fast_iteration(
      increment.from_last_solve ? increment.current() :
                                  increment.committed_open_on_demand(),
      increment.followed ? increment.parameters().fast_stall_iterations : 0);
    StateMethodOutcome outcome;
    outcome.iterations = fast.iterations;
    outcome.converged =
      fast.converged &&
      (increment.monolithic() ||
       increment.mechanisms().describe(increment.current()).empty());
    outcome.no_equilibrium = fast.no_equilibrium;
    outcome.failure        = fast.failure;
    if (fast.converged && !outcome.converged)
      outcome.failure = increment.head() +
                        ": the fast iteration's states leave a mechanism:" +
                        increment.mechanisms().describe(increment.current());
    return outcome;
  }



  template class FastStateMethod<2>;
  template class FastStateMethod<3>;
} // namespace mbfem

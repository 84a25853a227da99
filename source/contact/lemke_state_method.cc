#include <mbfem/contact/increment_context.h>
#include <mbfem/contact/lemke_method.h>
#include <mbfem/contact/lemke_state_method.h>

namespace mbfem
{
  template <int dim>
  std::string
  LemkeStateMethod<dim>::name()
  {
    return "Lemke";
  }



  template <int dim>
  std::string
  LemkeStateMethod<dim>::description()
  {
    return "complementary pivoting on the increment's problem as a linear "
           "complementarity problem (exact in 2D, a faceted friction cone in "
           "3D), its states then checked by a fast solve (condensed only; "
           "see 'Lemke').";
  }



  template <int dim>
  StateMethodTraits
  LemkeStateMethod<dim>::traits()
  {
    // Not resumed first: it pivots through the whole problem again (0.5 to
    // 0.8 pivots per variable), whatever the increment changes.
    return StateMethodTraits();
  }



  template <int dim>
  StateMethodOutcome
  LemkeStateMethod<dim>::run(IncrementContext<dim> &increment)
  {
    increment.set_path_start();
    increment.set_load_fraction(1.);
    typename IncrementContext<dim>::StatesGuard states(increment);

    // The problem without W first: the method's size says whether W, the
    // costly part, is needed at all.
    const StateMethodParameters &limits  = increment.parameters();
    ContactProblem<dim>          problem = increment.problem(false);
    LemkeMethod<dim>             method(problem,
                            limits.lemke_max_variables,
                            limits.lemke_pivots_per_variable);
    if (method.size() <= limits.lemke_max_variables)
      increment.condensed().add_entries(problem.W);
    StateMethodOutcome outcome;
    if (method.solve(outcome.iterations))
      increment.settle(method.answer_states(increment.committed()), outcome);
    else
      outcome.failure = method.failure();
    if (outcome.converged)
      states.keep();
    else
      outcome.failure =
        increment.method_failure("Lemke's method", outcome.failure);
    return outcome;
  }



  template class LemkeStateMethod<2>;
  template class LemkeStateMethod<3>;
} // namespace mbfem

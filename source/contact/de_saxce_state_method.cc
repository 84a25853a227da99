#include <mbfem/contact/de_saxce_method.h>
#include <mbfem/contact/de_saxce_state_method.h>
#include <mbfem/contact/increment_context.h>

namespace mbfem
{
  template <int dim>
  std::string
  DeSaxceStateMethod<dim>::name()
  {
    return "De Saxce";
  }



  template <int dim>
  std::string
  DeSaxceStateMethod<dim>::description()
  {
    return "De Saxce's fixed point: convex QPs (an interior-point method) with the "
           "Mohr-Coulomb cone and each gap shifted by mu times its slip, "
           "until the shifts settle (the cone faceted in 3D), its states "
           "then checked by a fast solve (condensed only; see 'De Saxce').";
  }



  template <int dim>
  StateMethodTraits
  DeSaxceStateMethod<dim>::traits()
  {
    // Not resumed first: each QP is the whole problem again.
    return StateMethodTraits();
  }



  template <int dim>
  StateMethodOutcome
  DeSaxceStateMethod<dim>::run(IncrementContext<dim> &increment)
  {
    increment.set_path_start();
    increment.set_load_fraction(1.);
    typename IncrementContext<dim>::StatesGuard states(increment);

    const StateMethodParameters &limits  = increment.parameters();
    ContactProblem<dim>          problem = increment.problem(false);
    StateMethodOutcome           outcome;
    if (problem.n_pairs > limits.de_saxce_max_pairs)
      {
        outcome.failure = increment.method_failure(
          "De Saxce's fixed point",
          "was not tried: the increment has " +
            std::to_string(problem.n_pairs) +
            " pairs, more than 'Contact/De Saxce/Maximum pairs' (" +
            std::to_string(limits.de_saxce_max_pairs) +
            "), and its QPs are dense");
        return outcome;
      }
    increment.condensed().add_entries(problem.W);
    DeSaxceMethod<dim> method(problem,
                              limits.de_saxce_max_qps,
                              limits.de_saxce_relaxation);
    if (method.solve(outcome.iterations))
      increment.settle(method.answer_states(increment.committed()), outcome);
    else
      {
        outcome.failure = method.failure();
        // The joints it broke, for the certificate's second look
        // (ContactSolver::certify_path_breaking()), as the load path's.
        if (method.stopped_after_breaking())
          {
            outcome.stopped_short = true;
            outcome.stopped_broken =
              method.broken_flags(increment.committed().broken);
            outcome.stopped_by = "De Saxce's fixed point";
          }
      }
    if (outcome.converged)
      states.keep();
    else
      outcome.failure =
        increment.method_failure("De Saxce's fixed point", outcome.failure);
    return outcome;
  }



  template class DeSaxceStateMethod<2>;
  template class DeSaxceStateMethod<3>;
} // namespace mbfem

#include <mbfem/contact/increment_context.h>
#include <mbfem/contact/load_path.h>
#include <mbfem/contact/load_path_state_method.h>

#include <iomanip>
#include <sstream>

namespace mbfem
{
  template <int dim>
  std::string
  LoadPathStateMethod<dim>::name()
  {
    return "load path";
  }



  template <int dim>
  std::string
  LoadPathStateMethod<dim>::description()
  {
    return "the increment's load applied in a continuous fraction, one pair "
           "switching where its condition fails (condensed only).";
  }



  template <int dim>
  StateMethodTraits
  LoadPathStateMethod<dim>::traits()
  {
    StateMethodTraits traits;
    traits.primary                   = true;
    traits.resumes_first             = true;
    traits.certificate_after_failure = true;
    return traits;
  }



  template <int dim>
  StateMethodOutcome
  LoadPathStateMethod<dim>::run(IncrementContext<dim> &increment)
  {
    // The path does not conclude where in 3D it pivots in a cycle at one
    // load, where from zero load every event is at s = 0+, or where it
    // stops at a mechanism (below a limit it can take a branch that ends
    // there, doc/state_iteration.md). It may stop part way: the next
    // method starts from the increment's full load.
    increment.set_path_start();
    LoadPath<dim>      path(increment.pairs(),
                       increment.held(),
                       increment.coupling(),
                       increment.state_check(),
                       increment.mechanisms(),
                       increment.committed(),
                       increment.committed_displacement(),
                       increment.start_loads(),
                       increment.full_loads(),
                       increment.loads(),
                       increment.trial_solve());
    const auto         end = path.run(increment.head());
    StateMethodOutcome outcome;
    outcome.iterations     = end.iterations;
    outcome.no_equilibrium = end.no_equilibrium;
    outcome.failure        = end.failure;
    // Where the path reached s = 1 it found its states there: the second
    // certificate is for a path that stopped.
    if (end.reached_end)
      finish(increment, end.states, outcome);
    else
      {
        outcome.stopped_short  = true;
        outcome.stopped_broken = end.states.broken;
        std::ostringstream by;
        by << "the load path (up to s = " << std::setprecision(6) << end.s
           << " of this increment)";
        outcome.stopped_by = by.str();
      }
    increment.set_load_fraction(1.);
    return outcome;
  }



  template <int dim>
  void
  LoadPathStateMethod<dim>::finish(IncrementContext<dim> &increment,
                                   const StateTrial<dim> &states,
                                   StateMethodOutcome    &outcome)
  {
    // At s = 1: the states the path ended with, solved and checked as the
    // fast iteration does (in 3D its Newton on the slip directions ends
    // there too).
    increment.set_load_fraction(1.);
    const auto        polish  = increment.fast_iteration(states);
    const std::string reached = LoadPath<dim>::how_far(1., outcome.iterations);
    if (!polish.converged)
      {
        outcome.failure =
          increment.head() +
          ": the load path reached the end of the "
          "increment" +
          reached + ", but its states do not settle there: " + polish.failure;
        return;
      }
    const std::string motion =
      increment.mechanisms().describe(increment.current());
    if (!motion.empty())
      {
        outcome.no_equilibrium = true;
        outcome.failure =
          increment.head() + ": no equilibrium" + reached + "." + motion;
        return;
      }
    outcome.iterations += polish.iterations;
    outcome.converged = true;
  }



  template class LoadPathStateMethod<2>;
  template class LoadPathStateMethod<3>;
} // namespace mbfem

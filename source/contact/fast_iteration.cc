#include <mbfem/contact/fast_iteration.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <sstream>

namespace mbfem
{
  template <int dim>
  FastIteration<dim>::FastIteration(const StateCheck<dim>    &checks,
                                    const MechanismTest<dim> &mechanisms,
                                    const std::vector<ContactPair<dim>> &pairs,
                                    const unsigned int max_iterations,
                                    const unsigned int stall_iterations)
    : checks(checks)
    , mechanisms(mechanisms)
    , pairs(pairs)
    , max_iterations(max_iterations)
    , stall_iterations(stall_iterations)
  {}



  template <int dim>
  struct FastIteration<dim>::Progress
  {
    /** Switching one pair at a time (after a cycle or a lost support). */
    bool                  damped = false;
    std::set<std::string> seen;
    /** The last trial that solved, the states and violations its check gave. */
    bool                have_good = false;
    Trial               last_good, last_good_next;
    std::vector<double> last_good_violation;
    /** The fewest pairs switching so far, and when (undamped). */
    unsigned int fewest_switching = numbers::invalid_unsigned_int;
    unsigned int fewest_at        = 0;
  };



  template <int dim>
  typename FastIteration<dim>::Outcome
  FastIteration<dim>::run(Trial              trial,
                          const Solve       &solve,
                          const std::string &head) const
  {
    Outcome  outcome;
    Progress progress;
    progress.seen.insert(checks.signature(trial));
    for (unsigned int iteration = 1; iteration <= max_iterations; ++iteration)
      {
        outcome.iterations = iteration;
        Vector<double> solution, displacement;
        if (!solve(trial, solution, displacement))
          {
            if (damp_after_singular(progress, trial))
              continue;
            outcome.no_equilibrium = true;
            outcome.failure =
              head + ": no equilibrium." + mechanisms.diagnose_singular(trial);
            return outcome;
          }

        std::vector<double> violation;
        double              direction_change;
        Trial               next = checks.check(
          trial, solution, displacement, violation, direction_change);
        if (checks.signature(next) == checks.signature(trial) &&
            direction_change < direction_tolerance)
          {
            // The directions the solve used, for condensed_problem(); the
            // trial keeps the updated ones (the next increment's guess).
            const auto solved             = trial.slip_direction;
            trial.slip_direction          = next.slip_direction;
            outcome.states                = trial;
            outcome.solution              = solution;
            outcome.displacement          = displacement;
            outcome.solved_slip_direction = solved;
            outcome.converged             = true;
            return outcome;
          }
        progress.have_good           = true;
        progress.last_good           = trial;
        progress.last_good_next      = next;
        progress.last_good_violation = violation;

        outcome.failure =
          choose_next(progress, trial, next, violation, iteration, head);
        if (!outcome.failure.empty())
          return outcome;
        progress.seen.insert(checks.signature(next));
        trial = next;
      }
    outcome.failure = head + ": the contact states did not settle in " +
                      std::to_string(max_iterations) +
                      " iterations ('Contact/Maximum iterations'). Use more "
                      "load increments.";
    return outcome;
  }


  template <int dim>
  bool
  FastIteration<dim>::damp_after_singular(Progress &progress,
                                          Trial    &trial) const
  {
    // Too many switches at once can lose a block's support; go back and
    // switch one pair at a time.
    if (progress.damped || !progress.have_good)
      return false;
    progress.damped = true;
    progress.seen.clear();
    trial = single_change(progress.last_good,
                          progress.last_good_next,
                          progress.last_good_violation);
    progress.seen.insert(checks.signature(trial));
    return true;
  }



  template <int dim>
  std::string
  FastIteration<dim>::choose_next(Progress                  &progress,
                                  const Trial               &trial,
                                  Trial                     &next,
                                  const std::vector<double> &violation,
                                  const unsigned int         iteration,
                                  const std::string         &head) const
  {
    if (progress.damped && checks.signature(next) != checks.signature(trial))
      next = single_change(trial, next, violation);
    if (checks.signature(next) != checks.signature(trial) &&
        progress.seen.count(checks.signature(next)) == 1)
      {
        if (progress.damped)
          return describe_cycle(head, iteration, trial, next);
        progress.damped = true;
        progress.seen.clear();
        next = single_change(trial, next, violation);
      }
    // Undamped still (no cycle): has it stalled?
    if (!progress.damped && stall_iterations > 0)
      {
        const unsigned int switching = n_switching(trial, next);
        // Only the 3D slip directions moving counts as progress.
        if (switching < progress.fewest_switching || switching == 0)
          {
            progress.fewest_switching = switching;
            progress.fewest_at        = iteration;
          }
        else if (iteration - progress.fewest_at >= stall_iterations)
          return describe_stall(head, iteration, switching);
      }
    return {};
  }



  template <int dim>
  typename FastIteration<dim>::Trial
  FastIteration<dim>::single_change(const Trial               &from,
                                    const Trial               &to,
                                    const std::vector<double> &violation)
  {
    Trial              result = from;
    const unsigned int worst =
      std::distance(violation.begin(),
                    std::max_element(violation.begin(), violation.end()));
    result.state[worst]        = to.state[worst];
    result.broken[worst]       = to.broken[worst];
    result.tensile_slip[worst] = to.tensile_slip[worst];
    result.slip_direction      = to.slip_direction;
    result.direction_stiffness = to.direction_stiffness;
    return result;
  }


  template <int dim>
  unsigned int
  FastIteration<dim>::n_switching(const Trial &trial, const Trial &next) const
  {
    // What the states' signature tells apart: the state, the 2D slip
    // sense, breaking and tensile slip.
    const std::string from = checks.signature(trial),
                      to   = checks.signature(next);
    unsigned int n         = 0;
    for (unsigned int k = 0; k < from.size(); ++k)
      n += (from[k] != to[k]);
    return n;
  }



  template <int dim>
  std::string
  FastIteration<dim>::describe_stall(const std::string &head,
                                     const unsigned int iteration,
                                     const unsigned int switching) const
  {
    return head + ": the fast iteration stalls: at solve " +
           std::to_string(iteration) + " " + std::to_string(switching) +
           " pairs switch, and in the " + std::to_string(stall_iterations) +
           " solves since the fewest (solve " +
           std::to_string(iteration - stall_iterations) +
           ") none switched fewer ('Contact/Fast iteration stall'), so it "
           "gave way to the next method. Use more load increments.";
  }



  template <int dim>
  std::string
  FastIteration<dim>::describe_cycle(const std::string &head,
                                     const unsigned int iteration,
                                     const Trial       &trial,
                                     const Trial       &next) const
  {
    std::ostringstream listed;
    unsigned int       n_listed = 0;
    for (unsigned int k = 0; k < pairs.size() && n_listed < 10; ++k)
      if (next.state[k] != trial.state[k])
        {
          listed << "\n      pair " << k << " at (" << pairs[k].a.point
                 << "): " << to_string(trial.state[k]) << " <-> "
                 << to_string(next.state[k]);
          ++n_listed;
        }
    return head + ": the contact states cycle after " +
           std::to_string(iteration) +
           " iterations, even switching one pair at a time. Pairs "
           "that keep switching:" +
           listed.str() + "\n    Use more load increments.";
  }


  template class FastIteration<2>;
  template class FastIteration<3>;
} // namespace mbfem

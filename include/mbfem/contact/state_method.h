#ifndef mbfem_contact_state_method_h
#define mbfem_contact_state_method_h

#include <string>
#include <vector>

namespace mbfem
{
  /**
   * The methods of an increment's state iteration (doc/state_iteration.md),
   * tried in the order of 'Contact/State method' until one concludes:
   *
   * - fast: the fixed-point active-set iteration (assume states, solve,
   *   check, switch);
   * - load path: the increment's load applied from the last converged
   *   state in a continuous parameter s in [0, 1], switching the state of
   *   one pair exactly where its condition fails, which ends at s = 1 with
   *   the solution or at a mechanism with the fraction it reached;
   * - semismooth Newton: the increment as one nonsmooth system (Alart and
   *   Curnier's projections for the joint law) with a sparse Jacobian,
   *   whose answer gives the states that the fast iteration then solves
   *   and checks;
   * - load continuation: the fast iteration at ten times the increment's
   *   load, then back to it in steps, each from the states of the last.
   */
  enum class StateMethod : unsigned char
  {
    fast,
    load_path,
    semismooth_newton,
    load_continuation
  };

  std::string
  to_string(const StateMethod method);

  /** The choices of 'Contact/State method', as a ParameterHandler pattern. */
  std::string
  state_method_names();

  /**
   * The methods named in @p text (a comma-separated list of
   * state_method_names()), in order; throws naming 'Contact/State method'
   * on an unknown or repeated name or an empty list.
   */
  std::vector<StateMethod>
  parse_state_methods(const std::string &text);

  /** The list as 'Contact/State method' writes it. */
  std::string
  to_string(const std::vector<StateMethod> &methods);
} // namespace mbfem

#endif

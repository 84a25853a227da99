#ifndef mbfem_contact_state_method_h
#define mbfem_contact_state_method_h

#include <deal.II/base/parameter_handler.h>

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
   * - Lemke: complementary pivoting on the increment's problem as a
   *   linear complementarity problem (LemkeMethod), whose answer gives the
   *   states that the fast iteration then solves and checks;
   * - load continuation: the fast iteration at ten times the increment's
   *   load, then back to it in steps, each from the states of the last.
   */
  enum class StateMethod : unsigned char
  {
    fast,
    load_path,
    semismooth_newton,
    lemke,
    load_continuation
  };

  std::string
  to_string(const StateMethod method);

  /**
   * How one method of the state iteration ended on an increment: whether
   * it concluded, whether its verdict is "no equilibrium" (a mechanism, a
   * singular trial), its iterations (solves, switches, Newton steps or
   * pivots, with those of the fast iteration that checks its answer) and,
   * where it did not conclude, why. A method's own outcome adds its answer.
   */
  struct StateMethodOutcome
  {
    bool         converged      = false;
    bool         no_equilibrium = false;
    unsigned int iterations     = 0;
    std::string  failure;
  };

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



  /**
   * Which methods the state iteration tries, and the limits of those that
   * have any ('Contact/State method', 'Contact/Semismooth Newton',
   * 'Contact/Load continuation'). The fast iteration's limit is
   * 'Contact/Maximum iterations'; the load path's follows from the number
   * of pairs (doc/state_iteration.md).
   */
  struct StateMethodParameters
  {
    /** Declares the entries in the subsection 'Contact' (entered). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Reads them, in the subsection 'Contact' (entered). */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** The methods, in the order tried. */
    std::vector<StateMethod> methods = {StateMethod::fast,
                                        StateMethod::load_path,
                                        StateMethod::semismooth_newton,
                                        StateMethod::lemke,
                                        StateMethod::load_continuation};

    /**
     * The fast iteration gives way to the next method where the number of
     * pairs switching state has not reached a new low in this many solves
     * ('Contact/Fast iteration stall'; 0: never).
     */
    unsigned int fast_stall_iterations = 10;

    /**
     * Whether an increment starts with the method that concluded the last
     * one where that is the load path or Newton's method, the others
     * following in their order ('Contact/Method order'): a model whose
     * increments the fast iteration does not conclude then pays for its
     * trials once, not at every increment.
     */
    bool last_concluded_first = true;

    /** Newton iterations per system before the method gives up. */
    unsigned int newton_max_iterations = 200;
    /**
     * Newton converged where every residual is below this times the
     * largest force or displacement of the increment's data: far below the
     * state check's 1e-9, so that the states read from the answer are
     * those the check accepts.
     */
    double newton_tolerance = 1e-11;
    /**
     * Where Newton's method stalls or meets a singular Jacobian, it is
     * run again with the floating
     * blocks held by springs to where they were (a proximal point
     * iteration on their rigid motions): the springs' stiffness relative
     * to the contact stiffness (doc/state_iteration.md), and the number of
     * times the springs' anchors may follow the blocks.
     */
    double       proximal_stiffness = 1e-4;
    unsigned int proximal_steps     = 100;
    /**
     * The load continuation's load factors (of the increment, from the
     * last converged state), the last 1: from ten times the load back to
     * it.
     */
    std::vector<double> continuation_factors = {10., 5., 2., 1.};

    /**
     * Lemke's method is not tried on a problem of more variables than
     * this: its tableau is dense, 16 n^2 bytes, and a pivot costs 2 n^2
     * operations (2000 variables: 64 MB and 8e6 per pivot).
     */
    unsigned int lemke_max_variables = 2000;
    /**
     * Pivots per variable before Lemke's method gives up: it needed 0.5 to
     * 0.8 on the problems of doc/state_iteration.md.
     */
    unsigned int lemke_pivots_per_variable = 10;
  };
} // namespace mbfem

#endif

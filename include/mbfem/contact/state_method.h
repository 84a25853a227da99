#ifndef mbfem_contact_state_method_h
#define mbfem_contact_state_method_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mbfem
{
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
    /**
     * A method that stopped after breaking joints (the load path short of
     * the increment's end, De Saxce's fixed point where statics failed):
     * the pairs' broken flags there, which the statics certificate of a
     * failed increment reads (ContactSolver::certify_path_breaking()), and
     * who broke them, for its message ("the load path (up to s = 0.4 of
     * this increment)", "De Saxce's fixed point").
     */
    bool              stopped_short = false;
    std::vector<bool> stopped_broken;
    std::string       stopped_by;
  };

  /**
   * What the state iteration's chain (ContactSolver::solve_increment())
   * needs to know of a method besides its answer: the method's place in
   * the chain, never how it works.
   */
  struct StateMethodTraits
  {
    /**
     * The fast iteration: every other method's answer is polished by it,
     * and its iterations are counted apart (ContactSolver::last_iterations()).
     */
    bool polishes = false;
    /**
     * Its failure is the verdict of an increment no method concludes (the
     * others' failures are said after it).
     */
    bool primary = false;
    /**
     * Its work grows with what the increment changes (not with the whole
     * problem), so that where it concluded the last increment it goes first
     * ('Contact/Method order').
     */
    bool resumes_first = false;
    /**
     * In a trial of strength reduction, where it fails and costly methods
     * follow, the statics certificate decides first (set_early_verdict()).
     */
    bool certificate_after_failure = false;
    /** It runs on the monolithic formulation too (the others need C_hat). */
    bool monolithic = false;
  };

  template <int dim>
  class IncrementContext;

  /**
   * A method of the state iteration (doc/state_iteration.md): given one
   * increment (IncrementContext: its data, the committed states and the
   * services every method shares), it concludes with the increment's states
   * made current, or says why not. A new method is a class derived from
   * this one with static name(), description() and traits(), in its own
   * file pair, and one line in source/contact/state_method_registry.cc.
   */
  template <int dim>
  class StateMethodInterface
  {
  public:
    virtual ~StateMethodInterface() = default;

    virtual StateMethodOutcome
    run(IncrementContext<dim> &increment) = 0;
  };

  /** One method as the registry holds it. */
  template <int dim>
  struct StateMethodEntry
  {
    /** Its name in 'Contact/State method'. */
    std::string name;
    /** What it does, for the entry's documentation. */
    std::string                                                 description;
    StateMethodTraits                                           traits;
    std::function<std::unique_ptr<StateMethodInterface<dim>>()> create;
  };

  /**
   * Every method, in the default order of 'Contact/State method'
   * (source/contact/state_method_registry.cc).
   */
  template <int dim>
  const std::vector<StateMethodEntry<dim>> &
  registered_state_methods();

  /** The registered method of @p name (a name that parse_state_methods() accepted). */
  template <int dim>
  const StateMethodEntry<dim> &
  registered_state_method(const std::string &name);

  /** The choices of 'Contact/State method', as a ParameterHandler pattern. */
  std::string
  state_method_names();

  /**
   * The methods named in @p text (a comma-separated list of
   * state_method_names()), in order; throws naming 'Contact/State method'
   * on an unknown or repeated name or an empty list.
   */
  std::vector<std::string>
  parse_state_methods(const std::string &text);

  /** The list as 'Contact/State method' writes it. */
  std::string
  join_state_methods(const std::vector<std::string> &methods);



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
    std::vector<std::string> methods = {"fast",
                                        "load path",
                                        "semismooth Newton",
                                        "Lemke",
                                        "De Saxce",
                                        "load continuation"};

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

    /**
     * De Saxce's fixed point: the QPs of one increment before it gives up,
     * and the relaxation omega of its shifts (without it, omega = 1, the
     * fixed point oscillates on Goodman and Bray's column).
     */
    unsigned int de_saxce_max_qps    = 200;
    double       de_saxce_relaxation = 0.5;
    /** Not tried on an increment of more pairs: its QPs are dense. */
    unsigned int de_saxce_max_pairs = 500;
  };
} // namespace mbfem

#endif

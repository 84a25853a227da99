#ifndef mbfem_contact_increment_context_h
#define mbfem_contact_increment_context_h

#include <mbfem/contact/contact_solver.h>
#include <mbfem/contact/state_method.h>

#include <array>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * One increment as a state method sees it (StateMethodInterface): the
   * increment's data, the committed states it starts from, the states in
   * hand, and the services every method shares (the fast iteration, the
   * polishing of another method's states, the load fraction). It is what a
   * method may read and change; the methods share nothing else, and none
   * reads another's members. ContactSolver::solve_increment() makes one for
   * every method it runs.
   */
  template <int dim>
  class IncrementContext
  {
  public:
    using Trial = StateTrial<dim>;

    /**
     * Increment @p increment of @p solver; @p from_last_solve: a repeated
     * solve of the same increment (the plastic Newton method's later
     * passes), whose fast iteration starts from the last solve's states;
     * @p followed: another method comes after this one.
     */
    IncrementContext(ContactSolver<dim> &solver,
                     const unsigned int  increment,
                     const bool          from_last_solve,
                     const bool          followed);

    const unsigned int increment;
    const bool         from_last_solve;
    const bool         followed;

    /** "Load increment 3", the start of every message of a method. */
    std::string
    head() const;

    /**
     * "Load increment 3: the semismooth Newton method did not converge.":
     * the failure of @p method for the reason @p why.
     */
    std::string
    method_failure(const std::string &method, const std::string &why) const;

    /** 'Contact/State method' and the methods' limits. */
    const StateMethodParameters &
    parameters() const;

    /** The monolithic formulation (no C_hat, P_hat: the fast iteration only).
     */
    bool
    monolithic() const;

    /** @name The increment's data */
    /** @{ */
    const std::vector<ContactPair<dim>> &
    pairs() const;

    /** The condensed system (C_hat, P_hat; condensed formulation only). */
    CondensedSystem<dim> &
    condensed() const;

    const RigidCoupling<dim> &
    coupling() const;

    /** Directions in which both nodes of a pair are held by supports. */
    const std::vector<std::array<bool, dim>> &
    held() const;

    /**
     * The increment's loads as the system solves them now, and at the
     * fractions s = 1 and s = 0 of set_path_start() (a method that follows
     * the load sets them with set_load_fraction()).
     */
    IncrementLoads &
    loads() const;
    const IncrementLoads &
    full_loads() const;
    const IncrementLoads &
    start_loads() const;

    const StateCheck<dim> &
    state_check() const;

    const MechanismTest<dim> &
    mechanisms() const;
    /** @} */

    /** @name The states */
    /** @{ */
    /** The last converged increment's states, forces and displacements. */
    const Trial &
    committed() const;
    const Vector<double> &
    committed_solution() const;
    const std::vector<Tensor<1, dim>> &
    committed_displacement() const;
    /**
     * Whether committed_solution() was solved for these pairs (not after a
     * restart or a new stage's pairs, which hold no force yet).
     */
    bool
    committed_solved() const;

    /** The states in hand (a method that concludes leaves its own here). */
    const Trial &
    current() const;

    /**
     * The committed states, with the pairs whose committed forces say they
     * opened set open (StateCheck::open_on_demand()).
     */
    Trial
    committed_open_on_demand() const;
    /** @} */

    /** @name The services the methods share */
    /** @{ */
    /**
     * The fast iteration (FastIteration) from @p trial; where it converges
     * its answer is current. With @p stall_iterations > 0 it gives up where
     * it stalls.
     */
    typename FastIteration<dim>::Outcome
    fast_iteration(const Trial &trial, const unsigned int stall_iterations = 0);

    /** The solve of a trial's states, as FastIteration and LoadPath take it. */
    typename FastIteration<dim>::Solve
    trial_solve();

    /**
     * The fast iteration from the @p states a method found, and the
     * mechanism test of its answer: @p outcome converges if they stand (the
     * answer then current); it counts the fast iteration's iterations too.
     */
    void
    settle(const Trial &states, StateMethodOutcome &outcome);

    /**
     * The mechanism for which the current answer is refused; empty if it
     * stands: its states leave no mechanism, or (3D) its slip is elastic.
     */
    std::string
    refused_mechanism() const;

    /**
     * The load path's start: the load (s = 0) for which the committed
     * solution is exact with the present flexibility and coupling.
     */
    void
    set_path_start();

    /**
     * The increment's data at the load fraction @p s of set_path_start()'s
     * (s = 1: the increment's load; s > 1 beyond it).
     */
    void
    set_load_fraction(const double s);

    /**
     * The condensed problem of the increment from its start (Lemke's
     * method's), without W unless @p with_flexibility.
     */
    ContactProblem<dim>
    problem(const bool with_flexibility) const;
    /** @} */

    /**
     * Keeps the states in hand and puts them back when it goes out of
     * scope, unless the method concluded (keep()): a method that fails then
     * leaves them as the methods before it did.
     */
    class StatesGuard
    {
    public:
      explicit StatesGuard(IncrementContext<dim> &context);
      ~StatesGuard();

      /** The method concluded: its states stay. */
      void
      keep();

    private:
      ContactSolver<dim>         &solver;
      const Trial                 trial;
      const Vector<double>        solution;
      std::vector<Tensor<1, dim>> displacement;
      bool                        kept = false;
    };

  private:
    /**
     * Whether the current answer's largest slip increment is of the order
     * of the blocks' deformation, not an unbounded rigid slide
     * (refused_mechanism()).
     */
    bool
    slip_is_elastic() const;

    ContactSolver<dim> &solver;
  };
} // namespace mbfem

#endif

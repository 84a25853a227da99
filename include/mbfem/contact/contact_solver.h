#ifndef mbfem_contact_contact_solver_h
#define mbfem_contact_contact_solver_h

#include <mbfem/block/block.h>
#include <mbfem/contact/condensed_system.h>
#include <mbfem/contact/contact_problem.h>
#include <mbfem/contact/contact_solver_parameters.h>
#include <mbfem/contact/contact_state.h>
#include <mbfem/contact/fast_iteration.h>
#include <mbfem/contact/interface_system.h>
#include <mbfem/contact/load_path.h>
#include <mbfem/contact/mechanism_test.h>
#include <mbfem/contact/monolithic_system.h>
#include <mbfem/contact/rigid_coupling.h>
#include <mbfem/contact/state_check.h>
#include <mbfem/contact/state_method.h>
#include <mbfem/contact/static_admissibility.h>
#include <mbfem/interface/contact_interface.h>
#include <mbfem/interface/pair_equation.h>

#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * How the interface system is solved: condensed to the contact DoFs
   * through the blocks' flexibilities (the multi-body method), or as one
   * monolithic Lagrange-multiplier system of all blocks (the reference).
   */
  enum class ContactFormulation : unsigned char
  {
    condensed,
    monolithic
  };

  std::string
  to_string(const ContactFormulation formulation);

  /**
   * A progress line for a long state iteration: at most one every
   * 'interval' seconds, naming the increment, the state solves so far,
   * the method and the states of the trial in hand. Off without a stream
   * (test mode: its lines depend on the machine's speed). On a terminal
   * (@p in_place) one line that updates every second from the second
   * second on and is cleared when the increment ends, as users of
   * long-running tools expect; in a log a line every 'interval' seconds.
   */
  struct StateProgress
  {
    void
    start(const unsigned int increment);

    /** One more state solve; prints if the interval has passed. */
    void
    step(const std::string &method, const std::string &states);

    /** Clears the line shown in place, if any. */
    void
    clear();

    std::ostream *out       = nullptr;
    double        interval  = 10.;
    bool          in_place  = false;
    bool          shown     = false;
    unsigned int  increment = 0, solves = 0;
    double        next = 0.;
    Timer         clock;
  };



  /**
   * The contact solve of the multi-body method (paper eqs. 7-10, 15 and
   * Table 1), generalised to any number of blocks and to 3D: the state
   * iteration on an InterfaceSystem, its entry point and its results
   * (doc/contact_solver.md).
   *
   * With r_k the force of pair k on its block b (and -r_k on block a), the
   * relative displacement of the pairs is
   *
   *   d = C_a r + Delta_F + P alpha,
   *
   * C_a assembled from the blocks' contact flexibilities, Delta_F the
   * relative displacement under the external loads alone, and alpha the
   * amplitudes of the floating blocks' free modes, whose equilibrium closes
   * the system: P^T r = -F_e. Everything is written in each pair's frame
   * (normal, tangents). Each state gives its equations (stick: no normal
   * gap, no tangential increment; slip: no normal gap, |r_T| = c A + mu r_N
   * against the slip; open: r = 0); the states are iterated within a load
   * increment until every pair satisfies its check. The system that gives
   * d for a trial's equations is a CondensedSystem (C_a, P, as above).
   *
   * With ContactFormulation::monolithic the same state iteration runs on
   * the same PairEquation rows, but d comes from a monolithic
   * Lagrange-multiplier system of all blocks (MonolithicSystem) instead of
   * C_a and P: a second road to the same discrete solution.
   *
   * Not copyable or movable: its interface system refers to its pairs and
   * coupling.
   */
  template <int dim>
  class ContactSolver
  {
  public:
    ContactSolver(
      std::vector<ContactPair<dim>> pairs,
      const unsigned int            max_iterations,
      const ContactFormulation      formulation = ContactFormulation::condensed,
      const std::string            &solver_package = "Amesos_Klu",
      const ContactSolverParameters::StateSystem state_system =
        ContactSolverParameters::StateSystem::automatic);

    ContactSolver(const ContactSolver &) = delete;
    ContactSolver &
    operator=(const ContactSolver &) = delete;

    /**
     * Condensed: the dense flexibility C_a and coupling P, from every
     * block's factorisation. Monolithic: the system of all blocks (which
     * must have had assemble_load() once); no block is factorised.
     */
    void
    setup(const std::vector<std::unique_ptr<Block<dim>>> &blocks);

    /**
     * setup() for the pairs of one stage of a model whose stages add
     * blocks: the blocks @p present marks false are not there yet (no
     * floating modes; no pair of this solver touches them). Condensed only.
     */
    void
    setup(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
          const std::vector<bool>                        &present);

    /**
     * The start of a stage that adds blocks or switches interfaces on:
     * this solver, built over the pairs there from now on, takes over what
     * @p earlier (the solver of the stage before) committed for the pairs
     * both have, @p earlier_pair[k] being pair k's index in @p earlier
     * (numbers::invalid_unsigned_int for a pair new at this stage): states,
     * broken joints, slips, gaps, forces, floating amplitudes, and the
     * strength factor of restart(). A new pair starts closed, stuck and
     * unloaded where its two sides are now (from @p blocks' displacements):
     * gap zero, its slip measured from here, as for a block cast onto the
     * deformed ones. Condensed only.
     */
    void
    continue_from(const ContactSolver                            &earlier,
                  const std::vector<unsigned int>                &earlier_pair,
                  const std::vector<std::unique_ptr<Block<dim>>> &blocks);

    ContactFormulation
    formulation() const;

    /**
     * Solves one load increment. Each block must have the load of this
     * increment (assemble_load()); condensed, its solution must hold its
     * response u_F to that load. Returns the number of
     * state iterations; throws with a message naming blocks or pairs when
     * the increment has no consistent solution. The state iteration starts
     * from the committed states, or with @p from_last_solve from those of
     * the last solve of this increment (Newton's passes, whose linear
     * problems differ little from one to the next).
     */
    unsigned int
    solve_increment(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                    const unsigned int                              increment,
                    const bool from_last_solve = false);

    /**
     * The methods of the state iteration, in the order solve_increment()
     * tries them ('Contact/State method'), and their limits. The monolithic
     * formulation has the fast iteration only: the others need C_hat and
     * P_hat.
     */
    void
    set_state_methods(const StateMethodParameters &parameters);

    /**
     * With @p on, an increment whose load path fails (after the fast
     * iteration where that comes first, 'Contact/Method order')
     * asks the statics certificate first, with the joints broken at the
     * start of the increment (breaking only takes strength away): if no
     * admissible forces exist, it ends with ExcNoEquilibrium at once,
     * without the semismooth Newton method, Lemke's method and the load
     * continuation. A trial of strength reduction needs only that verdict;
     * a plain run keeps the chain, whose failures its message reports.
     */
    void
    set_early_verdict(const bool on);

    /**
     * Whole or on demand (Contact/Flexibility columns); before setup(), no
     * effect on the monolithic formulation.
     */
    void
    set_flexibility_columns(
      const ContactSolverParameters::FlexibilityColumns columns);

    /** Accepts the converged increment as the start of the next one. */
    void
    commit();

    /**
     * Long state iterations print a progress line to @p out every
     * @p seconds (nullptr: none).
     */
    void
    report_progress(std::ostream *out, const double seconds = 10.);

    /**
     * The clock of the progress lines starts for increment @p increment:
     * once per increment, whatever passes and steps it takes.
     */
    void
    start_progress(const unsigned int increment);

    /** Clears a progress line shown in place (StateProgress). */
    void
    end_progress();

    /**
     * Back to the states before the first increment (no slip, nothing
     * broken), with every joint's strength divided by @p strength_factor
     * (JointLaw::reduced()): a trial of strength reduction. The
     * flexibilities and factorisations stay as they are.
     */
    void
    restart(const double strength_factor, const bool reduce_tension = true);

    /**
     * Lets @p change set each pair's nominal joint law (the one restart()
     * divides), given the pair: the strengths of a sample of 'Mode =
     * reliability'. Takes effect at the next restart().
     */
    void
    change_nominal_joints(
      const std::function<void(const ContactPair<dim> &, JointLaw &)> &change);

    /** Contact forces on block @p b as (DoF, force) lists. */
    void
    forces_on_block(const unsigned int                    b,
                    std::vector<types::global_dof_index> &dofs,
                    std::vector<double>                  &forces) const;

    /** Amplitudes of block @p b's floating modes (condensed). */
    std::vector<double>
    floating_amplitudes(const unsigned int b) const;

    /** Monolithic: block @p b's displacement from the converged solve. */
    void
    block_solution(const unsigned int b,
                   const Block<dim>  &block,
                   Vector<double>    &solution) const;

    const std::vector<ContactPair<dim>> &
    pairs() const;

    /** Force on block b of pair k in its frame: (r_N, r_T...). */
    Tensor<1, dim>
    local_force(const unsigned int k) const;

    /** Force on block b of pair k in global components. */
    Tensor<1, dim>
    force(const unsigned int k) const;

    /** Normal gap g0 + d.n (>= 0). */
    double
    gap(const unsigned int k) const;

    /**
     * Tangential relative displacement (accumulated slip) in the frame,
     * since the pair began: a pair new at a stage (continue_from()) counts
     * from there.
     */
    Tensor<1, dim>
    slip(const unsigned int k) const;

    /**
     * The gap pair k had when it began: the mesh's, or 0 for a pair new at
     * a stage (closed where its sides were; continue_from()).
     */
    double
    starting_gap(const unsigned int k) const;

    ContactState
    state(const unsigned int k) const;

    bool
    broken(const unsigned int k) const;

    /**
     * 3D: the largest angle (degrees) between a slipping pair's friction
     * direction and its slip in the increment just solved (before
     * commit()), over pairs slipping at least 1 % of the most. The
     * direction is solved for (Newton on the slip law), so this is 0 up to
     * the iteration's tolerance: a check, printed every increment. 0 in 2D.
     */
    double
    misalignment() const;

    /** Count of pairs in @p state. */
    unsigned int
    count(const ContactState state) const;

    /**
     * The statics certificate for the loads of the current increment (as
     * the last solve_increment() set them up): do contact forces within
     * every candidate pair's Mohr-Coulomb cone balance all floating blocks
     * together? The pairs' broken flags are those of the last trial. The
     * result's description names the verdict, the strength factor and,
     * if none exist, each moving block's translation and rotation. With
     * @p unbroken every pair keeps its cohesion and tensile strength: the
     * strength factor is then an upper bound for any load path (breaking
     * only takes strength away), which strength reduction needs.
     */
    typename StaticAdmissibility<dim>::Result
    certify(const bool with_mechanism_factor = true,
            const bool unbroken              = false) const;

    /**
     * The statics certificate with the joints as the increment's load path
     * left them where it stopped: the pairs it broke on the way, in the
     * order of its events, without their cohesion and tensile strength,
     * for good. Where this admits no forces and
     * certify() does, the increment has no equilibrium after the breaking
     * its own loads caused, which rigid-block statics with every joint
     * unbroken cannot see (doc/decisions.md, "Joints the load path broke").
     * Empty where the last increment's path broke no pair beyond those
     * certify() counts as broken, or did not run.
     */
    std::optional<typename StaticAdmissibility<dim>::Result>
    certify_path_breaking() const;

    /**
     * Which method broke the joints certify_path_breaking() reads: "the
     * load path" or "De Saxce's fixed point".
     */
    std::string
    path_breaking_method() const;

    /**
     * Names of the floating blocks none of whose pairs stuck in the
     * increment just solved (all slip or open): such an increment may have
     * converged to a sliding state no forces can hold, and is certified.
     */
    std::vector<std::string>
    blocks_without_stuck_pairs() const;

    /**
     * Whether a pair has cohesion or tensile strength left at the start of
     * the increment (unbroken), which the increment could break: where none
     * has, breaking cannot be why no state was found (doc/decisions.md).
     */
    bool
    has_strength_to_lose() const;

    /**
     * The condensed problem of the increment just solved (before commit())
     * with its solution, or with @p solved false the problem of an
     * increment that failed, from its start. Without W if not
     * @p with_flexibility (the costly part, CondensedSystem::add_entries()).
     * Condensed formulation only (source/contact/contact_problem.cc).
     */
    ContactProblem<dim>
    condensed_problem(const unsigned int increment,
                      const double       time,
                      const bool         solved           = true,
                      const bool         with_flexibility = true) const;

    /**
     * Flexibility columns computed on demand so far, and how many the
     * blocks on demand have (CondensedSystem::columns_on_demand()).
     */
    std::pair<std::size_t, std::size_t>
    columns_on_demand() const;

    /** Which method concluded the last solve_increment(). */
    const std::string &
    last_method() const;

    /**
     * The state iterations of the last solve_increment(): those of the fast
     * iteration, and those of the method that concluded if another did (0
     * if the fast iteration concluded); solve_increment() returns their
     * sum (the iterations of a method that failed before are not counted).
     */
    std::pair<unsigned int, unsigned int>
    last_iterations() const;

  private:
    using Trial = StateTrial<dim>;

    /** "stick/slip/open a/b/c" of @p trial, for progress lines. */
    std::string
    count_states(const Trial &trial) const;

    StateProgress progress;

    /**
     * The slip directions of the system whose solution was accepted last
     * (the fast iteration keeps the updated ones in current).
     */
    std::vector<Tensor<1, dim>> solved_slip_direction;

    /** The rows (Table 1) of every pair direction for @p trial. */
    std::vector<PairEquation<dim>>
    pair_equations(const Trial &trial) const;

    /**
     * Solves the system of @p trial: the forces rho (condensed: then the
     * alphas) into @p solution, and d in the pairs' frames.
     */
    bool
    solve_trial(const Trial    &trial,
                Vector<double> &solution,
                Vector<double> &displacement);

    /** solve_trial() as the function the state methods are given. */
    typename FastIteration<dim>::Solve
    trial_solve();


    /**
     * The certificate's mechanism (per floating mode) as each moving
     * block's translation and rotation.
     */
    std::string
    describe_mechanism(const std::vector<double> &mechanism) const;

    /** The limit equilibrium along the certificate's mechanism, in words. */
    std::string
    describe_mechanism_factor(
      const typename StaticAdmissibility<dim>::Result &result) const;

    /**
     * The fast iteration (FastIteration) from @p trial on this solver's
     * interface system; where it converges, its answer is current. With
     * @p stall_iterations > 0 it gives up where it stalls (another method
     * follows).
     */
    typename FastIteration<dim>::Outcome
    fast_iteration(const Trial       &trial,
                   const unsigned int increment,
                   const unsigned int stall_iterations = 0);

    /**
     * Pair @p k's tangential relative displacement in the increment just
     * solved (current against committed), in its frame.
     */
    Tensor<1, dim>
    slip_increment(const unsigned int k) const;

    /** Stores a consistent trial and its solution as current. */
    void
    accept(const Trial          &trial,
           const Vector<double> &solution,
           const Vector<double> &displacement);

    /**
     * solve_increment()'s data: Delta_F in the pairs' frames (condensed;
     * from each block's response u_F in its solution) or the monolithic
     * system's loads, and the floating blocks' load resultants F_e.
     */
    void
    set_increment_data(const std::vector<std::unique_ptr<Block<dim>>> &blocks);

    /**
     * The methods of this increment in the order tried: 'Contact/State
     * method', the one that concluded the last increment first where
     * 'Contact/Method order' says so (not on a repeated solve of the same
     * increment, @p from_last_solve); the fast iteration alone where the
     * formulation is monolithic (the others need C_hat and P_hat).
     */
    std::vector<const StateMethodEntry<dim> *>
    increment_methods(const bool from_last_solve) const;

    /**
     * In a trial of strength reduction (set_early_verdict()), after a
     * method whose failure calls for it (the load path) and before the
     * costly ones: throws ExcNoEquilibrium if the statics certificate, with
     * the joints as the increment found them, admits no forces.
     */
    void
    early_statics_verdict(const StateMethodOutcome &outcome) const;

    /** The pairs, with the joint laws of restart()'s strength factor. */
    std::vector<ContactPair<dim>> contact_pairs;
    /** The nominal joint law of every pair (strength reduction divides it). */
    std::vector<JointLaw> nominal_joints;
    /**
     * The relative displacement of each pair where it began: zero, or
     * its sides' at the stage that brought it (continue_from()).
     */
    std::vector<Tensor<1, dim>> start_displacement;

    /** See set_early_verdict(). */
    bool early_verdict = false;

    /**
     * The statics certificate's LPs for the increment's loads, with the
     * pairs' broken flags @p broken (certify() solves and formats it).
     */
    StaticAdmissibility<dim>
    statics(const std::vector<bool> &broken) const;

    /**
     * setup(): the statics certificate's candidates, the pairs with each
     * merged pair of a cross-point split into the node-to-node pairs it
     * stands for (ContactPair::cross_point_pairs): which pair each
     * candidate belongs to, its area, and its rows of P_hat (null where no
     * pair is split: the coupling's own rows serve).
     */
    void
    setup_statics(const std::vector<std::unique_ptr<Block<dim>>> &blocks);
    std::vector<unsigned int>     statics_owner;
    std::vector<double>           statics_areas;
    std::unique_ptr<CouplingRows> statics_rows;

    /** statics(@p broken) solved, with its verdict in words. */
    typename StaticAdmissibility<dim>::Result
    certify_with(const std::vector<bool> &broken,
                 const bool               with_mechanism_factor) const;

    /**
     * The pairs' broken flags where a method of the increment stopped
     * after breaking joints (the load path, De Saxce's fixed point), in
     * the order the methods ran, and who broke them
     * (StateMethodOutcome::stopped_by); certify_path_breaking() tries them
     * in turn.
     */
    struct BrokenRecord
    {
      std::vector<bool> broken;
      std::string       by;
      bool              load_path = true;
    };
    std::vector<BrokenRecord> path_broken;
    /** The record certify_path_breaking() proved "no equilibrium" with. */
    mutable unsigned int path_record = 0;

    /** The arguments of the last restart(), for continue_from(). */
    double strength_factor = 1.;
    bool   reduce_tension  = true;
    /** The states before the first increment, for restart(). */
    Trial                    initial;
    const unsigned int       max_iterations;
    const unsigned int       n_pairs;
    const ContactFormulation contact_formulation;
    /** RigidCoupling: the floating modes and P_hat, for both formulations. */
    RigidCoupling<dim> coupling;
    /**
     * The interface system: CondensedSystem or MonolithicSystem, with a
     * typed view of whichever it is (the other is nullptr) for what only
     * one has (the load path and the Newton method need C_hat).
     */
    std::unique_ptr<InterfaceSystem<dim>> system;
    CondensedSystem<dim>                 *condensed  = nullptr;
    MonolithicSystem<dim>                *monolithic = nullptr;

    /** Directions in which both nodes are held by supports. */
    std::vector<std::array<bool, dim>> held;

    /** The loads of the current increment (Delta_F, F_e). */
    IncrementLoads loads;

    /** Converged state and the solution of the current increment. */
    Trial                       committed;
    std::vector<Tensor<1, dim>> committed_displacement; // local d
    Trial                       current;
    Vector<double>              current_solution;
    std::vector<Tensor<1, dim>> current_displacement;
    /** (rho, alpha) of the converged increment: the load path's start. */
    Vector<double> committed_solution;
    /**
     * Whether committed_solution was solved for these pairs (false after
     * restart() and continue_from(), whose new pairs hold no force yet):
     * Newton's method starts from it only then.
     */
    bool committed_solved = false;

    /** The load path: the loads of the increment at s = 1 and at s = 0. */
    IncrementLoads full_loads, start_loads;

    /** The check of Table 1's conditions, on the members above. */
    std::unique_ptr<const StateCheck<dim>> state_check;
    /** The mechanism tests of the trials' states. */
    const MechanismTest<dim> mechanisms{contact_pairs, held, loads, coupling};

    /** 'Contact/State method' and the methods' limits. */
    StateMethodParameters method_parameters;
    /** The method running or (after the increment) the one that concluded. */
    std::string  method          = "fast";
    unsigned int fast_iterations = 0, path_switches = 0;
    /**
     * The method that concluded the last increment (or plastic pass) since
     * this solver was made or restart() (none before): the first of the
     * next increment's where 'Contact/Method order' says so. A stage that
     * changes the contact set-up gets a new solver; one that changes loads
     * only keeps it.
     */
    std::optional<std::string> last_concluded;

    /** The state methods work on the increment through it. */
    friend class IncrementContext<dim>;
  };
} // namespace mbfem

#endif

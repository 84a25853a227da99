#ifndef mbfem_analysis_multibody_problem_h
#define mbfem_analysis_multibody_problem_h

#include <mbfem/analysis/formulation_comparison.h>
#include <mbfem/analysis/strength_reduction.h>
#include <mbfem/block/block.h>
#include <mbfem/contact/contact_solver.h>
#include <mbfem/interface/joint_water.h>
#include <mbfem/output/output.h>
#include <mbfem/output/screen_detail.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  template <int dim>
  struct Parameters;

  /**
   * The multi-body finite element method from mesh to results: the mesh is
   * split into blocks (one per material id), each block is factorised once,
   * contact pairs are found on the declared interfaces, the blocks' contact
   * flexibilities are computed by unit loads, and the load history is
   * followed increment by increment (external response of every block,
   * contact-state iteration, field recovery, output). A mesh with one held
   * block and no interface is the plain elastic problem.
   */
  template <int dim>
  class MultiBodyProblem
  {
  public:
    MultiBodyProblem(Parameters<dim> &parameters, ConditionalOStream &pcout);

    void
    run();

    /** The blocks with their final fields (after run()). */
    const std::vector<std::unique_ptr<Block<dim>>> &
    get_blocks() const;

    /** The contact solver, or nullptr without interfaces. */
    const ContactSolver<dim> *
    get_contact() const;

  private:
    void
    make_blocks();

    /**
     * Under mpirun, the rank that factorises and solves each block,
     * balanced by the blocks' cost() (Parallel::assign_owners()).
     */
    void
    assign_block_owners();

    /**
     * Under mpirun, that every rank's contact iteration took the same
     * states (it must: the same code on the same data); otherwise a clear
     * error rather than ranks that wait for each other.
     */
    void
    check_ranks_agree() const;

    /**
     * Under mpirun, each block's solution from its owner to every rank,
     * after all ranks solved theirs (Block::share_solution()).
     */
    void
    share_solutions();

    /**
     * Whether the blocks are factorised: not if the monolithic formulation
     * alone runs, whose one system holds them all.
     */
    bool
    factorises_blocks() const;

    /** Each block's DoFs, constraints and stiffness (not yet factorised). */
    void
    setup_blocks();

    /**
     * Factorises each block's stiffness on its owner, if
     * factorises_blocks(): with MUMPS where the block's flexibility will be
     * on demand among @p pairs (its columns are entries of that
     * factorisation's inverse), so that the block does not hold Amesos's
     * as well; hence after the pairs are found.
     */
    void
    factorize_blocks(const std::vector<ContactPair<dim>> &pairs);

    /**
     * The blocks' sizes, materials and free rigid-body modes (on the screen
     * or in the blocks' detail file: ScreenDetail).
     */
    void
    print_blocks() const;

    /** The screen's summary of many blocks: cells, DoFs, floating, sizes. */
    void
    print_block_counts() const;

    /**
     * The resultant force of every interface at increment @p k (on the
     * screen or in the interfaces' detail file).
     */
    void
    print_resultants(const unsigned int k, const double time) const;

    /** Where print_blocks() and the interfaces' detail go. */
    mutable std::unique_ptr<ScreenDetail> screen;

    /** Every block with free rigid-body modes has a pair that can hold it. */
    void
    check_blocks_held(const std::vector<ContactPair<dim>> &pairs) const;

    /**
     * The contact pairs and the formulation(s) that solve for their forces:
     * the condensed one (flexibilities), the monolithic one, or both.
     */
    void
    make_contact();

    /** Each configuration's water in the joints, where 'Water pressure' has
     * some. */
    void
    make_water();

    /** The screen line of the contact formulation(s) of @p n_pairs pairs. */
    void
    print_formulation(const unsigned int n_pairs) const;

    /**
     * Models whose stages add or remove blocks or switch interfaces on:
     * the refusals (the monolithic reference, plasticity, an in-situ
     * stress, unknown blocks or interfaces, an added block moved by its
     * supports before its stage, a block removed by the first stage or no
     * later than it is added), and each added or removed block's stage
     * (Block::set_added(), Block::set_removed()).
     */
    void
    check_staged_model();

    /**
     * The configurations of the stages from the pairs of the whole model
     * (a single one without stages that change the model), each with its
     * condensed solver set up, and their water.
     */
    void
    make_configurations(const std::vector<ContactPair<dim>> &pairs,
                        const std::function<std::unique_ptr<ContactSolver<dim>>(
                          std::vector<ContactPair<dim>>)>   &make_solver);

    /**
     * Increment @p k begins a stage with another configuration: its
     * solver takes over (ContactSolver::continue_from()) and a line says
     * what the stage adds.
     */
    void
    switch_configuration(const unsigned int k);

    /**
     * Back to the first configuration with its states before the first
     * increment, the joints' strengths divided by @p factor.
     */
    void
    restart_contact(const double factor);

    /** Every increment of the load history, from the start. */
    void
    run_load_history();

    /**
     * Mode = strength reduction: the factor of safety by trials of the
     * whole load history at reduced joint strengths, on the same blocks,
     * factorisations and flexibilities; then the load history at the
     * factor found, with output, and the table of the trials.
     */
    void
    run_strength_reduction(const double setup_seconds);

    /**
     * One trial of run_strength_reduction(): the load history from the
     * start at the joints' strengths divided by @p factor, silent and
     * without output; with @p statics_bound the certificate's strength
     * factor after every increment.
     */
    StrengthTrial
    run_trial(const double factor, const bool statics_bound);

    /**
     * run_trial(): the statics certificate (every pair unbroken) after an
     * increment into @p trial's statics bound, and at the @p last one the
     * limit equilibrium along its mechanism.
     */
    void
    measure_statics(StrengthTrial &trial, const bool last) const;

    /** The output folder, and the PVD writers of blocks and pairs. */
    void
    make_writers();

    /**
     * One load increment, as step-18's do_timestep(): solve (with step
     * halving), check, print, compare, write, commit.
     */
    void
    do_increment(const unsigned int k);

    /**
     * Increment @p k's files of the contact pairs (CSV, the summary, the
     * contact problem if asked for); the name of the pairs' VTU file.
     */
    std::string
    write_contact_files(const unsigned int k,
                        const double       time,
                        const unsigned int iterations,
                        const unsigned int reference_iterations);

    /**
     * Increment @p k's VTU files of the blocks present at @p time (each
     * rank its own), indexed with @p pair_file in the PVD files.
     */
    void
    write_blocks(const unsigned int k,
                 const double       time,
                 const std::string &pair_file);

    void
    print_plasticity(const unsigned int   plastic_iterations,
                     const PlasticUpdate &plastic_update) const;

    /** What a finished run prints at its end. */
    void
    print_run_summary();

    void
    print_formulation_times() const;

    /**
     * Solves increment @p k up to pseudo-time @p time from the committed
     * state: one pass for elastic blocks, repeated passes until the plastic
     * strain settles for plastic ones. Returns the number of plastic
     * iterations; throws if the contact states or the plastic iteration
     * do not converge.
     */
    unsigned int
    solve_step(const unsigned int k,
               const double       time,
               unsigned int      &iterations,
               unsigned int      &reference_iterations,
               PlasticUpdate     &plastic_update);

    /** solve_step(): every block's plastic strain from its last solution. */
    PlasticUpdate
    update_plastic_strain();

    /**
     * solve_step(): throws ExcIncrementNotConverged once the plastic
     * iteration has used 'Plasticity/Maximum iterations'.
     */
    void
    check_plastic_iterations(const unsigned int k,
                             const double       time,
                             const double       change,
                             const unsigned int plastic_iterations) const;

    /**
     * Increment @p k, retried in halved steps if it fails and
     * 'Load history/Maximum step halvings' allows; returns the plastic
     * iterations of its last step.
     */
    unsigned int
    solve_increment(const unsigned int k,
                    unsigned int      &iterations,
                    unsigned int      &reference_iterations,
                    PlasticUpdate     &plastic_update);

    /**
     * After increment @p k converged: if every pair of some floating
     * block slips or is open, runs the statics certificate and, if no
     * admissible forces exist, ends the run (ExcNoEquilibrium).
     */
    void
    certify_sliding_blocks(const unsigned int k, const double time) const;

    /** Accepts a step short of the increment's end as converged. */
    void
    commit_step();

    /**
     * One pass of solve_step(): with Newton's tangent if @p newton, and if
     * that has no solution, with the elastic stiffness. Returns whether
     * Newton is still on.
     */
    bool
    pass_with_fallback(const unsigned int k,
                       const double       time,
                       unsigned int      &iterations,
                       unsigned int      &reference_iterations,
                       const bool         from_last_solve,
                       bool               newton,
                       const unsigned int plastic_iterations);

    /**
     * A progress line for long plastic runs; @p omega < 0 for a Newton
     * iteration.
     */
    void
    print_plastic_progress(const unsigned int plastic_iterations,
                           const double       change,
                           const double       omega,
                           const unsigned int n_yielded) const;

    /**
     * Aitken's relaxation of the fixed point x = F(x) (plain steps converge
     * at a rate near 1 once the plastic zone is large): the next omega from
     * the last two residuals.
     */
    static double
    aitken_relaxation(const double omega, const PlasticUpdate &update);

    /**
     * Newton failed on @p failure: puts the elastic stiffness back for the
     * rest of the step (returns false, Newton off) or, if the stiffness
     * was elastic already, rethrows.
     */
    bool
    give_way_to_initial_stress(const ExceptionBase &failure,
                               const unsigned int   plastic_iterations);

    /**
     * Newton's method for plastic blocks: reassembles and refactorises every
     * block whose tangent changed, and then recomputes the contact
     * flexibilities.
     */
    void
    update_tangent_stiffness();

    /**
     * Every block's load at @p time (with the water and the forces
     * released by removed blocks), and with @p condensed its solution
     * without contact forces; on every rank with @p loads_everywhere.
     */
    void
    assemble_loads(const double time,
                   const bool   condensed,
                   const bool   loads_everywhere);

    /**
     * Every block's displacement from the contact forces just found:
     * @p condensed: solved again with them and the floating amplitudes;
     * else the monolithic system's.
     */
    void
    recover_fields(const bool condensed);

    /**
     * One pass through increment @p k: every block's load and (condensed)
     * its response to it, the contact iteration (and the monolithic
     * reference), the fields. Repeated while the plastic strain settles.
     */
    void
    solve_pass(const unsigned int k,
               const double       time,
               unsigned int      &iterations,
               unsigned int      &reference_iterations,
               const bool         from_last_solve = false);

    /** With 'Load history/Stages': a line where a stage begins. */
    void
    print_stage(const unsigned int k) const;

    void
    print_increment(const unsigned int k,
                    const double       time,
                    const unsigned int iterations) const;

    void
    print_errors(const double time) const;

    /**
     * Formulation "both": the monolithic reference against the condensed
     * solve of this increment, pair by pair; prints and records it.
     */
    void
    compare_formulations();

    /** One line per increment in <base>-summary.csv (rewritten whole). */
    void
    write_summary(const unsigned int k,
                  const double       time,
                  const unsigned int iterations,
                  const unsigned int reference_iterations);

    /** Largest tangential relative displacement over the pairs. */
    static double
    max_slip(const ContactSolver<dim> &solver);

    /**
     * What a failure message says of the files on disk: where the results
     * of the increments that converged are, or that none was written.
     */
    std::string
    earlier_results() const;

    /** Output/<base>-<prefix>problem-<k>: the stem of a contact problem. */
    std::string
    problem_stem(const unsigned int k, const std::string &prefix) const;

    /**
     * An increment that ends with exit code 3: writes its contact problem
     * (condensed) and returns the sentence saying where; "" in a trial of
     * strength reduction or without the condensed formulation.
     */
    std::string
    write_failed_problem(const unsigned int k, const double time) const;

    Parameters<dim>                         &parameters;
    ConditionalOStream                      &pcout;
    TimerOutput                              timer;
    std::vector<std::unique_ptr<Block<dim>>> blocks;
    /**
     * The blocks present and the pairs (indices into the pairs of the
     * whole model) from stage first_stage on, until the next
     * configuration's, with their contact solver and water.
     */
    struct Configuration
    {
      unsigned int                        first_stage = 0;
      std::vector<bool>                   present;
      std::vector<unsigned int>           pairs;
      std::unique_ptr<ContactSolver<dim>> solver;
      std::unique_ptr<JointWater<dim>>    water;
    };
    std::vector<Configuration> configurations;
    unsigned int               active_configuration = 0;
    /**
     * The forces that the pairs of a removed block exerted on a block that
     * stays (its DoFs and forces), released linearly from full at start
     * to 0 at end, the removing stage's times.
     */
    struct ReleasedForces
    {
      unsigned int                         block = 0;
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  forces;
      double                               start = 0., end = 1.;
    };
    std::vector<ReleasedForces> released;

    /**
     * switch_configuration(): the forces of the pairs of @p earlier that
     * end at stage @p s because it removes one of their blocks, as
     * released forces on the blocks that stay.
     */
    void
    release_removed_pairs(const Configuration &earlier,
                          const Configuration &next,
                          const unsigned int   s);

    /**
     * make_configurations(): every floating block of @p configuration
     * reaches a supported block through its pairs.
     */
    void
    check_configuration_held(const std::vector<ContactPair<dim>> &pairs,
                             const Configuration &configuration) const;

    /**
     * make_configurations(): the blocks of an interface that the stage of
     * @p configuration switches on are there.
     */
    void
    check_switched_on(const std::vector<ContactPair<dim>> &pairs,
                      const Configuration                 &configuration) const;

    /**
     * switch_configuration(): a line where the pairs of an interface
     * switched on now begin with the blocks overlapping.
     */
    void
    warn_of_overlap(const Configuration             &earlier,
                    const Configuration             &next,
                    const std::vector<unsigned int> &earlier_pair) const;

    /** The gap of every pair of the model as the mesh gives it. */
    std::vector<double> mesh_gaps;

    /**
     * solve_pass(): what is left at @p time of the forces released on
     * block @p b.
     */
    void
    add_released_forces(const unsigned int b, const double time);
    /** The contact solver of the present stage (nullptr: no interfaces). */
    ContactSolver<dim> *contact = nullptr;
    /** Formulation "both": the monolithic solve beside the condensed one. */
    std::unique_ptr<ContactSolver<dim>> reference;
    /** VTU/PVD of the blocks and of the pairs (with VTU output on). */
    std::unique_ptr<OutputWriter> writer;
    std::unique_ptr<OutputWriter> pair_writer;

    /**
     * Wall time of the work of each formulation alone (not the mesh, the
     * load vectors or the output, which both share): condensed = block
     * factorisation, flexibilities, load responses, contact iterations,
     * field recovery; monolithic = its assembly and contact iterations
     * (one sparse LU each) and field recovery.
     */
    double condensed_seconds  = 0.;
    double monolithic_seconds = 0.;

    /** Water pressure in the joints, if any joint is wet. */
    JointWater<dim> *water = nullptr;

    /** A trial of strength reduction: nothing printed or written. */
    bool trial_run = false;

    /** Steps in which Newton gave way to the initial-stress method. */
    unsigned int newton_suspensions = 0;

    /** 'Formulation = both': the condensed against the monolithic. */
    FormulationComparison comparison;
    double                last_contact_seconds = 0.;
    /** The contact time of all passes and steps of this increment. */
    double      increment_contact_seconds = 0.;
    double      last_reference_seconds    = 0.;
    std::string summary_csv;
    /** The last increment whose results are on disk (none yet: -1). */
    int last_written_increment = -1;
  };
} // namespace mbfem

#endif

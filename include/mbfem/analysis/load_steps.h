#ifndef mbfem_analysis_load_steps_h
#define mbfem_analysis_load_steps_h

#include <mbfem/analysis/model.h>
#include <mbfem/analysis/run_report.h>
#include <mbfem/analysis/stage_sequence.h>

namespace mbfem
{
  /**
   * One load increment of the present configuration, solved: every block's
   * load and (condensed) its response to it, the contact iteration (and
   * the monolithic reference), the fields; repeated while the plastic
   * strain settles (the initial-stress method, or Newton's with the
   * blocks' tangents); retried in halved steps where it fails and 'Load
   * history/Maximum step halvings' allows; ended with the statics
   * certificate's verdict where it fails for good.
   */
  template <int dim>
  class LoadSteps
  {
  public:
    LoadSteps(Model<dim>           &model,
              StageSequence<dim>   &stages,
              const RunReport<dim> &report);

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
     * Under mpirun, that every rank's contact iteration took the same
     * states (it must: the same code on the same data); otherwise a clear
     * error rather than ranks that wait for each other.
     */
    void
    check_ranks_agree() const;

  private:
    /**
     * The message that ends the run where an increment failed for good:
     * its @p first_failure (at the increment's own size), the @p halvings
     * tried, and where the earlier results are.
     */
    std::string
    final_message(const std::string &first_failure,
                  const unsigned int halvings) const;

    /**
     * After increment @p k converged: if every pair of some floating
     * block slips or is open, runs the statics certificate and, if no
     * admissible forces exist, ends the run (ExcNoEquilibrium).
     */
    void
    certify_sliding_blocks(const unsigned int k, const double time) const;

    /**
     * Under mpirun, each block's solution from its owner to every rank,
     * after all ranks solved theirs (Block::share_solution()).
     */
    void
    share_solutions();

    /** Accepts a step short of the increment's end as converged. */
    void
    commit_step();

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

    Model<dim>           &model;
    StageSequence<dim>   &stages;
    const RunReport<dim> &report;
  };
} // namespace mbfem

#endif

#ifndef mbfem_analysis_load_history_h
#define mbfem_analysis_load_history_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * Pseudo-time of the quasi-static load path. Loads and prescribed
   * displacements are functions of t; t runs from 0 to "End time" in equal
   * increments. With friction the answer depends on the path (paper,
   * eq. 15), so the increments are part of the model, not of the solver.
   */
  struct LoadHistory
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Pseudo-time at the end of increment @p k (k = 1..n_increments). */
    double
    time(const unsigned int k) const;

    /**
     * A stage of the load history ('Stages'): from the end of the stage
     * before (t = 0 for the first) to end_time in n_increments equal
     * increments.
     */
    struct Stage
    {
      std::string  name;
      double       end_time     = 1.;
      unsigned int n_increments = 1;
      /** Material ids of the blocks this stage adds ('Added blocks'). */
      std::vector<unsigned int> added_blocks;
      /** Material ids of the blocks this stage removes ('Removed blocks'). */
      std::vector<unsigned int> removed_blocks;
      /**
       * Interfaces this stage switches on ('Interfaces switched on'):
       * numbers of 'Contact/Interfaces' entries, from 1.
       */
      std::vector<unsigned int> interfaces_on;
    };

    /** Whether 'Stages' declared any (else one stage, unnamed). */
    bool
    has_stages() const
    {
      return !stages.empty();
    }

    /** The stage (index into stages) that increment @p k belongs to. */
    unsigned int
    stage(const unsigned int k) const;

    /** Whether increment @p k is the first of its stage. */
    bool
    starts_stage(const unsigned int k) const;

    /**
     * The stage that adds the block of material id @p id, or
     * numbers::invalid_unsigned_int for a block there from the start.
     */
    unsigned int
    stage_adding_block(const unsigned int id) const;

    /** The stage that removes the block of material id @p id, as above. */
    unsigned int
    stage_removing_block(const unsigned int id) const;

    /** The stage that switches interface @p number (from 1) on, as above. */
    unsigned int
    stage_switching_on(const unsigned int number) const;

    /**
     * Whether some stage adds or removes a block or switches an interface
     * on.
     */
    bool
    changes_model() const;

    /** Start and end time of stage @p s. */
    std::pair<double, double>
    stage_times(const unsigned int s) const;

    /** The declared stages, in order; empty without 'Stages'. */
    std::vector<Stage> stages;

    unsigned int n_increments = 1;
    double       end_time     = 1.;
    /**
     * How often an increment that fails (its contact states cycle, or its
     * plastic iteration does not converge) may be retried in steps of half
     * the size, each step committed as if it were an increment (friction
     * and plasticity follow the finer path); results are written at the
     * increments only.
     */
    unsigned int max_halvings = 0;

  private:
    /** 'Stages': sets stages, n_increments and end_time. */
    void
    parse_stages(const std::string &text);

    /**
     * 'Added blocks' or 'Interfaces switched on' (@p entry): 'STAGE: N,
     * N; ...' into the named stages' @p ids.
     */
    void
    parse_stage_lists(const std::string        &text,
                      const std::string        &entry,
                      std::vector<unsigned int> Stage::*ids);
  };
} // namespace mbfem

#endif

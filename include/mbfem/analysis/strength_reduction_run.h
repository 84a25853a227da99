#ifndef mbfem_analysis_strength_reduction_run_h
#define mbfem_analysis_strength_reduction_run_h

#include <mbfem/analysis/model.h>
#include <mbfem/analysis/stage_sequence.h>
#include <mbfem/analysis/strength_reduction.h>

#include <functional>

namespace mbfem
{
  /**
   * 'Mode = strength reduction' on a model (issue 28): the factor of safety
   * by trials of the whole load history at reduced joint strengths, on the
   * same blocks, factorisations and flexibilities; then the load history at
   * the factor found, with output, and the table of the trials. The search
   * itself is StrengthReduction, which knows nothing of blocks; the load
   * history is the caller's (MultiBodyProblem::do_increment()).
   */
  template <int dim>
  class StrengthReductionRun
  {
  public:
    /**
     * @p do_increment solves, prints and writes one increment (silent and
     * without files while Model::trial_run), @p run_load_history every
     * increment from the start.
     */
    StrengthReductionRun(Model<dim>                              &model,
                         StageSequence<dim>                      &stages,
                         const std::function<void(unsigned int)> &do_increment,
                         const std::function<void()> &run_load_history);

    /** The search and the final run; @p setup_seconds for the timing line. */
    void
    run(const double setup_seconds);

    /**
     * One trial: the load history from the start at the joints' strengths
     * divided by @p factor, silent and without output; with
     * @p statics_bound the certificate's strength factor after every
     * increment. (Also each sample's search of 'Mode = reliability'.)
     */
    StrengthTrial
    run_trial(const double factor, const bool statics_bound);

  private:
    /**
     * run_trial(): the statics certificate (every pair unbroken) after an
     * increment into @p trial's statics bound, and at the @p last one the
     * limit equilibrium along its mechanism.
     */
    void
    measure_statics(StrengthTrial &trial, const bool last) const;

    Model<dim>                             &model;
    StageSequence<dim>                     &stages;
    const std::function<void(unsigned int)> do_increment;
    const std::function<void()>             run_load_history;
  };
} // namespace mbfem

#endif

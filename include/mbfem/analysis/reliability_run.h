#ifndef mbfem_analysis_reliability_run_h
#define mbfem_analysis_reliability_run_h

#include <mbfem/analysis/model.h>
#include <mbfem/analysis/reliability.h>
#include <mbfem/analysis/stage_sequence.h>
#include <mbfem/analysis/strength_reduction_run.h>

#include <limits>
#include <string>
#include <vector>

namespace mbfem
{
  /** What one sample of 'Mode = reliability' gave. */
  struct ReliabilitySample
  {
    enum class Verdict : unsigned char
    {
      /** The load history at the sample's strengths (F = 1) converged. */
      stands,
      /** At F = 1 statics proves there is no equilibrium (exit code 2/4). */
      fails,
      /** At F = 1 the state iteration gave up with forces admissible. */
      gave_up
    };

    Verdict verdict = Verdict::stands;
    /** Its factor of safety (NaN with 'stands at F = 1', or no search). */
    double factor = std::numeric_limits<double>::quiet_NaN();
    /** The upper end of the search's final bracket (inf: none). */
    double upper = std::numeric_limits<double>::infinity();
    /** Load histories run, and how many of them gave up (exit code 3). */
    unsigned int trials = 0, trials_gave_up = 0;
    double       seconds = 0.;
  };

  /**
   * 'Mode = reliability' on a model (issue 63): samples of the joints'
   * strengths drawn by OpenTURNS (draw_samples()), each run on the one
   * set-up (blocks, factorisations and flexibilities do not depend on
   * strength): its factor of safety by strength reduction, or whether it
   * stands at F = 1. The verdict of a sample is its load history at F = 1,
   * the first trial of the search. Then the estimates: mean and standard
   * deviation of F, P(F < 1) with its interval, the reliability index; a
   * CSV line per sample and a summary file.
   */
  template <int dim>
  class ReliabilityRun
  {
  public:
    ReliabilityRun(Model<dim>                &model,
                   StageSequence<dim>        &stages,
                   StrengthReductionRun<dim> &strength_reduction);

    /** The samples and the estimates; @p setup_seconds for the timing. */
    void
    run(const double setup_seconds);

  private:
    /** Every variable sets some pair: its set or interface exists. */
    void
    check_targets();

    /** The sample's strengths into every pair's nominal law. */
    void
    apply(const std::vector<double> &values);

    /** One sample on the set-up, silent. */
    ReliabilitySample
    solve_sample();

    /** The CSV line of sample @p i. */
    std::string
    csv_line(const unsigned int         i,
             const std::vector<double> &values,
             const ReliabilitySample   &sample) const;

    /** The samples and their estimates; a CSV line each into @p csv. */
    std::string
    run_samples(const ReliabilitySamples &values,
                const std::string        &base,
                std::string              &csv);

    /** FORM on the limit state F - 1; a CSV line per evaluation. */
    std::string
    run_form_method(const std::string &base, std::string &csv);

    /** The estimates, for the screen and the summary file. */
    std::string
    summary(const std::vector<ReliabilitySample> &samples) const;

    Model<dim>                  &model;
    StageSequence<dim>          &stages;
    StrengthReductionRun<dim>   &strength_reduction;
    const ReliabilityParameters &parameters;
  };
} // namespace mbfem

#endif

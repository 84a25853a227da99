#ifndef mbfem_analysis_run_report_h
#define mbfem_analysis_run_report_h

#include <mbfem/analysis/formulation_comparison.h>
#include <mbfem/analysis/model.h>
#include <mbfem/analysis/stage_sequence.h>
#include <mbfem/output/output.h>
#include <mbfem/output/screen_detail.h>

#include <memory>
#include <string>

namespace mbfem
{
  /**
   * What a run shows and writes: the screen (its summary lines and, for a
   * model of many blocks, the detail files of ScreenDetail), the VTU/PVD
   * files of the blocks and the pairs, the pairs' CSV files, the summary
   * CSV, the contact problems, the comparison of the formulations, and what
   * a failure message says of the files on disk. Silent in a trial of
   * strength reduction (Model::trial_run), as its callers see to.
   */
  template <int dim>
  class RunReport
  {
  public:
    RunReport(Model<dim> &model, const StageSequence<dim> &stages);

    /**
     * The blocks' sizes, materials and free rigid-body modes (on the screen
     * or in the blocks' detail file: ScreenDetail).
     */
    void
    print_blocks() const;

    /** The screen line of the contact formulation(s) of @p n_pairs pairs. */
    void
    print_formulation(const unsigned int n_pairs) const;

    /** The output folder, and the PVD writers of blocks and pairs. */
    void
    make_writers();

    /** With 'Load history/Stages': a line where a stage begins. */
    void
    print_stage(const unsigned int k) const;

    void
    print_increment(const unsigned int k,
                    const double       time,
                    const unsigned int iterations) const;

    void
    print_plasticity(const unsigned int   plastic_iterations,
                     const PlasticUpdate &plastic_update) const;

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
     * Formulation "both": the monolithic reference against the condensed
     * solve of this increment, pair by pair; prints and records it.
     */
    void
    compare_formulations();

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
     * rank its own), indexed with @p pair_file in the PVD files; from now
     * on a failure says that the results up to @p k are on disk.
     */
    void
    write_blocks(const unsigned int k,
                 const double       time,
                 const std::string &pair_file);

    /**
     * What a failure message says of the files on disk: where the results
     * of the increments that converged are, or that none was written.
     */
    std::string
    earlier_results() const;

    /**
     * An increment that ends with exit code 3: writes its contact problem
     * (condensed) and returns the sentence saying where; "" in a trial of
     * strength reduction or without the condensed formulation.
     */
    std::string
    write_failed_problem(const unsigned int k, const double time) const;

    /** What a finished run prints at its end. */
    void
    print_run_summary();

  private:
    /** The screen's summary of many blocks: cells, DoFs, floating, sizes. */
    void
    print_block_counts() const;

    /**
     * The resultant force of every interface at increment @p k (on the
     * screen or in the interfaces' detail file).
     */
    void
    print_resultants(const unsigned int k, const double time) const;

    void
    print_errors(const double time) const;

    void
    print_formulation_times() const;

    /** The comment and the column names of <base>-summary.csv. */
    std::string
    summary_header() const;

    /** One line per increment in <base>-summary.csv (rewritten whole). */
    void
    write_summary(const unsigned int k,
                  const double       time,
                  const unsigned int iterations,
                  const unsigned int reference_iterations);

    /** Output/<base>-<prefix>problem-<k>: the stem of a contact problem. */
    std::string
    problem_stem(const unsigned int k, const std::string &prefix) const;

    Model<dim>               &model;
    const StageSequence<dim> &stages;

    /** Where print_blocks() and the interfaces' detail go. */
    mutable std::unique_ptr<ScreenDetail> screen;
    /** VTU/PVD of the blocks and of the pairs (with VTU output on). */
    std::unique_ptr<OutputWriter> writer;
    std::unique_ptr<OutputWriter> pair_writer;
    /** 'Formulation = both': the condensed against the monolithic. */
    FormulationComparison comparison;
    std::string           summary_csv;
    /** The last increment whose results are on disk (none yet: -1). */
    int last_written_increment = -1;
  };
} // namespace mbfem

#endif

#ifndef mbfem_analysis_strength_reduction_h
#define mbfem_analysis_strength_reduction_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /** Subsection "Strength reduction" (Mode = strength reduction). */
  struct StrengthReductionParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Relative width of the final bracket: (F_hi - F_lo) / F_lo. */
    double tolerance = 1e-3;
    /** Whether sigma_t is divided by F too (c and tan(phi) always are). */
    bool reduce_tensile_strength = true;
    /** Load histories at most, the final run with output not counted. */
    unsigned int max_trials = 40;
    /**
     * For verification: F of a closed form (limit equilibrium), to print
     * F's difference from it and whether the bracket holds it; 0: none.
     */
    double      closed_form = 0.;
    std::string closed_form_text;
  };



  /** One load history at the joints' strengths divided by F. */
  struct StrengthTrial
  {
    enum class Outcome : unsigned char
    {
      converged,
      /** Exit code 2 of a plain run: certified by statics. */
      no_equilibrium,
      /** Exit code 4: none along the mechanism of the statics limit. */
      none_along_mechanism,
      /** Exit code 3: the state iteration failed, forces exist. */
      not_converged
    };

    double  factor  = 1.;
    Outcome outcome = Outcome::converged;
    /**
     * No equilibrium only once the joints its load path broke lost their
     * strength (Exceptions::ExcNoEquilibriumAfterBreaking): rigid-block
     * statics with them whole admits forces.
     */
    bool after_breaking = false;
    /** Increments that converged, of how many. */
    unsigned int increments = 0, n_increments = 0;
    /** The state methods that concluded its increments ("fast", ...). */
    std::string  methods;
    unsigned int iterations = 0;
    double       seconds    = 0.;
    /** At the last increment that converged. */
    double largest_displacement = 0., largest_slip = 0.;
    /**
     * The statics certificate's strength factor, smallest over the
     * increments, in nominal strengths (only measured by the first trial;
     * NaN if not, or if unbounded).
     */
    double statics_bound = std::numeric_limits<double>::quiet_NaN();
    /**
     * Limit equilibrium along the certificate's mechanism at the last
     * increment tried (Hoek and Bray's wedge factor, Goodman and Bray's
     * toppling), in nominal strengths: the first guess below the statics
     * bound (first trial only; NaN if none).
     */
    double mechanism_factor = std::numeric_limits<double>::quiet_NaN();

    bool
    converged() const
    {
      return outcome == Outcome::converged;
    }
  };

  std::string
  to_string(const StrengthTrial::Outcome outcome);



  /**
   * The factor of safety by strength reduction (design.md, section 4): the
   * largest F at which the load history at tan(phi) / F and c / F (and
   * sigma_t / F) still converges, bracketed and bisected. The search knows
   * nothing of blocks: each trial is a callback that runs a load history
   * (MultiBodyProblem reuses its factorisations and flexibilities). The
   * first trial is F = 1; its statics bound F_LP (an upper bound: beyond it
   * no contact forces hold the blocks) gives the first bracket
   * [F_LP (1 - tol/2), F_LP (1 + tol/4)], which for one block sliding on
   * one plane is the answer; where limit equilibrium along the LP's
   * mechanism gives less (a wedge), the same bracket around that factor
   * comes first; below them the search steps down geometrically and
   * bisects.
   */
  class StrengthReduction
  {
  public:
    using RunTrial = std::function<StrengthTrial(double)>;

    /**
     * Prints the table to @p out and rewrites @p csv_file after every
     * trial (so that a search that fails leaves its trials on disk).
     */
    StrengthReduction(const StrengthReductionParameters &parameters,
                      std::ostream                      &out,
                      const bool                         test_mode,
                      const std::string                 &csv_file = "");

    /**
     * Runs trials until the bracket is within the tolerance; returns the
     * largest F that converged. Throws if every F down to 0.001 fails
     * (ExcNoEquilibrium where statics proved the last one) or the trials
     * run out.
     */
    double
    search(const RunTrial &run_trial);

    const std::vector<StrengthTrial> &
    trials() const;

    /** Lower and upper end of the final bracket (upper: inf if none). */
    double
    lower() const;
    double
    upper() const;
    /** F_LP of the first trial, NaN if none. */
    double
    statics_bound() const;

    /** The first trial's mechanism factor, NaN if none. */
    double
    mechanism_factor() const;

    /** 'factor of safety = F (bracket [..], statics bound ..)'. */
    std::string
    result_line() const;

    /**
     * With a closed form: 'closed form F_cf = ..: F differs by ..%, the
     * bracket holds it: yes/no'; empty without.
     */
    std::string
    closed_form_line() const;

    /** The trials as CSV (one line each), for plotting. */
    void
    write_csv(const std::string &filename) const;

  private:
    /** Every F down to 0.001 failed: throws, saying how. */
    [[noreturn]] void
    fail_everywhere() const;

    /** Runs and records one trial, and prints its line of the table. */
    void
    try_factor(const RunTrial &run_trial, const double factor);

    /** The next factor to try, or 0 once the bracket is narrow enough. */
    double
    next_factor() const;

    void
    print_header() const;

    void
    print_trial(const StrengthTrial &trial) const;

    const StrengthReductionParameters &parameters;
    std::ostream                      &out;
    const bool                         test_mode;
    const std::string                  csv_file;
    std::vector<StrengthTrial>         trial_list;
    double                             lo = 0.;
    double hi = std::numeric_limits<double>::infinity();
  };
} // namespace mbfem

#endif

#ifndef mbfem_analysis_reliability_h
#define mbfem_analysis_reliability_h

#include <mbfem/interface/joint_law.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * One random variable of 'Mode = reliability': which joints' strength it
   * sets, and its distribution as engineers quote it (mean and standard
   * deviation or coefficient of variation, bounds).
   */
  struct RandomVariable
  {
    enum class Quantity : unsigned char
    {
      friction_angle,
      friction_coefficient,
      cohesion,
      tensile_strength,
      /** A named constant of the functions' 'Function constants'. */
      constant
    };

    std::string name;
    /** 'all', 'set NAME' or 'interface K', as written. */
    std::string target;
    /** The pairs it sets: every pair, one joint set's, or one interface's. */
    bool        all = false;
    std::string set_name;
    /** 0-based; numbers::invalid_unsigned_int unless 'interface K'. */
    unsigned int interface = static_cast<unsigned int>(-1);
    Quantity     quantity  = Quantity::friction_angle;
    /** The constant's name (Quantity::constant). */
    std::string constant;
    /** normal, lognormal, uniform, truncated normal, beta, triangular. */
    std::string distribution;
    /** Its numbers by key: mean, sd, cov, min, max, mode, alpha, beta. */
    std::map<std::string, double> numbers;

    /** Whether it sets the law of a pair of interface @p k in set @p set. */
    bool
    applies_to(const unsigned int k, const std::string &set) const;

    /** Sets the quantity of @p law to @p value. */
    void
    apply(const double value, JointLaw &law) const;

    /** "friction angle" etc. */
    std::string
    quantity_name() const;
  };

  /** Subsection "Reliability" (Mode = reliability). */
  struct ReliabilityParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    std::vector<RandomVariable> variables;
    /** Spearman's rank correlation of pairs of variables (indices). */
    std::map<std::pair<unsigned int, unsigned int>, double> rank_correlation;
    /** Monte Carlo, Latin hypercube, Sobol. */
    std::string  sampling  = "Monte Carlo";
    unsigned int n_samples = 100;
    unsigned int seed      = 1;
    /** Each sample's factor of safety, or only whether it stands at F = 1. */
    bool factor_of_safety = true;
    /** 'sampling', or 'FORM': the design point of g = F - 1. */
    std::string method = "sampling";
  };

  /** The values drawn: one row per sample, one column per variable. */
  using ReliabilitySamples = std::vector<std::vector<double>>;

  /**
   * Draws the samples of @p parameters with OpenTURNS: the marginals and
   * a Gaussian copula of the rank correlations (a ComposedDistribution),
   * sampled in the standard normal space by Monte Carlo, a Latin hypercube
   * or Sobol's sequence and mapped back by the distribution's inverse
   * iso-probabilistic (Nataf) transformation, so that the three samplings
   * treat a correlation alike. Throws, naming the variable or the entry,
   * for impossible parameters or a correlation that is not positive
   * definite, and for a range a joint law cannot take (a friction angle
   * that can reach 0 or 90 degrees, a negative strength).
   */
  ReliabilitySamples
  draw_samples(const ReliabilityParameters &parameters);

  /** What FORM found: the design point of F - 1 = 0 nearest the mean. */
  struct FormResult
  {
    /** Hasofer and Lind's index and Phi(-beta) (the event's side). */
    double beta = 0., probability = 0.;
    /** The design point in the variables' units. */
    std::vector<double> design_point;
    /** The importance factors (OpenTURNS', elliptical: squares of alpha). */
    std::vector<double> importance;
    unsigned int        evaluations = 0;
  };

  /**
   * FORM with OpenTURNS (Cobyla for the nearest point in the standard
   * space, from the mean): @p factor maps the variables' values to the
   * model's factor of safety, each call one strength-reduction search.
   */
  FormResult
  run_form(const ReliabilityParameters                              &parameters,
           const std::function<double(const std::vector<double> &)> &factor);

  /** The estimates of P(F < 1) from a count of failures. */
  struct FailureProbability
  {
    double estimate = 0.;
    /** Clopper and Pearson's 95 % interval. */
    double lower = 0., upper = 1.;
    /** -Phi^-1(estimate); +-inf at 0 and 1. */
    double beta = 0.;
  };

  /**
   * P(F < 1) = @p failures / @p samples with Clopper and Pearson's exact
   * binomial 95 % interval (OpenTURNS' Beta quantiles) and the reliability
   * index.
   */
  FailureProbability
  failure_probability(const unsigned int failures, const unsigned int samples);
} // namespace mbfem

#endif

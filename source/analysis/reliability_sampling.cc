// 'Mode = reliability' (issue 63): the distributions, the copula, the
// experiments and the estimates, all OpenTURNS' (Debian's libopenturns-dev);
// mbfem writes no sampler or distribution of its own. The one file that
// includes OpenTURNS, whose headers are heavy.

#include <mbfem/analysis/reliability.h>

#include <deal.II/base/exceptions.h>

#include <openturns/Beta.hxx>
#include <openturns/Cobyla.hxx>
#include <openturns/ComposedDistribution.hxx>
#include <openturns/CompositeRandomVector.hxx>
#include <openturns/CorrelationMatrix.hxx>
#include <openturns/DistFunc.hxx>
#include <openturns/EvaluationImplementation.hxx>
#include <openturns/FORM.hxx>
#include <openturns/LHSExperiment.hxx>
#include <openturns/Less.hxx>
#include <openturns/LogNormalMuSigma.hxx>
#include <openturns/LowDiscrepancyExperiment.hxx>
#include <openturns/Normal.hxx>
#include <openturns/NormalCopula.hxx>
#include <openturns/RandomGenerator.hxx>
#include <openturns/SobolSequence.hxx>
#include <openturns/ThresholdEvent.hxx>
#include <openturns/Triangular.hxx>
#include <openturns/TruncatedNormal.hxx>
#include <openturns/Uniform.hxx>

#include <cmath>
#include <limits>
#include <set>

namespace mbfem
{
  namespace
  {
    std::string
    where(const RandomVariable &v)
    {
      return "Reliability/Random variables, the variable '" + v.name + "' (" +
             v.distribution + ")";
    }

    /** Number @p key of @p v, which its distribution needs. */
    double
    number(const RandomVariable &v, const std::string &key)
    {
      const auto it = v.numbers.find(key);
      AssertThrow(it != v.numbers.end(),
                  ExcMessage(where(v) + ": needs '" + key + "'."));
      return it->second;
    }

    /** The standard deviation: 'sd', or 'cov' times |mean|. */
    double
    deviation(const RandomVariable &v)
    {
      AssertThrow(v.numbers.count("sd") + v.numbers.count("cov") == 1,
                  ExcMessage(where(v) + ": give 'sd' or 'cov' (one of them)."));
      const double sd = v.numbers.count("sd") ?
                          v.numbers.at("sd") :
                          v.numbers.at("cov") * std::abs(number(v, "mean"));
      AssertThrow(sd > 0.,
                  ExcMessage(where(v) + ": the standard deviation must be "
                                        "positive."));
      return sd;
    }

    /** No key the distribution does not read. */
    void
    check_keys(const RandomVariable &v, const std::set<std::string> &known)
    {
      for (const auto &[key, value] : v.numbers)
        AssertThrow(known.count(key) > 0,
                    ExcMessage(where(v) + ": '" + key +
                               "' is not a number of this distribution."));
    }

    OT::Distribution
    marginal(const RandomVariable &v)
    {
      const std::string &d = v.distribution;
      if (d == "normal" || d == "lognormal")
        {
          check_keys(v, {"mean", "sd", "cov"});
          const double mean = number(v, "mean"), sd = deviation(v);
          if (d == "normal")
            return OT::Normal(mean, sd);
          AssertThrow(mean > 0.,
                      ExcMessage(where(v) + ": a lognormal mean is positive."));
          return OT::LogNormalMuSigma(mean, sd, 0.).getDistribution();
        }
      if (d == "truncated normal")
        {
          check_keys(v, {"mean", "sd", "cov", "min", "max"});
          return OT::TruncatedNormal(number(v, "mean"),
                                     deviation(v),
                                     number(v, "min"),
                                     number(v, "max"));
        }
      if (d == "uniform")
        {
          check_keys(v, {"min", "max"});
          return OT::Uniform(number(v, "min"), number(v, "max"));
        }
      if (d == "beta")
        {
          check_keys(v, {"alpha", "beta", "min", "max"});
          return OT::Beta(number(v, "alpha"),
                          number(v, "beta"),
                          number(v, "min"),
                          number(v, "max"));
        }
      if (d == "triangular")
        {
          check_keys(v, {"min", "mode", "max"});
          return OT::Triangular(number(v, "min"),
                                number(v, "mode"),
                                number(v, "max"));
        }
      AssertThrow(false,
                  ExcMessage(where(v) +
                             ": unknown distribution; the distributions are "
                             "normal, lognormal, uniform, truncated normal, "
                             "beta, triangular."));
      return OT::Normal();
    }

    /** The values a joint law can take: an angle in [0, 90), else >= 0. */
    void
    check_range(const RandomVariable &v, const OT::Distribution &distribution)
    {
      if (v.quantity == RandomVariable::Quantity::constant)
        return; // any value: the functions say what it means
      const OT::Interval range         = distribution.getRange();
      const bool         bounded_below = range.getFiniteLowerBound()[0];
      const bool         bounded_above = range.getFiniteUpperBound()[0];
      const double       lower         = range.getLowerBound()[0];
      const double       upper         = range.getUpperBound()[0];
      const auto         reach =
        (bounded_below ? std::to_string(lower) : std::string("-inf")) + " to " +
        (bounded_above ? std::to_string(upper) : std::string("+inf"));
      if (v.quantity == RandomVariable::Quantity::friction_angle)
        {
          AssertThrow(bounded_below && bounded_above && lower >= 0. &&
                        upper < 90.,
                      ExcMessage(where(v) +
                                 ": a friction angle must stay within [0, "
                                 "90) degrees, but this distribution "
                                 "reaches " +
                                 reach +
                                 ": use a bounded one (truncated normal, "
                                 "uniform, beta, triangular)."));
        }
      else
        {
          AssertThrow(bounded_below && lower >= 0.,
                      ExcMessage(where(v) + ": a " + v.quantity_name() +
                                 " cannot be negative, but this "
                                 "distribution reaches " +
                                 reach +
                                 ": use a lognormal, or a truncated normal "
                                 "with min 0 or more."));
        }
    }

    /** The marginals with a Gaussian copula of the rank correlations. */
    OT::ComposedDistribution
    joint_distribution(const ReliabilityParameters &parameters)
    {
      const unsigned int               n = parameters.variables.size();
      OT::Collection<OT::Distribution> marginals;
      for (const auto &v : parameters.variables)
        {
          try
            {
              marginals.add(marginal(v));
            }
          catch (const OT::Exception &e)
            {
              AssertThrow(false, ExcMessage(where(v) + ": " + e.what()));
            }
          check_range(v, marginals[marginals.getSize() - 1]);
        }
      if (parameters.rank_correlation.empty())
        return OT::ComposedDistribution(marginals);
      OT::CorrelationMatrix spearman(n);
      for (const auto &[pair, rho] : parameters.rank_correlation)
        spearman(pair.first, pair.second) = rho;
      try
        {
          return OT::ComposedDistribution(
            marginals,
            OT::NormalCopula(
              OT::NormalCopula::GetCorrelationFromSpearmanCorrelation(
                spearman)));
        }
      catch (const OT::Exception &e)
        {
          AssertThrow(false,
                      ExcMessage("Reliability/Rank correlation: the matrix "
                                 "of the correlations given is not a "
                                 "correlation matrix (positive definite): " +
                                 std::string(e.what())));
        }
      return OT::ComposedDistribution(marginals);
    }
  } // namespace



  ReliabilitySamples
  draw_samples(const ReliabilityParameters &parameters)
  {
    AssertThrow(!parameters.variables.empty(),
                ExcMessage("Mode = reliability needs at least one entry in "
                           "'Reliability/Random variables'."));
    const OT::ComposedDistribution distribution =
      joint_distribution(parameters);
    const unsigned int n = parameters.variables.size();
    const unsigned int N = parameters.n_samples;
    OT::RandomGenerator::SetSeed(parameters.seed);
    const OT::ComposedDistribution standard(
      OT::Collection<OT::Distribution>(n, OT::Normal()));
    OT::Sample u;
    if (parameters.sampling == "Monte Carlo")
      u = standard.getSample(N);
    else if (parameters.sampling == "Latin hypercube")
      u = OT::LHSExperiment(standard, N).generate();
    else
      u = OT::LowDiscrepancyExperiment(OT::SobolSequence(n), standard, N, false)
            .generate();
    const OT::Sample x =
      distribution.getInverseIsoProbabilisticTransformation()(u);
    ReliabilitySamples samples(N, std::vector<double>(n));
    for (unsigned int i = 0; i < N; ++i)
      for (unsigned int j = 0; j < n; ++j)
        samples[i][j] = x(i, j);
    return samples;
  }



  namespace
  {
    /** The limit state g(x) = F(x) - 1 as an OpenTURNS evaluation. */
    class LimitState : public OT::EvaluationImplementation
    {
    public:
      LimitState(
        const std::function<double(const std::vector<double> &)> &factor,
        const unsigned int                                        n,
        unsigned int                                             &calls)
        : factor(factor)
        , n(n)
        , calls(&calls)
      {}

      LimitState *
      clone() const override
      {
        return new LimitState(*this);
      }

      OT::Point
      operator()(const OT::Point &x) const override
      {
        ++*calls;
        return OT::Point(1,
                         factor(std::vector<double>(x.begin(), x.end())) - 1.);
      }

      OT::UnsignedInteger
      getInputDimension() const override
      {
        return n;
      }

      OT::UnsignedInteger
      getOutputDimension() const override
      {
        return 1;
      }

    private:
      std::function<double(const std::vector<double> &)> factor;
      unsigned int                                       n;
      unsigned int                                      *calls;
    };
  } // namespace



  FormResult
  run_form(const ReliabilityParameters                              &parameters,
           const std::function<double(const std::vector<double> &)> &factor)
  {
    const OT::ComposedDistribution distribution =
      joint_distribution(parameters);
    FormResult         result;
    const OT::Function g(
      LimitState(factor, parameters.variables.size(), result.evaluations));
    const OT::RandomVector   x(distribution);
    const OT::ThresholdEvent event(OT::CompositeRandomVector(g, x),
                                   OT::Less(),
                                   0.);
    OT::Cobyla               cobyla;
    // F is found to the strength-reduction search's tolerance (1e-3).
    cobyla.setMaximumEvaluationNumber(200);
    cobyla.setMaximumAbsoluteError(1e-4);
    cobyla.setMaximumConstraintError(1e-5);
    cobyla.setRhoBeg(0.5);
    OT::FORM form(cobyla, event, distribution.getMean());
    form.run();
    const OT::FORMResult found = form.getResult();
    result.beta                = found.getHasoferReliabilityIndex();
    result.probability         = found.getEventProbability();
    for (const double x : found.getPhysicalSpaceDesignPoint())
      result.design_point.push_back(x);
    for (const double f : found.getImportanceFactors())
      result.importance.push_back(f);
    return result;
  }



  FailureProbability
  failure_probability(const unsigned int failures, const unsigned int samples)
  {
    AssertThrow(samples > 0 && failures <= samples, ExcInternalError());
    FailureProbability p;
    const double       f = failures, n = samples;
    p.estimate       = f / n;
    p.lower          = (failures == 0 ?
                          0. :
                          OT::Beta(f, n - f + 1., 0., 1.).computeQuantile(0.025)[0]);
    p.upper          = (failures == samples ?
                          1. :
                          OT::Beta(f + 1., n - f, 0., 1.).computeQuantile(0.975)[0]);
    const double inf = std::numeric_limits<double>::infinity();
    p.beta           = (failures == 0       ? inf :
                        failures == samples ? -inf :
                                              -OT::DistFunc::qNormal(p.estimate));
    return p;
  }
} // namespace mbfem

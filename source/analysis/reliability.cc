// 'Mode = reliability' (issue 63): the random variables and how they are
// read. The drawing of samples and the estimates are OpenTURNS'
// (reliability_sampling.cc, the one file that includes it).

#include <mbfem/analysis/reliability.h>
#include <mbfem/base/text_input.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <set>
#include <sstream>

namespace mbfem
{
  bool
  RandomVariable::applies_to(const unsigned int k, const std::string &set) const
  {
    return all || (!set_name.empty() && set == set_name) || k == interface;
  }



  void
  RandomVariable::apply(const double value, JointLaw &law) const
  {
    switch (quantity)
      {
        case Quantity::friction_angle:
          law.friction_coefficient = std::tan(value * JointLaw::pi / 180.);
          break;
        case Quantity::friction_coefficient:
          law.friction_coefficient = value;
          break;
        case Quantity::cohesion:
          law.cohesion = value;
          break;
        case Quantity::tensile_strength:
          law.tensile_strength = value;
          break;
        case Quantity::constant:
          break; // not a joint's: ReliabilityRun sets the functions
      }
  }



  std::string
  RandomVariable::quantity_name() const
  {
    switch (quantity)
      {
        case Quantity::friction_angle:
          return "friction angle";
        case Quantity::friction_coefficient:
          return "friction coefficient";
        case Quantity::cohesion:
          return "cohesion";
        case Quantity::constant:
          return "constant";
        default:
          return "tensile strength";
      }
  }



  void
  ReliabilityParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Reliability");
    {
      prm.declare_entry(
        "Random variables",
        "",
        Patterns::Anything(),
        "For Mode = reliability: the random strengths, separated by ';', "
        "each 'name: target quantity, distribution', e.g. 'phi: set bedding "
        "friction angle, truncated normal mean 30 sd 3 min 15 max 45; c: "
        "all cohesion, lognormal mean 50e3 cov 0.3'. Target: 'all' (every "
        "joint), 'set NAME' (a joint set of Contact/Joint sets) or "
        "'interface K' (the K-th interface of the screen's list), or "
        "'constant NAME' alone: a constant of the functions' 'Function "
        "constants' (in every function that names it, e.g. a reservoir "
        "level in the traction and the water pressure). Quantity: "
        "friction angle (degrees), friction coefficient (tan(phi)), "
        "cohesion, tensile strength; where two variables set the same "
        "quantity of a joint, the later one does. Distributions (OpenTURNS): "
        "normal (mean, sd or cov), lognormal (mean, sd or cov), uniform "
        "(min, max), truncated normal (mean, sd or cov of the normal before "
        "truncation, min, max), beta (alpha, beta, min, max), triangular "
        "(min, mode, max). A friction angle must lie within (0, 90) and the "
        "other quantities at or above 0 for every value the distribution "
        "can take: a normal friction angle is refused, a truncated one is "
        "not.");
      prm.declare_entry(
        "Rank correlation",
        "",
        Patterns::Anything(),
        "Spearman's rank correlation of pairs of variables, 'name name "
        "value' separated by ';', e.g. 'phi c -0.5' (friction and cohesion "
        "are often negatively correlated); a Gaussian copula carries it. "
        "Pairs not given are independent.");
      prm.declare_entry("Sampling",
                        "Monte Carlo",
                        Patterns::Selection(
                          "Monte Carlo|Latin hypercube|Sobol"),
                        "How the samples are drawn (OpenTURNS): Monte Carlo, "
                        "a Latin hypercube, or Sobol's low-discrepancy "
                        "sequence.");
      prm.declare_entry("Number of samples",
                        "100",
                        Patterns::Integer(1, 1000000),
                        "Samples drawn, each a model with its strengths.");
      prm.declare_entry("Seed",
                        "1",
                        Patterns::Integer(0),
                        "Seed of OpenTURNS' random generator: the same seed "
                        "draws the same samples.");
      prm.declare_entry(
        "Method",
        "sampling",
        Patterns::Selection("sampling|FORM"),
        "'sampling': the samples of 'Sampling' and P(F < 1) counted. "
        "'FORM': the first-order reliability method (OpenTURNS' FORM with "
        "Cobyla): the point of F = 1 nearest the mean in the standard "
        "normal space (the design point), the reliability index beta, "
        "Phi(-beta) and the importance factors; each evaluation one "
        "factor of safety (Answer = factor of safety).");
      prm.declare_entry(
        "Answer",
        "factor of safety",
        Patterns::Selection("factor of safety|stands at F = 1"),
        "Per sample: its factor of safety by strength reduction (subsection "
        "'Strength reduction'), or only whether the load history stands at "
        "the sample's strengths (one load history, cheaper).");
    }
    prm.leave_subsection();
  }



  namespace
  {
    /** The target and quantity of '... target quantity' into @p v. */
    void
    read_target(const std::string &text, RandomVariable &v)
    {
      if (text.rfind("constant ", 0) == 0)
        {
          v.quantity = RandomVariable::Quantity::constant;
          v.constant = Utilities::trim(text.substr(9));
          v.target   = text;
          return;
        }
      const std::vector<std::pair<std::string, RandomVariable::Quantity>>
        quantities = {
          {"friction angle", RandomVariable::Quantity::friction_angle},
          {"friction coefficient",
           RandomVariable::Quantity::friction_coefficient},
          {"cohesion", RandomVariable::Quantity::cohesion},
          {"tensile strength", RandomVariable::Quantity::tensile_strength}};
      bool found = false;
      for (const auto &[name, quantity] : quantities)
        if (text.size() > name.size() &&
            text.compare(text.size() - name.size(), name.size(), name) == 0)
          {
            v.quantity = quantity;
            v.target =
              Utilities::trim(text.substr(0, text.size() - name.size()));
            found = true;
          }
      const std::string where =
        "Reliability/Random variables, the variable '" + v.name + "'";
      AssertThrow(found,
                  ExcMessage(where + ": '" + text +
                             "' does not end with a quantity (friction "
                             "angle, friction coefficient, cohesion, "
                             "tensile strength)."));
      std::istringstream in(v.target);
      std::string        kind, rest;
      in >> kind;
      std::getline(in, rest);
      rest = Utilities::trim(rest);
      if (kind == "all" && rest.empty())
        v.all = true;
      else if (kind == "set" && !rest.empty())
        v.set_name = rest;
      else if (kind == "interface" && !rest.empty())
        {
          const double k = parse_finite_number(rest, where);
          AssertThrow(k >= 1 && k == std::floor(k),
                      ExcMessage(where + ": 'interface " + rest +
                                 "' needs a number from 1."));
          v.interface = static_cast<unsigned int>(k) - 1;
        }
      else
        AssertThrow(false,
                    ExcMessage(where + ": the target '" + v.target +
                               "' is none of 'all', 'set NAME', "
                               "'interface K'."));
    }

    /** The distribution and its numbers of 'name key value ...'. */
    void
    read_distribution(const std::string &text, RandomVariable &v)
    {
      const std::string where =
        "Reliability/Random variables, the variable '" + v.name + "'";
      std::istringstream       in(text);
      std::vector<std::string> words;
      for (std::string w; in >> w;)
        words.push_back(w);
      std::size_t i = 1;
      AssertThrow(!words.empty(),
                  ExcMessage(where + ": no distribution after the ','."));
      v.distribution = words[0];
      if (words[0] == "truncated" && words.size() > 1 && words[1] == "normal")
        v.distribution = "truncated normal", i = 2;
      static const std::set<std::string> keys = {
        "mean", "sd", "cov", "min", "max", "mode", "alpha", "beta"};
      for (; i < words.size(); i += 2)
        {
          AssertThrow(keys.count(words[i]) > 0 && i + 1 < words.size(),
                      ExcMessage(where + ": cannot read '" + text +
                                 "': after the distribution's name come "
                                 "'key value' pairs with the keys mean, sd, "
                                 "cov, min, max, mode, alpha, beta."));
          AssertThrow(v.numbers.count(words[i]) == 0,
                      ExcMessage(where + ": '" + words[i] +
                                 "' is given twice."));
          v.numbers[words[i]] = parse_finite_number(words[i + 1], where);
        }
    }

    RandomVariable
    read_variable(const std::string &entry)
    {
      RandomVariable v;
      const auto     colon = entry.find(':');
      const auto     comma = entry.find(',');
      AssertThrow(colon != std::string::npos && comma != std::string::npos &&
                    colon < comma && colon > 0,
                  ExcMessage("Reliability/Random variables: cannot read '" +
                             entry +
                             "'; write 'name: target quantity, "
                             "distribution key value ...', e.g. 'phi: set "
                             "bedding friction angle, uniform min 25 max "
                             "35'."));
      v.name = Utilities::trim(entry.substr(0, colon));
      read_target(Utilities::trim(entry.substr(colon + 1, comma - colon - 1)),
                  v);
      read_distribution(entry.substr(comma + 1), v);
      return v;
    }
  } // namespace



  void
  ReliabilityParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Reliability");
    {
      variables.clear();
      const std::string text = prm.get("Random variables");
      if (!Utilities::trim(text).empty())
        for (const auto &entry :
             split_list(text, ';', "Reliability/Random variables"))
          {
            variables.push_back(read_variable(entry));
            for (unsigned int i = 0; i + 1 < variables.size(); ++i)
              AssertThrow(variables[i].name != variables.back().name,
                          ExcMessage("Reliability/Random variables: the "
                                     "name '" +
                                     variables.back().name +
                                     "' is given twice."));
          }
      rank_correlation.clear();
      const std::string correlation = prm.get("Rank correlation");
      if (!Utilities::trim(correlation).empty())
        for (const auto &entry :
             split_list(correlation, ';', "Reliability/Rank correlation"))
          {
            std::istringstream in(entry);
            std::string        a, b, value, extra;
            in >> a >> b >> value >> extra;
            const std::string where =
              "Reliability/Rank correlation, '" + entry + "'";
            unsigned int i = variables.size(), j = variables.size();
            for (unsigned int k = 0; k < variables.size(); ++k)
              {
                i = (variables[k].name == a ? k : i);
                j = (variables[k].name == b ? k : j);
              }
            AssertThrow(i < variables.size() && j < variables.size() &&
                          i != j && extra.empty(),
                        ExcMessage(where +
                                   ": write 'name name value' with two "
                                   "different names of Random variables."));
            const double rho = parse_finite_number(value, where);
            AssertThrow(rho > -1. && rho < 1.,
                        ExcMessage(where + ": a correlation lies in (-1, 1)."));
            rank_correlation[{std::min(i, j), std::max(i, j)}] = rho;
          }
      sampling         = prm.get("Sampling");
      n_samples        = prm.get_integer("Number of samples");
      seed             = prm.get_integer("Seed");
      factor_of_safety = (prm.get("Answer") == "factor of safety");
      method           = prm.get("Method");
      AssertThrow(method != "FORM" || factor_of_safety,
                  ExcMessage("Reliability/Method = FORM needs each model's "
                             "factor of safety (its limit state F - 1): set "
                             "'Answer = factor of safety'."));
    }
    prm.leave_subsection();
  }
} // namespace mbfem

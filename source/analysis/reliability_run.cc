// 'Mode = reliability' (issue 63): the samples on one set-up and the
// estimates. The samples themselves are drawn by OpenTURNS
// (reliability_sampling.cc).

#include <mbfem/analysis/parameters.h>
#include <mbfem/analysis/reliability_run.h>
#include <mbfem/base/exceptions.h>
#include <mbfem/base/files.h>
#include <mbfem/block/boundary_conditions.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

namespace mbfem
{
  template <int dim>
  ReliabilityRun<dim>::ReliabilityRun(
    Model<dim>                &model,
    StageSequence<dim>        &stages,
    StrengthReductionRun<dim> &strength_reduction)
    : model(model)
    , stages(stages)
    , strength_reduction(strength_reduction)
    , parameters(model.parameters.reliability)
  {}



  template <int dim>
  void
  ReliabilityRun<dim>::check_targets()
  {
    const auto &contact = model.parameters.contact;
    for (const auto &v : parameters.variables)
      {
        const std::string where =
          "Reliability/Random variables, the variable '" + v.name + "': ";
        if (v.quantity == RandomVariable::Quantity::constant)
          {
            std::set<std::string> known;
            for (const auto &function : parsed_functions())
              for (const auto &[name, value] : function.constants)
                known.insert(name);
            std::string list;
            for (const auto &name : known)
              list += (list.empty() ? "" : ", ") + name;
            AssertThrow(known.count(v.constant) > 0,
                        ExcMessage(where + "no function names the constant '" +
                                   v.constant +
                                   "' in its 'Function "
                                   "constants' (the constants named: " +
                                   (list.empty() ? "none" : list) + ")."));
            continue;
          }
        if (!v.set_name.empty())
          AssertThrow(std::any_of(contact.joint_sets.begin(),
                                  contact.joint_sets.end(),
                                  [&](const JointSet &set) {
                                    return set.name == v.set_name;
                                  }),
                      ExcMessage(where + "'set " + v.set_name +
                                 "' names no set of Contact/Joint sets."));
        if (!v.all && v.set_name.empty())
          AssertThrow(v.interface < contact.interfaces.size(),
                      ExcMessage(where + "'" + v.target + "': the model has " +
                                 std::to_string(contact.interfaces.size()) +
                                 " interface(s)."));
        unsigned int n_pairs = 0;
        stages.change_nominal_joints(
          [&](const ContactPair<dim> &pair, JointLaw &) {
            n_pairs += v.applies_to(pair.interface,
                                    pair.joint_set < contact.joint_sets.size() ?
                                      contact.joint_sets[pair.joint_set].name :
                                      "");
          });
        AssertThrow(n_pairs > 0,
                    ExcMessage(where + "'" + v.target +
                               "' is the law of no contact pair."));
      }
  }



  template <int dim>
  void
  ReliabilityRun<dim>::apply(const std::vector<double> &values)
  {
    // The functions that name a random constant, read again with the
    // sample's values of all of them.
    for (auto &function : parsed_functions())
      {
        auto constants = function.constants;
        bool changed   = false;
        for (unsigned int j = 0; j < parameters.variables.size(); ++j)
          {
            const auto &v = parameters.variables[j];
            if (v.quantity == RandomVariable::Quantity::constant &&
                constants.count(v.constant) > 0)
              {
                constants[v.constant] = values[j];
                changed               = true;
              }
          }
        if (changed)
          function.set_constants(constants);
      }
    const auto &sets = model.parameters.contact.joint_sets;
    stages.change_nominal_joints(
      [&](const ContactPair<dim> &pair, JointLaw &law) {
        const std::string set =
          pair.joint_set < sets.size() ? sets[pair.joint_set].name : "";
        for (unsigned int j = 0; j < parameters.variables.size(); ++j)
          if (parameters.variables[j].applies_to(pair.interface, set))
            parameters.variables[j].apply(values[j], law);
      });
  }



  template <int dim>
  ReliabilitySample
  ReliabilityRun<dim>::solve_sample()
  {
    ReliabilitySample sample;
    Timer             clock;
    // The search's first trial is F = 1: the sample's verdict.
    std::ostream      silent(nullptr);
    StrengthReduction search(model.parameters.strength_reduction, silent, true);
    const auto        trial = [&](const double f) {
      const StrengthTrial t =
        strength_reduction.run_trial(f, search.trials().empty());
      if (search.trials().empty())
        sample.verdict = t.converged() ? ReliabilitySample::Verdict::stands :
                                t.outcome == StrengthTrial::Outcome::not_converged ?
                                                ReliabilitySample::Verdict::gave_up :
                                                ReliabilitySample::Verdict::fails;
      ++sample.trials;
      sample.trials_gave_up +=
        (t.outcome == StrengthTrial::Outcome::not_converged);
      return t;
    };
    if (!parameters.factor_of_safety)
      trial(1.);
    else
      try
        {
          sample.factor = search.search(trial);
          sample.upper  = search.upper();
        }
      catch (const ExceptionBase &e)
        {
          // Every F down to 0.001 failed, or the trials ran out: the
          // verdict at F = 1 stands, F is unknown.
          const int code = exit_code(e);
          if (code != 2 && code != 3 && code != 4)
            throw;
        }
    sample.seconds = clock.wall_time();
    return sample;
  }



  namespace
  {
    std::string
    to_string(const ReliabilitySample::Verdict verdict)
    {
      return verdict == ReliabilitySample::Verdict::stands ? "stands" :
             verdict == ReliabilitySample::Verdict::fails  ? "fails" :
                                                             "gave up";
    }
  } // namespace



  template <int dim>
  std::string
  ReliabilityRun<dim>::csv_line(const unsigned int         i,
                                const std::vector<double> &values,
                                const ReliabilitySample   &sample) const
  {
    std::ostringstream line;
    line << std::setprecision(10) << i + 1;
    for (const double x : values)
      line << ',' << x;
    line << ',' << sample.factor << ',' << to_string(sample.verdict) << ','
         << sample.trials << ',' << sample.trials_gave_up;
    if (!model.parameters.run.test_mode)
      line << ',' << std::setprecision(4) << sample.seconds;
    line << '\n';
    return line.str();
  }



  namespace
  {
    /** Mean, standard deviation, smallest and largest of @p x. */
    std::array<double, 4>
    statistics(const std::vector<double> &x)
    {
      double mean = 0., square = 0.;
      for (const double v : x)
        mean += v / x.size();
      for (const double v : x)
        square += (v - mean) * (v - mean);
      return {{mean,
               x.size() > 1 ? std::sqrt(square / (x.size() - 1)) : 0.,
               *std::min_element(x.begin(), x.end()),
               *std::max_element(x.begin(), x.end())}};
    }
  } // namespace



  template <int dim>
  std::string
  ReliabilityRun<dim>::summary(
    const std::vector<ReliabilitySample> &samples) const
  {
    const unsigned int  N        = samples.size();
    unsigned int        failures = 0, gave_up = 0, trials_gave_up = 0;
    std::vector<double> factors;
    for (const auto &sample : samples)
      {
        failures += (sample.verdict == ReliabilitySample::Verdict::fails);
        gave_up += (sample.verdict == ReliabilitySample::Verdict::gave_up);
        trials_gave_up += sample.trials_gave_up;
        if (!std::isnan(sample.factor))
          factors.push_back(sample.factor);
      }
    std::ostringstream out;
    out << std::setprecision(6);
    if (!factors.empty())
      {
        const auto f = statistics(factors);
        out << "  F: mean " << f[0] << ", standard deviation " << f[1]
            << ", smallest " << f[2] << ", largest " << f[3] << " (of "
            << factors.size() << " samples with a factor)\n";
      }
    const FailureProbability p = failure_probability(failures, N);
    out << "  P(F < 1) = " << p.estimate << " (" << failures << " of " << N
        << " samples have no equilibrium at their strengths), 95 % interval ["
        << p.lower << ", " << p.upper
        << "] (Clopper and Pearson's, exact for Monte Carlo, conservative "
           "for Latin hypercube and Sobol samples)\n"
        << "  reliability index beta = -Phi^-1(P(F < 1)) = " << p.beta << "\n";
    if (gave_up > 0)
      out << "  " << gave_up << " of " << N
          << " samples gave up at their strengths (exit code 3: admissible "
             "forces, no state found), counted apart: P(F < 1) lies between "
          << p.estimate << " and " << double(failures + gave_up) / N << "\n";
    out << "  " << trials_gave_up
        << " load histories of the searches gave up (their samples' F is "
           "then a lower bound)\n";
    return out.str();
  }



  template <int dim>
  void
  ReliabilityRun<dim>::run(const double setup_seconds)
  {
    const ReliabilitySamples values = draw_samples(parameters);
    check_targets();
    std::ostringstream header;
    if (parameters.method == "FORM")
      header << "Reliability: FORM (OpenTURNS, Cobyla from the mean) of ";
    else
      header << "Reliability: " << values.size() << " samples ("
             << parameters.sampling << ", seed " << parameters.seed << ") of ";
    header << parameters.variables.size() << " random variable(s); each "
           << (parameters.factor_of_safety ?
                 "model's factor of safety by strength reduction" :
                 "model's load history at F = 1")
           << ", on one set-up\n";
    for (const auto &v : parameters.variables)
      header << "  " << v.name << ": " << v.target
             << (v.quantity == RandomVariable::Quantity::constant ?
                   "" :
                   " " + v.quantity_name())
             << ", " << v.distribution << "\n";
    model.pcout << header.str();
    const std::string base = model.parameters.output.directory + "/" +
                             model.parameters.output.base_name + "-reliability";
    std::string csv = "sample";
    for (const auto &v : parameters.variables)
      csv += "," + v.name;
    csv += std::string(",F,verdict,trials,trials_gave_up") +
           (model.parameters.run.test_mode ? "" : ",seconds") + "\n";

    Timer             clock;
    const std::string text =
      (parameters.method == "FORM" ? run_form_method(base, csv) :
                                     run_samples(values, base, csv));
    model.pcout << text;
    if (!model.parameters.run.test_mode)
      model.pcout << "  set-up " << std::fixed << std::setprecision(2)
                  << setup_seconds << " s, " << parameters.method << " "
                  << clock.wall_time() << " s" << std::defaultfloat
                  << std::setprecision(6) << "\n";
    model.pcout << "  a line per model run in " << base
                << ".csv, the estimates in " << base << "-summary.txt\n";
    write_file_atomically(base + "-summary.txt", header.str() + text);
  }



  template <int dim>
  std::string
  ReliabilityRun<dim>::run_samples(const ReliabilitySamples &values,
                                   const std::string        &base,
                                   std::string              &csv)
  {
    const unsigned int             N = values.size();
    std::vector<ReliabilitySample> samples;
    Timer                          clock;
    const unsigned int             every = std::max(1u, N / 20);
    for (unsigned int i = 0; i < N; ++i)
      {
        apply(values[i]);
        samples.push_back(solve_sample());
        csv += csv_line(i, values[i], samples.back());
        if (N <= 20 || (i + 1) % every == 0 || i + 1 == N)
          {
            write_file_atomically(base + ".csv", csv);
            const auto failed =
              std::count_if(samples.begin(), samples.end(), [](const auto &s) {
                return s.verdict == ReliabilitySample::Verdict::fails;
              });
            model.pcout << "  " << i + 1 << " of " << N
                        << " samples: " << failed << " without equilibrium";
            if (!model.parameters.run.test_mode)
              model.pcout << ", " << std::fixed << std::setprecision(1)
                          << clock.wall_time() << " s, about "
                          << clock.wall_time() * (N - i - 1) / (i + 1)
                          << " s to go" << std::defaultfloat
                          << std::setprecision(6);
            model.pcout << "\n";
          }
      }
    return summary(samples);
  }



  template <int dim>
  std::string
  ReliabilityRun<dim>::run_form_method(const std::string &base,
                                       std::string       &csv)
  {
    unsigned int i = 0;
    // Each evaluation of the limit state: the model at those values, its
    // factor of safety (0 where every factor down to 0.001 fails).
    const auto factor = [&](const std::vector<double> &values) {
      apply(values);
      const ReliabilitySample sample = solve_sample();
      csv += csv_line(i++, values, sample);
      write_file_atomically(base + ".csv", csv);
      model.pcout << "  evaluation " << i << ":";
      for (unsigned int j = 0; j < values.size(); ++j)
        model.pcout << " " << parameters.variables[j].name << " = "
                    << values[j];
      model.pcout << ", F = " << sample.factor << "\n";
      // The middle of the search's bracket: the limit state's root then
      // lies within a quarter of the bracket (1e-3) of the model's.
      return std::isnan(sample.factor) ? 0. :
             std::isinf(sample.upper)  ? sample.factor :
                                         0.5 * (sample.factor + sample.upper);
    };
    const FormResult   form = run_form(parameters, factor);
    std::ostringstream out;
    out << std::setprecision(6) << "  FORM: design point";
    for (unsigned int j = 0; j < form.design_point.size(); ++j)
      out << " " << parameters.variables[j].name << " = "
          << form.design_point[j];
    out << "\n  reliability index beta = " << form.beta
        << " (Hasofer and Lind's), P(F < 1) = Phi(-beta) = " << form.probability
        << "\n  importance factors:";
    for (unsigned int j = 0; j < form.importance.size(); ++j)
      out << " " << parameters.variables[j].name << " " << form.importance[j];
    out << "\n  " << form.evaluations
        << " evaluations of the limit state F - 1 (a strength-reduction "
           "search each)\n";
    return out.str();
  }



  template class ReliabilityRun<2>;
  template class ReliabilityRun<3>;
} // namespace mbfem

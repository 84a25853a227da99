#include <mbfem/analysis/strength_reduction.h>
#include <mbfem/base/exceptions.h>
#include <mbfem/base/text_input.h>
#include <mbfem/output/output.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace mbfem
{
  namespace
  {
    /** Below this F the model is taken to have no factor of safety. */
    constexpr double smallest_factor = 1e-3;
    /** Above this F the search stops: "at least 1000". */
    constexpr double largest_factor = 1e3;
  } // namespace



  void
  StrengthReductionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Strength reduction");
    {
      prm.declare_entry(
        "Tolerance",
        "1e-3",
        Patterns::Double(1e-8, 0.5),
        "Mode = strength reduction: the search ends when the largest F that "
        "converged and the smallest that failed differ by at most this "
        "fraction of the first. F divides tan(phi) and the cohesion of every "
        "joint.");
      prm.declare_entry(
        "Reduce tensile strength",
        "true",
        Patterns::Bool(),
        "Whether F divides the joints' tensile strength too, as the statics "
        "certificate does.");
      prm.declare_entry("Maximum trials",
                        "40",
                        Patterns::Integer(2, 1000),
                        "Load histories the search may run (the final run at "
                        "the factor of safety, which writes the results, is "
                        "not counted).");
      prm.declare_entry(
        "Closed-form factor of safety",
        "",
        Patterns::Anything(),
        "For verification: F from a closed form (limit equilibrium), a "
        "number or an expression of numbers (muparser: sin, cos, tan, "
        "atan, pi, ...). The run then prints F's difference from it and "
        "whether the final bracket holds it. Empty: none.");
    }
    prm.leave_subsection();
  }



  void
  StrengthReductionParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Strength reduction");
    {
      tolerance               = prm.get_double("Tolerance");
      reduce_tensile_strength = prm.get_bool("Reduce tensile strength");
      max_trials              = prm.get_integer("Maximum trials");
      closed_form_text =
        Utilities::trim(prm.get("Closed-form factor of safety"));
      closed_form = 0.;
      if (!closed_form_text.empty())
        {
          FunctionParser<1> parser;
          try
            {
              const QuietCerr quiet;
              parser.initialize("closed_form_variable_",
                                closed_form_text,
                                {{"pi", numbers::PI}, {"Pi", numbers::PI}});
              closed_form = parser.value(Point<1>());
            }
          catch (...)
            {
              closed_form = std::numeric_limits<double>::quiet_NaN();
            }
          AssertThrow(std::isfinite(closed_form) && closed_form > 0.,
                      ExcMessage("Strength reduction/Closed-form factor of "
                                 "safety: '" +
                                 closed_form_text +
                                 "' is no positive number (an expression "
                                 "of numbers, pi and muparser's "
                                 "functions)."));
        }
    }
    prm.leave_subsection();
  }



  std::string
  to_string(const StrengthTrial::Outcome outcome)
  {
    switch (outcome)
      {
        case StrengthTrial::Outcome::converged:
          return "converged";
        case StrengthTrial::Outcome::no_equilibrium:
          return "no equilibrium";
        case StrengthTrial::Outcome::none_along_mechanism:
          return "none along mechanism";
        case StrengthTrial::Outcome::not_converged:
          return "not converged";
      }
    return "";
  }



  StrengthReduction::StrengthReduction(
    const StrengthReductionParameters &parameters,
    std::ostream                      &out,
    const bool                         test_mode,
    const std::string                 &csv_file)
    : parameters(parameters)
    , out(out)
    , test_mode(test_mode)
    , csv_file(csv_file)
  {}



  double
  StrengthReduction::search(const RunTrial &run_trial)
  {
    print_header();
    try_factor(run_trial, 1.);
    for (double factor = next_factor(); factor > 0.; factor = next_factor())
      {
        if (factor < smallest_factor)
          fail_everywhere();
        if (trial_list.size() >= parameters.max_trials)
          {
            std::ostringstream message;
            message << "Strength reduction: no bracket narrower than "
                       "'Strength reduction/Tolerance' after "
                    << trial_list.size()
                    << " trials ('Strength reduction/Maximum trials'); the "
                       "last bracket was ["
                    << lo << ", " << hi << "]. The trials are in <" << csv_file
                    << ">.";
            AssertThrow(false, ExcMessage(message.str()));
          }
        try_factor(run_trial, factor);
      }
    AssertThrow(lo > 0., ExcInternalError());
    return lo;
  }



  void
  StrengthReduction::fail_everywhere() const
  {
    // Say what the failures were: statics proved them, or the iteration
    // gave up (then the model may well hold).
    const StrengthTrial::Outcome last = trial_list.back().outcome;
    const bool         after_breaking = trial_list.back().after_breaking;
    std::ostringstream message;
    message << "Strength reduction: the load history fails at every factor "
               "tried, down to F = "
            << hi << " (the joints' strengths multiplied by " << 1. / hi
            << "); the last trial ended with '" << to_string(last) << "'"
            << (last != StrengthTrial::Outcome::no_equilibrium ?
                  ", which proves nothing of the model." :
                after_breaking ?
                  ": no contact forces hold the blocks once the joints its "
                  "load path broke have lost their strength (with them "
                  "whole, rigid-block statics admits forces), so the model "
                  "has no factor of safety along this loading." :
                  ": no contact forces within the joints' strength hold the "
                  "blocks, so the model has no factor of safety.")
            << " Run it with Mode = simulation to see why.";
    if (last == StrengthTrial::Outcome::no_equilibrium)
      throw Exceptions::ExcNoEquilibrium(message.str());
    AssertThrow(false, ExcMessage(message.str()));
    std::abort(); // not reached: AssertThrow threw
  }



  void
  StrengthReduction::try_factor(const RunTrial &run_trial, const double factor)
  {
    StrengthTrial trial = run_trial(factor);
    trial.factor        = factor;
    if (trial.converged())
      lo = std::max(lo, factor);
    else
      hi = std::min(hi, factor);
    trial_list.push_back(trial);
    print_trial(trial);
    if (!csv_file.empty())
      write_csv(csv_file);
  }



  double
  StrengthReduction::next_factor() const
  {
    const double tol = parameters.tolerance;
    if (lo > 0. && hi - lo <= tol * lo)
      return 0.;
    if (lo >= largest_factor && std::isinf(hi))
      return 0.;
    // First the bracket around the statics bound, then down from it in
    // steps growing fourfold (an elastic model that opens at a heel holds
    // less than the rigid blocks): for one block sliding on one plane the
    // first two trials after F = 1 end the search.
    const double bound = statics_bound();
    if (std::isfinite(bound) && bound > 0.)
      {
        std::vector<double> candidates;
        const double        guess = mechanism_factor();
        if (std::isfinite(guess) && guess > 0. && guess < bound)
          candidates = {guess * (1. + tol / 4.), guess * (1. - tol / 2.)};
        candidates.push_back(bound * (1. + tol / 4.));
        for (double step = tol / 2.; step < 0.5; step *= 4.)
          candidates.push_back(bound * (1. - step));
        for (const double c : candidates)
          {
            bool tried = false;
            for (const auto &trial : trial_list)
              tried = tried || trial.factor == c;
            if (!tried && c > lo * (1. + tol / 8.) && c < hi * (1. - tol / 8.))
              return c;
          }
      }
    // No bound: doubling. Above the bound (a failed first guess): up in
    // steps growing fourfold from the tolerance.
    if (std::isinf(hi) && !std::isfinite(bound))
      return 2. * lo;
    if (std::isinf(hi))
      {
        unsigned int n_up = 0;
        for (const auto &trial : trial_list)
          n_up += (trial.factor > 1. && trial.converged());
        return lo * std::min(1. + tol * std::pow(4., n_up), 2.);
      }
    if (lo == 0.)
      return hi / 2.;
    return (lo + hi) / 2.;
  }



  const std::vector<StrengthTrial> &
  StrengthReduction::trials() const
  {
    return trial_list;
  }



  double
  StrengthReduction::lower() const
  {
    return lo;
  }



  double
  StrengthReduction::upper() const
  {
    return hi;
  }



  double
  StrengthReduction::statics_bound() const
  {
    return trial_list.empty() ? std::numeric_limits<double>::quiet_NaN() :
                                trial_list.front().statics_bound;
  }



  double
  StrengthReduction::mechanism_factor() const
  {
    return trial_list.empty() ? std::numeric_limits<double>::quiet_NaN() :
                                trial_list.front().mechanism_factor;
  }



  std::string
  StrengthReduction::result_line() const
  {
    std::ostringstream line;
    line << std::setprecision(6);
    if (std::isinf(hi))
      line << "factor of safety at least " << lo << " (every F up to " << lo
           << " converged";
    else
      line << "factor of safety = " << lo << " (bracket [" << lo << ", " << hi
           << "]";
    // With sigma_t kept, the certificate (which divides it) is no bound.
    const std::string name  = parameters.reduce_tensile_strength ?
                                "statics bound" :
                                "statics estimate with sigma_t / F";
    const double      bound = statics_bound();
    if (std::isfinite(bound))
      line << ", " << name << " " << bound << ")";
    else
      line << ", " << name << " above 1000 or none)";
    const double guess = mechanism_factor();
    if (std::isfinite(guess) && std::isfinite(bound) && guess < bound)
      line << "\n  limit equilibrium along the statics limit's mechanism: "
           << guess << " (the search's first guess)";
    // What bounds F from above where statics alone does not: the failing
    // trial at hi ended after its load path broke joints, or the state
    // iteration gave up (the model may hold more, or the elastic model
    // may have no equilibrium there): say so.
    for (const auto &trial : trial_list)
      {
        if (trial.factor != hi)
          continue;
        if (trial.after_breaking)
          line << "\n  at F = " << hi
               << " no equilibrium once the joints its load path broke lost "
                  "their strength; rigid-block statics with them whole "
                  "admits forces (a verdict for the path's history, "
                  "doc/decisions.md \"Joints the load path broke\")";
        else if (trial.outcome == StrengthTrial::Outcome::not_converged)
          line << "\n  F is a lower bound: at F = " << hi
               << " the state iteration gave up although rigid-block "
                  "statics admits forces (exit code 3 of a plain run); "
                  "either the solver failed there or the elastic model has "
                  "no equilibrium (statics cannot tell where the joint "
                  "opens)";
      }
    return line.str();
  }



  std::string
  StrengthReduction::closed_form_line() const
  {
    const double cf = parameters.closed_form;
    if (cf <= 0.)
      return "";
    std::ostringstream line;
    line << "closed form F = " << std::setprecision(6) << cf
         << ": F differs by " << std::fixed << std::setprecision(3)
         << 100. * (lo - cf) / cf << " %, the bracket holds it: "
         << (lo <= cf * (1. + 1e-12) && cf <= hi * (1. + 1e-12) ? "yes" : "no");
    return line.str();
  }



  void
  StrengthReduction::print_header() const
  {
    out << "Strength reduction: tan(phi) / F, c / F"
        << (parameters.reduce_tensile_strength ? ", sigma_t / F" : "")
        << " on every joint; the factorisations and flexibilities are "
           "reused.\n"
        << "  trial          F  result                increments  method(s)"
           "                 iterations"
        << (test_mode ? "" : "     time") << "\n";
  }



  void
  StrengthReduction::print_trial(const StrengthTrial &trial) const
  {
    std::ostringstream line;
    line << "  " << std::setw(5) << trial_list.size() << "  " << std::setw(9)
         << std::fixed << std::setprecision(6) << trial.factor << "  "
         << std::left << std::setw(20) << to_string(trial.outcome) << "  "
         << std::right << std::setw(4) << trial.increments << "/" << std::left
         << std::setw(5) << trial.n_increments << "  " << std::setw(24)
         << (trial.methods.empty() ? "-" : trial.methods) << std::right
         << std::setw(11) << trial.iterations;
    if (!test_mode)
      line << std::setw(8) << std::setprecision(2) << trial.seconds << " s";
    out << line.str() << std::endl;
  }



  void
  StrengthReduction::write_csv(const std::string &filename) const
  {
    std::ostringstream csv;
    csv << "trial,F,result,increments,methods,iterations,seconds,"
           "largest_displacement,largest_slip\n"
        << std::setprecision(10);
    for (unsigned int i = 0; i < trial_list.size(); ++i)
      {
        const auto &t = trial_list[i];
        csv << i + 1 << "," << t.factor << "," << to_string(t.outcome) << ","
            << t.increments << "," << t.methods << "," << t.iterations << ","
            << (test_mode ? 0. : t.seconds) << "," << t.largest_displacement
            << "," << t.largest_slip << "\n";
      }
    write_file_atomically(filename, csv.str());
  }
} // namespace mbfem

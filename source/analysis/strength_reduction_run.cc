// The strength-reduction mode (issue 28): the trials
// of the load history at reduced joint strengths on one set-up, and the
// final run at the factor of safety. The search itself is
// StrengthReduction (strength_reduction.cc), which knows nothing of blocks.

#include <mbfem/analysis/block_measures.h>
#include <mbfem/analysis/parameters.h>
#include <mbfem/analysis/strength_reduction_run.h>
#include <mbfem/base/exceptions.h>

#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>
#include <string>

namespace mbfem
{
  template <int dim>
  StrengthReductionRun<dim>::StrengthReductionRun(
    Model<dim>                              &model,
    StageSequence<dim>                      &stages,
    const std::function<void(unsigned int)> &do_increment,
    const std::function<void()>             &run_load_history)
    : model(model)
    , stages(stages)
    , do_increment(do_increment)
    , run_load_history(run_load_history)
  {}



  template <int dim>
  void
  StrengthReductionRun<dim>::run(const double setup_seconds)
  {
    const auto       &srm = model.parameters.strength_reduction;
    StrengthReduction search(srm,
                             model.pcout.get_stream(),
                             model.parameters.run.test_mode,
                             model.parameters.output.directory + "/" +
                               model.parameters.output.base_name +
                               "-strength-reduction.csv");
    // The formulation's time of the run at F, not of the trials.
    const double condensed_setup = model.condensed_seconds;
    const double factor          = search.search(
      [&](const double f) { return run_trial(f, search.trials().empty()); });

    model.pcout << "The load history at F = " << factor
                << ", the last factor that converged:\n";
    model.condensed_seconds = condensed_setup;
    Timer final_clock;
    stages.restart_contact(factor);
    stages.set_early_verdict(false); // the full messages
    run_load_history();
    const double final_seconds = final_clock.wall_time();

    model.pcout << search.result_line() << "\n";
    if (!search.closed_form_line().empty())
      model.pcout << "  " << search.closed_form_line() << "\n";
    double trial_seconds = 0.;
    for (const auto &trial : search.trials())
      trial_seconds += trial.seconds;
    model.pcout << "  " << search.trials().size()
                << " trial load histories and the final one on one set-up "
                   "(factorisations and flexibilities reused)";
    if (!model.parameters.run.test_mode)
      model.pcout << ": set-up " << std::fixed << std::setprecision(2)
                  << setup_seconds << " s, trials " << trial_seconds
                  << " s, final run " << final_seconds << " s; in all "
                  << std::setprecision(1)
                  << (setup_seconds + trial_seconds + final_seconds) /
                       (setup_seconds + search.trials().front().seconds)
                  << " times one run of the model at F = 1" << std::defaultfloat
                  << std::setprecision(6);
    model.pcout << "\n";
  }



  namespace
  {
    /**
     * A trial of strength reduction while it lives, however it ends (a
     * failure, a signal): the screen silent and nothing written
     * (Model::trial_run).
     */
    class TrialScope
    {
    public:
      TrialScope(ConditionalOStream &pcout, bool &trial_run)
        : pcout(pcout)
        , was_active(pcout.is_active())
        , trial_run(trial_run)
      {
        pcout.set_condition(false);
        trial_run = true;
      }

      ~TrialScope()
      {
        pcout.set_condition(was_active);
        trial_run = false;
      }

    private:
      ConditionalOStream &pcout;
      const bool          was_active;
      bool               &trial_run;
    };



    /**
     * How a trial's failure counts (the exit code a plain run would have
     * ended with); any other error ends the run, naming the trial.
     */
    StrengthTrial::Outcome
    trial_outcome(const ExceptionBase &e, const double factor)
    {
      const int code = exit_code(e);
      if (code == 2)
        return StrengthTrial::Outcome::no_equilibrium;
      if (code == 4)
        return StrengthTrial::Outcome::none_along_mechanism;
      if (code == 3 ||
          dynamic_cast<const Exceptions::ExcIncrementNotConverged *>(&e))
        return StrengthTrial::Outcome::not_converged;
      std::ostringstream message;
      message << "Strength reduction, the trial at F = " << factor << ": "
              << message_of(e);
      AssertThrow(false, ExcMessage(message.str()));
      return StrengthTrial::Outcome::not_converged;
    }
  } // namespace



  template <int dim>
  StrengthTrial
  StrengthReductionRun<dim>::run_trial(const double factor,
                                       const bool   statics_bound)
  {
    StrengthTrial      trial;
    const unsigned int first = model.parameters.in_situ_stress.enabled ? 0 : 1;
    const unsigned int last  = model.parameters.load_history.n_increments;
    trial.factor             = factor;
    trial.n_increments       = last + 1 - first;
    stages.restart_contact(factor);
    // A trial needs only the verdict: where statics proves none, the
    // costly methods of the chain are not tried.
    stages.set_early_verdict(true);
    const TrialScope scope(model.pcout, model.trial_run);

    std::set<std::string> methods;
    Timer                 clock;
    try
      {
        for (unsigned int k = first; k <= last; ++k)
          {
            do_increment(k);
            ++trial.increments;
            methods.insert(model.contact->last_method());
            trial.iterations += model.contact->last_iterations().first +
                                model.contact->last_iterations().second;
            trial.largest_displacement = 0.;
            for (const auto &block : model.blocks)
              trial.largest_displacement =
                std::max(trial.largest_displacement, max_displacement(*block));
            trial.largest_slip = max_slip(*model.contact);
            if (statics_bound)
              measure_statics(trial, k == last);
          }
      }
    catch (const ExceptionBase &e)
      {
        trial.outcome = trial_outcome(e, factor);
        trial.after_breaking =
          dynamic_cast<const Exceptions::ExcNoEquilibriumAfterBreaking *>(&e) !=
          nullptr;
        if (statics_bound)
          measure_statics(trial, true);
      }
    trial.seconds = clock.wall_time();
    for (const auto &method : methods)
      trial.methods += (trial.methods.empty() ? "" : "+") + method;
    return trial;
  }



  template <int dim>
  void
  StrengthReductionRun<dim>::measure_statics(StrengthTrial &trial,
                                             const bool     last) const
  {
    // Unbroken: an upper bound whatever pairs another trial breaks
    // (strength_factor_bounded: the search hit its bound of 1000). The
    // mechanism's limit equilibrium only where the history ends.
    const auto result = model.contact->certify(last, true);
    if (!result.strength_factor_bounded)
      {
        const double bound  = trial.factor * result.strength_factor;
        trial.statics_bound = std::isnan(trial.statics_bound) ?
                                bound :
                                std::min(trial.statics_bound, bound);
      }
    if (last && !result.limit_mechanism.empty() &&
        !result.mechanism_factor_bounded)
      trial.mechanism_factor = trial.factor * result.mechanism_factor;
  }


  template class StrengthReductionRun<2>;
  template class StrengthReductionRun<3>;
} // namespace mbfem

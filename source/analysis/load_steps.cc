// One load increment of the present configuration (LoadSteps): step
// halving, the plastic passes, each pass's loads, contact solve and field
// recovery, and the statics certificate's verdict where it fails for good.

#include <mbfem/analysis/load_steps.h>
#include <mbfem/analysis/parameters.h>
#include <mbfem/base/exceptions.h>
#include <mbfem/base/parallel.h>

#include <deal.II/base/timer.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>

namespace mbfem
{
  template <int dim>
  LoadSteps<dim>::LoadSteps(Model<dim>           &model,
                            StageSequence<dim>   &stages,
                            const RunReport<dim> &report)
    : model(model)
    , stages(stages)
    , report(report)
  {}



  namespace
  {
    /**
     * Why an increment failed although statics (and limit equilibrium
     * along its mechanism, where there is one) admits forces: the text
     * that follows an admissible certificate.
     */
    template <int dim>
    std::string
    why_admissible_but_failed(
      const typename StaticAdmissibility<dim>::Result &result,
      const ContactSolver<dim>                        &contact)
    {
      std::string why;
      if (result.limit_mechanism.empty())
        why = "    Statics admits forces with these joint strengths and "
              "gives no mechanism to check limit equilibrium along. The "
              "state iteration found no equilibrium: a failure of the "
              "iteration, or of the model beyond what statics can "
              "prove.";
      else if (result.mechanism_factor_bounded && result.mechanism_factor < 1.)
        why = "    Statics admits forces with these joint strengths; "
              "the mechanism of its limit is none the blocks could be "
              "held along even with 1000 times the strength, so it "
              "says nothing here. The state iteration found no "
              "equilibrium: a failure of the iteration, or of the "
              "model beyond what statics can prove.";
      else
        why = "    Statics and limit equilibrium along the mechanism "
              "both admit forces with these joint strengths, and the "
              "state iteration found no equilibrium: a failure of the "
              "iteration, or of the elastic model where it opens "
              "joints whose cohesion rigid-block statics counts "
              "(statics cannot prove that the elastic model has a "
              "solution; doc/contact_problems.md says how to check the "
              "increment's problem).";
      // Where nothing can break, what is left is the solver or
      // friction beyond the existence result's conditions
      // (doc/decisions.md).
      if (!contact.has_strength_to_lose())
        why += " No joint of this increment has cohesion or tensile "
               "strength to lose, so breaking is not the reason; what "
               "is left is the solver, or friction beyond the "
               "conditions of the existence result (doc/decisions.md, "
               "\"A method that concludes\"): check the increment's "
               "problem with another solver, or report it.";
      return why;
    }



    /**
     * Ends the run after an increment failed for good (after any step
     * halvings) with the verdict of the statics certificate for the loads
     * of the last step tried: none exist (ExcNoEquilibrium, exit code 2),
     * some exist but none along the mechanism of the statics limit with
     * the shear against the slip (ExcNoEquilibriumAlongMechanism, 4), some
     * exist along it too although the iteration failed
     * (ExcNotConvergedButAdmissible, 3), or, undecided or without
     * interfaces, the failure as it was (ExcIncrementNotConverged, 1).
     * None exist also where statics without the joints the load path
     * broke admits no forces (2). Those two verdicts that statics alone
     * cannot give leave the increment's problem on disk: @p write_problem
     * writes it and says where.
     */
    template <int dim>
    [[noreturn]] void
    end_with_certificate(const ContactSolver<dim>           *contact,
                         const std::string                  &message,
                         const double                        time,
                         const bool                          no_equilibrium,
                         const std::function<std::string()> &write_problem)
    {
      if (!contact)
        {
          if (no_equilibrium)
            throw Exceptions::ExcNoEquilibrium(message);
          throw Exceptions::ExcIncrementNotConverged(message);
        }
      const auto         result = contact->certify();
      std::ostringstream text;
      text << message << "    Statics certificate at t = " << time << ": "
           << result.description << "\n";
      using Verdict = typename StaticAdmissibility<dim>::Verdict;
      // The verdict first, however the state iteration ended.
      if (result.verdict == Verdict::none)
        {
          std::ostringstream verdict;
          verdict << "No equilibrium at t = " << time
                  << ": no contact forces within the joints' strength "
                     "balance the floating blocks' loads (the statics "
                     "certificate below).\n    "
                  << text.str();
          throw Exceptions::ExcNoEquilibrium(verdict.str());
        }
      // Statics admits forces with every joint whole; the increment broke
      // some on the way (the load path, De Saxce's fixed point).
      if (const auto path = contact->certify_path_breaking();
          path && path->verdict == Verdict::none)
        {
          std::ostringstream verdict;
          const std::string  by = contact->path_breaking_method();
          verdict << "No equilibrium at t = " << time << " once the joints "
                  << by
                  << " broke have lost their strength: no contact forces "
                     "within what is left of it balance the floating blocks' "
                     "loads (the second statics certificate below). Breaking "
                     "is for good, and the method broke them in the order of "
                     "its events (doc/decisions.md, \"Joints the load path "
                     "broke\", says what this proves); rigid-block statics "
                     "with those joints whole (the first certificate) cannot "
                     "see this.\n    "
                  << text.str() << "    Statics certificate at t = " << time
                  << " after " << by << ": " << path->description << "\n"
                  << write_problem();
          throw Exceptions::ExcNoEquilibriumAfterBreaking(verdict.str());
        }
      // A mechanism along which no strength holds the loads (factor
      // below 0.001: blocks lifting off, as the LP's duals can give for a
      // column of blocks) says nothing of the model: exit code 3 then.
      if (result.verdict == Verdict::admissible &&
          !result.limit_mechanism.empty() && !result.mechanism_factor_bounded &&
          result.mechanism_factor < 1.)
        {
          std::ostringstream verdict;
          verdict << "No equilibrium along the mechanism at t = " << time
                  << ": statics alone admits contact forces, but with the "
                     "shear of every sliding pair against its slip (limit "
                     "equilibrium, as Hoek and Bray's and Goodman and "
                     "Bray's analyses take it) none balance the loads, so "
                     "the blocks cannot move that way in equilibrium (the "
                     "statics certificate below). This is not a proof that "
                     "no equilibrium exists: a state in which they do not "
                     "move so might hold them, and the state iteration "
                     "found none.\n    "
                  << text.str();
          throw Exceptions::ExcNoEquilibriumAlongMechanism(verdict.str());
        }
      if (result.verdict == Verdict::admissible)
        {
          const std::string why =
            why_admissible_but_failed<dim>(result, *contact);
          throw Exceptions::ExcNotConvergedButAdmissible(
            text.str() + why + "\n" + write_problem());
        }
      throw Exceptions::ExcIncrementNotConverged(text.str());
    }
  } // namespace



  template <int dim>
  std::string
  LoadSteps<dim>::final_message(const std::string &first_failure,
                                const unsigned int halvings) const
  {
    const unsigned int max_halvings =
      model.parameters.load_history.max_halvings;
    return first_failure +
           (max_halvings == 0 ?
              "" :
              "    The increment was also tried in steps down to 1/" +
                std::to_string(1u << halvings) +
                " of its size ('Load history/Maximum step halvings = " +
                std::to_string(max_halvings) + "').\n") +
           "    " + report.earlier_results() + "\n";
  }



  template <int dim>
  unsigned int
  LoadSteps<dim>::solve_increment(const unsigned int k,
                                  unsigned int      &iterations,
                                  unsigned int      &reference_iterations,
                                  PlasticUpdate     &plastic_update)
  {
    // A failed increment may be retried from its start in steps of half
    // the size ('Load history/Maximum step halvings'); the steps before
    // the last are committed like increments. Only the failures a smaller
    // step can cure are retried (Exceptions::ExcIncrementNotConverged,
    // ExcNoEquilibrium); the message that ends the run is the first
    // failure's, at the increment's own size, not the last retry's, with
    // the statics certificate's verdict (end_with_certificate()).
    const LoadHistory &history = model.parameters.load_history;
    const double       time    = history.time(k);
    const double       start   = (k == 0 ? 0. : history.time(k - 1));
    double             reached = start, step = time - start;
    unsigned int       halvings = 0, n_steps = 0, plastic_iterations = 0;
    std::string        first_failure;
    const auto on_failure = [&](const auto &failure, const double target) {
      if (first_failure.empty())
        first_failure = message_of(failure);
      if (halvings == history.max_halvings)
        end_with_certificate<dim>(
          model.contact,
          final_message(first_failure, halvings),
          target,
          std::is_same_v<std::decay_t<decltype(failure)>,
                         Exceptions::ExcNoEquilibrium>,
          [&]() { return report.write_failed_problem(k, target); });
      for (const auto &block : model.blocks)
        block->plastic_state().restore();
      ++halvings;
      step                     = (target - reached) / 2.;
      const std::string reason = message_of(failure);
      model.pcout << "    step to t = " << target << " failed ("
                  << reason.substr(0, reason.find('\n')) << "); halving "
                  << halvings << " of " << history.max_halvings << ": steps of "
                  << step << "\n";
    };
    do
      {
        // (The last step ends at the increment's time exactly, not a
        // round-off short of it.)
        const double target =
          (halvings == 0 || reached + step > time - 1e-9 * step ?
             time :
             reached + step);
        try
          {
            plastic_iterations = solve_step(
              k, target, iterations, reference_iterations, plastic_update);
          }
        catch (const Exceptions::ExcIncrementNotConverged &e)
          {
            on_failure(e, target);
            continue;
          }
        catch (const Exceptions::ExcNoEquilibrium &e)
          {
            on_failure(e, target);
            continue;
          }
        reached = target;
        ++n_steps;
        if (reached < time)
          commit_step();
      }
    while (reached < time);
    if (n_steps > 1)
      model.pcout << "    increment " << k << " reached in " << n_steps
                  << " steps\n";
    certify_sliding_blocks(k, time);
    return plastic_iterations;
  }



  template <int dim>
  void
  LoadSteps<dim>::certify_sliding_blocks(const unsigned int k,
                                         const double       time) const
  {
    // A floating block none of whose pairs sticks may have converged to a
    // sliding state whose forces balance it only with tension or against
    // the cone (the 3D wedge beyond its limit did, with |u| ~ 1e8 m):
    // such an increment stands only if admissible forces exist.
    if (!model.contact)
      return;
    const std::vector<std::string> sliding =
      model.contact->blocks_without_stuck_pairs();
    if (sliding.empty())
      return;
    // Only the verdict decides here: the mechanism factor's LPs wait
    // until it is none.
    if (model.contact->certify(false).verdict !=
        StaticAdmissibility<dim>::Verdict::none)
      return;
    const auto  result = model.contact->certify();
    std::string names;
    for (const auto &name : sliding)
      names += (names.empty() ? "" : ", ") + name;
    std::ostringstream text;
    text << "Load increment " << k << ": no equilibrium. The contact "
         << "iteration converged with every pair of " << names
         << " slipping or open, but at t = " << time << " "
         << result.description
         << "\n    The converged state is no equilibrium the joints can "
            "hold. "
         << report.earlier_results();
    throw Exceptions::ExcNoEquilibrium(text.str());
  }



  template <int dim>
  void
  LoadSteps<dim>::share_solutions()
  {
    if (Parallel::n_ranks() > 1)
      for (const auto &block : model.blocks)
        block->share_solution();
  }



  template <int dim>
  void
  LoadSteps<dim>::check_ranks_agree() const
  {
    if (Parallel::n_ranks() == 1)
      return;
    std::vector<unsigned long long> states;
    for (unsigned int k = 0; k < model.contact->pairs().size(); ++k)
      {
        states.push_back(static_cast<unsigned int>(model.contact->state(k)));
        states.push_back(model.contact->broken(k));
      }
    Parallel::check_same_on_all_ranks(states,
                                      "the states of the contact pairs");
  }



  template <int dim>
  void
  LoadSteps<dim>::commit_step()
  {
    for (const auto &block : model.blocks)
      block->plastic_state().commit();
    if (model.contact)
      {
        check_ranks_agree();
        model.contact->commit();
      }
    if (model.reference)
      model.reference->commit();
  }



  template <int dim>
  void
  LoadSteps<dim>::assemble_loads(const double time,
                                 const bool   condensed,
                                 const bool   loads_everywhere)
  {
    TimerOutput::Scope t(model.timer, "load response");
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (unsigned int b = 0; b < model.blocks.size(); ++b)
        {
          Block<dim> &block = *model.blocks[b];
          block.assemble_load(model.parameters.boundary_conditions,
                              time,
                              loads_everywhere);
          if (model.water)
            model.water->add_load(b, block, time);
          stages.add_released_forces(b,
                                     time); // from the pairs of removed blocks
          if (condensed)
            {
              Timer clock;
              block.solve(); // on the block's owner
              model.condensed_seconds += clock.wall_time();
            }
        }
    });
    if (Parallel::n_ranks() > 1)
      for (const auto &block : model.blocks)
        block->share_load_resultant();
    if (condensed)
      share_solutions();
  }



  template <int dim>
  void
  LoadSteps<dim>::recover_fields(const bool condensed)
  {
    TimerOutput::Scope t(model.timer, "field recovery");
    Timer              clock;
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (unsigned int b = 0; b < model.blocks.size(); ++b)
        if (condensed)
          {
            std::vector<types::global_dof_index> dofs;
            std::vector<double>                  forces;
            model.contact->forces_on_block(b, dofs, forces);
            model.blocks[b]->add_point_forces(dofs, forces);
            model.blocks[b]->solve(model.contact->floating_amplitudes(b));
          }
        else
          {
            Vector<double> displacement;
            model.contact->block_solution(b, *model.blocks[b], displacement);
            model.blocks[b]->set_solution(std::move(displacement));
          }
    });
    if (condensed)
      share_solutions();
    (condensed ? model.condensed_seconds : model.monolithic_seconds) +=
      clock.wall_time();
  }



  template <int dim>
  void
  LoadSteps<dim>::solve_pass(const unsigned int k,
                             const double       time,
                             unsigned int      &iterations,
                             unsigned int      &reference_iterations,
                             const bool         from_last_solve)
  {
    const bool condensed = !model.contact || model.contact->formulation() ==
                                               ContactFormulation::condensed;
    // The condensed formulation needs a block's load on its owner alone
    // (the floating blocks' F_e is shared below); the monolithic system
    // assembles every block's on every rank.
    const bool loads_everywhere = !condensed || model.reference != nullptr;
    assemble_loads(time, condensed, loads_everywhere);
    if (model.contact)
      {
        {
          TimerOutput::Scope t(model.timer, "contact iterations");
          Timer              clock;
          iterations =
            model.contact->solve_increment(model.blocks, k, from_last_solve);
          model.last_contact_seconds = clock.wall_time();
          model.increment_contact_seconds += model.last_contact_seconds;
          (condensed ? model.condensed_seconds : model.monolithic_seconds) +=
            model.last_contact_seconds;
        }
        if (model.reference)
          {
            TimerOutput::Scope t(model.timer, "monolithic reference");
            Timer              clock;
            reference_iterations =
              model.reference->solve_increment(model.blocks, k);
            model.last_reference_seconds = clock.wall_time();
            model.monolithic_seconds += model.last_reference_seconds;
          }
        recover_fields(condensed);
      }
  }



  template <int dim>
  PlasticUpdate
  LoadSteps<dim>::update_plastic_strain()
  {
    PlasticUpdate      update;
    TimerOutput::Scope t(model.timer, "plasticity");
    for (const auto &block : model.blocks)
      update += block->plastic_state().update(*block);
    return update;
  }



  template <int dim>
  void
  LoadSteps<dim>::check_plastic_iterations(
    const unsigned int k,
    const double       time,
    const double       change,
    const unsigned int plastic_iterations) const
  {
    AssertThrow(plastic_iterations < model.parameters.plasticity.max_iterations,
                Exceptions::ExcIncrementNotConverged(
                  "Increment " + std::to_string(k) +
                  " (t = " + std::to_string(time) +
                  "): the plastic strain still changes " + "by " +
                  std::to_string(change) + " (relative) after " +
                  std::to_string(plastic_iterations) +
                  " iterations ('Plasticity/Maximum iterations'). The rock may "
                  "be failing (no equilibrium with this strength), or the "
                  "increment is too large: use more load increments. " +
                  report.earlier_results()));
  }



  template <int dim>
  unsigned int
  LoadSteps<dim>::solve_step(const unsigned int k,
                             const double       time,
                             unsigned int      &iterations,
                             unsigned int      &reference_iterations,
                             PlasticUpdate     &plastic_update)
  {
    // Plastic blocks: the increment is repeated with the plastic strain
    // of the last pass as a load until that strain settles (the
    // initial-stress method); elastic blocks pass once.
    const PlasticityParameters &plasticity = model.parameters.plasticity;
    unsigned int                plastic_iterations = 0;
    double                      previous_change    = 0.;
    double                      omega              = 1.;
    // Newton may give way to the initial-stress method for the rest of
    // the step (see PlasticState::suspend_newton()).
    bool newton = plasticity.newton;
    for (const auto &block : model.blocks)
      block->plastic_state().suspend_newton(false);
    for (;;)
      {
        // Newton: the contact states of the last pass start the next.
        const bool from_last_solve =
          plasticity.newton && plastic_iterations > 0;
        newton = pass_with_fallback(k,
                                    time,
                                    iterations,
                                    reference_iterations,
                                    from_last_solve,
                                    newton,
                                    plastic_iterations);
        if (!plasticity.enabled)
          break;
        ++plastic_iterations;
        plastic_update      = update_plastic_strain();
        const double change = std::sqrt(plastic_update.change2 /
                                        std::max(plastic_update.norm2, 1e-300));
        // The initial-stress iteration converges linearly, at a rate
        // that nears 1 as the plastic zone grows: what is left to go is
        // about change * rate / (1 - rate), not the change itself.
        const double rate =
          (previous_change > 0. ? change / previous_change : 0.);
        previous_change = change;
        report.print_plastic_progress(plastic_iterations,
                                      change,
                                      newton ? -1. : omega,
                                      plastic_update.n_yielded);
        const double remaining =
          (rate < 1. ? change * std::max(rate / (1. - rate), 1.) :
                       change * 1e3);
        if (plastic_update.change2 == 0. || remaining < plasticity.tolerance)
          break;
        check_plastic_iterations(k, time, change, plastic_iterations);

        // Aitken's relaxation of the fixed point x = F(x): omega from
        // the last two residuals (plain steps converge at a rate near 1
        // once the plastic zone is large, e.g. with dilatancy).
        if (newton)
          continue; // the new tangent goes in before the next pass
        omega = (plasticity.aitken && plastic_iterations > 1 ?
                   aitken_relaxation(omega, plastic_update) :
                   1.);
        for (const auto &block : model.blocks)
          block->plastic_state().relax(omega);
      }
    return plastic_iterations;
  }



  template <int dim>
  bool
  LoadSteps<dim>::pass_with_fallback(const unsigned int k,
                                     const double       time,
                                     unsigned int      &iterations,
                                     unsigned int      &reference_iterations,
                                     const bool         from_last_solve,
                                     bool               newton,
                                     const unsigned int plastic_iterations)
  {
    if (newton)
      try
        {
          update_tangent_stiffness();
          solve_pass(
            k, time, iterations, reference_iterations, from_last_solve);
          return true;
        }
      catch (const Exceptions::ExcNoEquilibrium &e)
        {
          newton = give_way_to_initial_stress(e, plastic_iterations);
        }
      catch (const Exceptions::ExcSingularMatrix &e)
        {
          newton = give_way_to_initial_stress(e, plastic_iterations);
        }
    // (Reassembles only after a suspension: the elastic stiffness.)
    update_tangent_stiffness();
    solve_pass(k, time, iterations, reference_iterations, from_last_solve);
    return newton;
  }



  template <int dim>
  double
  LoadSteps<dim>::aitken_relaxation(const double         omega,
                                    const PlasticUpdate &update)
  {
    // Bounds that keep a noisy estimate from stalling (0.05) or
    // overshooting far beyond the fixed point (20).
    constexpr double smallest = 0.05, largest = 20.;
    if (update.aitken_denominator <= 0.)
      return 1.;
    return std::min(largest,
                    std::max(smallest,
                             -omega * update.aitken_numerator /
                               update.aitken_denominator));
  }



  template <int dim>
  bool
  LoadSteps<dim>::give_way_to_initial_stress(
    const ExceptionBase &failure,
    const unsigned int   plastic_iterations)
  {
    // The tangent of perfect plasticity is singular along the flow; with
    // slipping pairs around a yielded band the condensed system can be too,
    // while the elastic one is not.
    bool suspended = false;
    for (const auto &block : model.blocks)
      suspended = block->plastic_state().suspend_newton(true) || suspended;
    if (!suspended)
      throw; // the elastic stiffness would fail alike: not Newton's fault
    ++model.newton_suspensions;
    const std::string reason = message_of(failure);
    if (!model.parameters.run.test_mode)
      model.pcout << "    Newton iteration " << plastic_iterations + 1
                  << ": no solution with the tangent stiffness ("
                  << reason.substr(0, reason.find('\n'))
                  << "); the rest of the step uses the elastic stiffness "
                  << "(initial-stress method)\n";
    return false;
  }



  template <int dim>
  void
  LoadSteps<dim>::update_tangent_stiffness()
  {
    bool changed = false;
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (const auto &block : model.blocks)
        if (block->plastic_state().tangent_changed())
          {
            changed = true;
            {
              TimerOutput::Scope t(model.timer, "assembly");
              block->assemble_stiffness();
            }
            TimerOutput::Scope t(model.timer, "factorisation");
            Timer              clock;
            block->factorize(); // on the block's owner
            model.condensed_seconds += clock.wall_time();
          }
    });
    if (changed && model.contact)
      {
        TimerOutput::Scope t(model.timer, "flexibility");
        Timer              clock;
        model.contact->setup(model.blocks);
        model.condensed_seconds += clock.wall_time();
      }
  }



  template class LoadSteps<2>;
  template class LoadSteps<3>;
} // namespace mbfem

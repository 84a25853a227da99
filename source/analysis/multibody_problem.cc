#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/base/exceptions.h>
#include <mbfem/base/parameters.h>

#include <deal.II/base/timer.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace mbfem
{
  template <int dim>
  MultiBodyProblem<dim>::MultiBodyProblem(Parameters<dim>    &parameters,
                                          ConditionalOStream &pcout)
    : parameters(parameters)
    , pcout(pcout)
    // Summary printed at the end of a run that finished, not on the way
    // out of one that failed.
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
  {}



  template <int dim>
  void
  MultiBodyProblem<dim>::make_blocks()
  {
    TimerOutput::Scope t(timer, "mesh");
    Triangulation<dim> mesh;
    create_mesh(parameters.mesh, mesh);

    const auto &materials = parameters.block_materials;
    const auto &excavated = parameters.excavation.excavated_ids;
    const auto  ids       = block_ids(mesh);
    for (const auto id : excavated)
      AssertThrow(std::find(ids.begin(), ids.end(), id) != ids.end(),
                  ExcMessage("Excavation/Excavated material ids lists " +
                             std::to_string(id) +
                             ", which is not a material id of the mesh."));
    for (const auto id : ids)
      {
        if (std::find(excavated.begin(), excavated.end(), id) !=
            excavated.end())
          continue; // removed rock: not a block
        Material material = parameters.material;
        if (!materials.empty())
          {
            AssertThrow(materials.count(id) == 1,
                        ExcMessage("Block " + std::to_string(id) +
                                   " (material id " + std::to_string(id) +
                                   " in the mesh) has no material: list it "
                                   "in 'Material/Block materials'."));
            material = materials.at(id);
          }
        blocks.push_back(
          std::make_unique<Block<dim>>(material,
                                       parameters.discretisation,
                                       parameters.linear_solver.package,
                                       id));
        extract_block(mesh, id, blocks.back()->triangulation);
        blocks.back()->set_initial_state(&parameters.in_situ_stress,
                                         &parameters.excavation);
        blocks.back()->set_plasticity(parameters.plasticity);
        const InSituStress &in_situ = parameters.in_situ_stress;
        AssertThrow(!in_situ.enabled ||
                      std::abs(material.unit_weight - in_situ.unit_weight) <=
                        1e-12 * std::max(in_situ.unit_weight, 1.),
                    ExcMessage(
                      "Block " + std::to_string(id) + " weighs " +
                      std::to_string(material.unit_weight) +
                      " per volume, but 'In-situ stress/Unit weight' is " +
                      std::to_string(in_situ.unit_weight) +
                      ": the in-situ stress would not be in equilibrium with "
                      "gravity. Make them equal."));
      }
    for (const auto &[id, material] : materials)
      AssertThrow(std::any_of(blocks.begin(),
                              blocks.end(),
                              [id = id](const auto &b) { return b->id == id; }),
                  ExcMessage("Material/Block materials lists block " +
                             std::to_string(id) +
                             ", which is not a material id of the mesh."));

    std::set<types::boundary_id> present;
    for (const auto &block : blocks)
      for (const auto id : boundary_ids_of(block->triangulation))
        present.insert(id);
    parameters.boundary_conditions.check_boundary_ids(present);
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::setup_blocks()
  {
    // The monolithic formulation alone factorises no block: its one system
    // holds them all.
    const bool factorise = parameters.contact.interfaces.empty() ||
                           parameters.contact.runs_condensed();
    parameters.boundary_conditions.set_time(0.);
    for (const auto &block : blocks)
      {
        {
          TimerOutput::Scope t(timer, "assembly");
          block->setup_system(parameters.boundary_conditions);
          if (factorise)
            block->assemble_stiffness();
        }
        if (factorise)
          {
            TimerOutput::Scope t(timer, "factorisation");
            Timer              clock;
            block->factorize();
            condensed_seconds += clock.wall_time();
          }
      }
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::run()
  {
    make_blocks();
    setup_blocks();

    const auto &first = *blocks.front();
    pcout << "mbfem: "
          << (blocks.size() == 1 ?
                (parameters.plasticity.enabled ? "one elastic-plastic block" :
                                                 "one elastic block") :
                std::to_string(blocks.size()) + " blocks")
          << ", " << dim << "D" << (dim == 2 ? " plane strain" : "")
          << ", FE_Q(" << first.fe.degree << ")^" << dim << ", MappingQ("
          << first.mapping.get_degree() << ")\n";
    for (const auto &block : blocks)
      {
        pcout << (blocks.size() == 1 ? "" : "  " + block->name() + ":\n")
              << "  cells: " << block->triangulation.n_active_cells()
              << ", degrees of freedom: " << block->n_dofs() << "\n"
              << "  E = " << block->material.youngs_modulus
              << ", nu = " << block->material.poissons_ratio << "\n";
        const auto &free_modes = block->free_rigid_body_modes();
        if (!free_modes.empty())
          {
            pcout << "  floating: free rigid-body modes";
            for (const auto &mode : free_modes)
              pcout << " [" << Block<dim>::describe_rigid_body_mode(mode)
                    << "]";
            pcout << ", held by contact\n";
          }
      }

    std::vector<ContactPair<dim>> pairs;
    if (!parameters.contact.interfaces.empty())
      pairs = find_contact_pairs(blocks, parameters.contact, pcout);

    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        const auto  free_modes = blocks[b]->free_rigid_body_modes();
        std::string description;
        for (const auto &mode : free_modes)
          description +=
            " [" + Block<dim>::describe_rigid_body_mode(mode) + "]";
        const bool has_pairs =
          std::any_of(pairs.begin(), pairs.end(), [b](const auto &pair) {
            return pair.a.block == b || pair.b.block == b;
          });
        AssertThrow(
          free_modes.empty() || has_pairs,
          ExcMessage(
            blocks[b]->name() + " is not held: its supports " +
            "('Boundary conditions/...') leave " +
            std::to_string(free_modes.size()) + " rigid-body mode(s) free," +
            description +
            ", and it has no contact pair that could hold it. "
            "Prescribe the displacement components that remove "
            "them, or declare its interfaces in 'Contact/Interfaces'."));
      }

    const ContactParameters &contact_parameters = parameters.contact;
    AssertThrow(!parameters.plasticity.newton || pairs.empty() ||
                  !contact_parameters.runs_monolithic(),
                ExcMessage(
                  "'Plasticity/Method = Newton' works with the condensed "
                  "contact formulation only (its tangent flexibilities); "
                  "set 'Contact/Formulation = condensed' or use the "
                  "initial-stress method."));
    if (!pairs.empty())
      {
        const std::string &package = parameters.linear_solver.package;
        if (contact_parameters.runs_condensed())
          {
            TimerOutput::Scope t(timer, "flexibility");
            Timer              clock;
            contact = std::make_unique<ContactSolver<dim>>(
              pairs,
              parameters.contact.max_iterations,
              ContactFormulation::condensed,
              package);
            contact->setup(blocks);
            condensed_seconds += clock.wall_time();
          }
        if (contact_parameters.runs_monolithic())
          {
            TimerOutput::Scope t(timer, "monolithic assembly");
            Timer              clock;
            auto               solver = std::make_unique<ContactSolver<dim>>(
              pairs,
              parameters.contact.max_iterations,
              ContactFormulation::monolithic,
              package);
            solver->setup(blocks);
            monolithic_seconds += clock.wall_time();
            (contact_parameters.runs_condensed() ? reference : contact) =
              std::move(solver);
          }
        pcout << "  contact formulation: "
              << (!contact_parameters.runs_monolithic() ? "condensed" :
                  !contact_parameters.runs_condensed()  ? "monolithic" :
                                                          "both");
        if (contact_parameters.runs_monolithic())
          {
            types::global_dof_index n = pairs.size() * dim;
            for (const auto &block : blocks)
              n += block->n_dofs();
            pcout << " (monolithic system of " << n << " unknowns)";
          }
        pcout << "\n";
      }

    std::filesystem::create_directories(parameters.output.directory);
    std::unique_ptr<OutputWriter> writer;
    std::unique_ptr<OutputWriter> pair_writer;
    if (parameters.output.write_vtu)
      {
        writer = std::make_unique<OutputWriter>(parameters.output);
        if (contact)
          {
            OutputParameters pair_output = parameters.output;
            pair_output.base_name += "-pairs";
            pair_writer = std::make_unique<OutputWriter>(pair_output);
          }
      }

    const LoadHistory &history = parameters.load_history;
    // With an in-situ stress, increment 0 is the geostatic stage at t = 0:
    // nothing released yet, zero displacement, the interfaces in the
    // compression of sigma_0.
    const unsigned int first_increment =
      parameters.in_situ_stress.enabled ? 0 : 1;
    for (unsigned int k = first_increment; k <= history.n_increments; ++k)
      {
        const double                time       = history.time(k);
        unsigned int                iterations = 0, reference_iterations = 0;
        const PlasticityParameters &plasticity         = parameters.plasticity;
        unsigned int                plastic_iterations = 0;
        PlasticUpdate               plastic_update;
        plastic_iterations =
          solve_increment(k, iterations, reference_iterations, plastic_update);
        for (const auto &block : blocks)
          block->commit_plastic_strain();
        if (dim == 3 && contact && contact->count(ContactState::slip) > 0)
          pcout << "    friction against the slip made: largest angle "
                << std::fixed << std::setprecision(1) << contact->misalignment()
                << " degrees" << std::defaultfloat << std::setprecision(6)
                << "\n";
        for (const auto &block : blocks)
          AssertThrow(std::isfinite(block->solution.l2_norm()),
                      ExcMessage(
                        "Increment " + std::to_string(k) +
                        " (t = " + std::to_string(time) +
                        "): the displacement of " + block->name() +
                        " is not finite. A load or prescribed displacement "
                        "function gives NaN or inf at this time. Results of "
                        "the earlier increments are in " +
                        parameters.output.directory + "."));

        print_increment(k, time, iterations);
        if (plasticity.enabled)
          pcout << "    plasticity: " << plastic_iterations
                << " iteration(s), yielded " << plastic_update.n_yielded
                << " of " << plastic_update.n_points << " quadrature points ("
                << (dim == 2 ? "area " : "volume ") << std::scientific
                << std::setprecision(6) << plastic_update.yielded_measure
                << "), largest equivalent plastic strain "
                << plastic_update.max_equivalent << std::defaultfloat
                << std::setprecision(6) << "\n";
        if (reference)
          compare_formulations();
        std::string pair_file;
        if (contact)
          {
            pair_file = write_pairs(k, time);
            write_summary(k, time, iterations, reference_iterations);
            contact->commit();
            if (reference)
              reference->commit();
          }
        if (writer)
          {
            TimerOutput::Scope       t(timer, "output");
            std::vector<std::string> files;
            for (unsigned int b = 0; b < blocks.size(); ++b)
              files.push_back(
                writer->write_block(*blocks[b], blocks[b]->id, k));
            writer->add_step(time, files);
            if (pair_writer)
              pair_writer->add_step(time, {pair_file});
          }
      }

    if (newton_suspensions > 0)
      pcout << "  Newton's tangent system had no solution in "
            << newton_suspensions << " step(s); the elastic stiffness "
            << "(initial-stress method) took over in them\n";
    if (contact)
      print_interface_summary();
    if (reference)
      {
        const bool agree =
          state_differences == 0 && largest_force_difference <= 1e-6 &&
          largest_gap_difference <= 1e-6 && largest_slip_difference <= 1e-6;
        pcout << "  condensed against monolithic over all increments: "
              << "states equal at every increment "
              << (state_differences == 0 ? "yes" : "NO")
              << "; largest differences (relative): forces "
              << format_difference(largest_force_difference) << ", gaps "
              << format_difference(largest_gap_difference) << ", slips "
              << format_difference(largest_slip_difference) << "; within 1e-6 "
              << (agree ? "yes" : "NO") << "\n";
      }
    if (contact && !parameters.run.test_mode)
      {
        pcout << "  time of the contact formulation(s) alone (wall, s): ";
        if (parameters.contact.runs_condensed())
          pcout << "condensed " << std::setprecision(3) << condensed_seconds
                << " (factorisation, flexibility, load response, contact "
                   "iterations, recovery)";
        if (parameters.contact.runs_condensed() &&
            parameters.contact.runs_monolithic())
          pcout << "; ";
        if (parameters.contact.runs_monolithic())
          pcout << "monolithic " << std::setprecision(3) << monolithic_seconds
                << " (assembly, contact iterations with one sparse LU "
                   "each, recovery)";
        pcout << std::setprecision(6) << "\n";
      }
    if (parameters.exact_solution.enabled)
      print_errors(history.time(history.n_increments));

    if (writer)
      pcout << "  wrote " << history.n_increments << " VTU file(s)"
            << (blocks.size() > 1 ? " per block" : "") << " indexed by "
            << writer->pvd_file() << "\n";
    if (contact && !parameters.run.test_mode)
      pcout << "  contact pairs per increment in "
            << parameters.output.directory << "/" << parameters.output.base_name
            << "-pairs-*.csv, a line per increment in "
            << parameters.output.directory << "/" << parameters.output.base_name
            << "-summary.csv\n";
    if (!parameters.run.test_mode)
      timer.print_summary();
  }



  template <int dim>
  unsigned int
  MultiBodyProblem<dim>::solve_increment(const unsigned int k,
                                         unsigned int      &iterations,
                                         unsigned int  &reference_iterations,
                                         PlasticUpdate &plastic_update)
  {
    // A failed increment may be retried from its start in steps of half
    // the size ('Load history/Maximum step halvings'); the steps before
    // the last are committed like increments. Only the failures a smaller
    // step can cure are retried (Exceptions::ExcIncrementNotConverged,
    // ExcNoEquilibrium); the message that ends the run is the first
    // failure's, at the increment's own size, not the last retry's.
    const LoadHistory &history = parameters.load_history;
    const double       time    = history.time(k);
    const double       start   = (k == 0 ? 0. : history.time(k - 1));
    double             reached = start, step = time - start;
    unsigned int       halvings = 0, n_steps = 0, plastic_iterations = 0;
    std::string        first_failure;
    const auto on_failure = [&](const auto &failure, const double target) {
      if (first_failure.empty())
        first_failure = message_of(failure);
      if (halvings == history.max_halvings)
        {
          if (history.max_halvings == 0)
            throw;
          using Failure = std::decay_t<decltype(failure)>;
          throw Failure(first_failure +
                        "    The increment was also tried in steps down to 1/" +
                        std::to_string(1u << halvings) +
                        " of its size ('Load history/Maximum step halvings = " +
                        std::to_string(history.max_halvings) +
                        "'). Results of the earlier increments are in " +
                        parameters.output.directory + ".");
        }
      for (const auto &block : blocks)
        block->restore_plastic_state();
      ++halvings;
      step                     = (target - reached) / 2.;
      const std::string reason = message_of(failure);
      pcout << "    step to t = " << target << " failed ("
            << reason.substr(0, reason.find('\n')) << "); halving " << halvings
            << " of " << history.max_halvings << ": steps of " << step << "\n";
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
      pcout << "    increment " << k << " reached in " << n_steps << " steps\n";
    return plastic_iterations;
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::commit_step()
  {
    for (const auto &block : blocks)
      block->commit_plastic_strain();
    if (contact)
      contact->commit();
    if (reference)
      reference->commit();
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::solve_pass(const unsigned int k,
                                    const double       time,
                                    unsigned int      &iterations,
                                    unsigned int      &reference_iterations,
                                    const bool         from_last_solve)
  {
    const bool condensed =
      !contact || contact->formulation() == ContactFormulation::condensed;
    {
      TimerOutput::Scope t(timer, "load response");
      for (const auto &block : blocks)
        {
          block->assemble_load(parameters.boundary_conditions, time);
          if (condensed)
            {
              Timer clock;
              block->solve();
              condensed_seconds += clock.wall_time();
            }
        }
    }
    if (contact)
      {
        {
          TimerOutput::Scope t(timer, "contact iterations");
          Timer              clock;
          iterations = contact->solve_increment(blocks, k, from_last_solve);
          last_contact_seconds = clock.wall_time();
          (condensed ? condensed_seconds : monolithic_seconds) +=
            last_contact_seconds;
        }
        if (reference)
          {
            TimerOutput::Scope t(timer, "monolithic reference");
            Timer              clock;
            reference_iterations   = reference->solve_increment(blocks, k);
            last_reference_seconds = clock.wall_time();
            monolithic_seconds += last_reference_seconds;
          }
        TimerOutput::Scope t(timer, "field recovery");
        Timer              clock;
        for (unsigned int b = 0; b < blocks.size(); ++b)
          if (condensed)
            {
              std::vector<types::global_dof_index> dofs;
              std::vector<double>                  forces;
              contact->forces_on_block(b, dofs, forces);
              blocks[b]->add_point_forces(dofs, forces);
              blocks[b]->solve(contact->floating_amplitudes(b));
            }
          else
            contact->block_solution(b, *blocks[b], blocks[b]->solution);
        (condensed ? condensed_seconds : monolithic_seconds) +=
          clock.wall_time();
      }
  }



  template <int dim>
  unsigned int
  MultiBodyProblem<dim>::solve_step(const unsigned int k,
                                    const double       time,
                                    unsigned int      &iterations,
                                    unsigned int      &reference_iterations,
                                    PlasticUpdate     &plastic_update)
  {
    // Plastic blocks: the increment is repeated with the plastic strain
    // of the last pass as a load until that strain settles (the
    // initial-stress method); elastic blocks pass once.
    const PlasticityParameters &plasticity         = parameters.plasticity;
    unsigned int                plastic_iterations = 0;
    double                      previous_change    = 0.;
    double                      omega              = 1.;
    // Newton may give way to the initial-stress method for the rest of
    // the step (see Block::suspend_newton()).
    bool newton = plasticity.newton;
    for (const auto &block : blocks)
      block->suspend_newton(false);
    for (;;)
      {
        // Newton: the contact states of the last pass start the next.
        const bool from_last_solve =
          plasticity.newton && plastic_iterations > 0;
        bool solved = false;
        if (newton)
          try
            {
              update_tangent_stiffness();
              solve_pass(
                k, time, iterations, reference_iterations, from_last_solve);
              solved = true;
            }
          catch (const Exceptions::ExcNoEquilibrium &e)
            {
              newton = give_way_to_initial_stress(e, plastic_iterations);
            }
          catch (const Exceptions::ExcSingularMatrix &e)
            {
              newton = give_way_to_initial_stress(e, plastic_iterations);
            }
        if (!solved)
          {
            // (Reassembles only after a suspension: the elastic stiffness.)
            update_tangent_stiffness();
            solve_pass(
              k, time, iterations, reference_iterations, from_last_solve);
          }

        if (!plasticity.enabled)
          break;
        ++plastic_iterations;
        plastic_update = PlasticUpdate();
        {
          TimerOutput::Scope t(timer, "plasticity");
          for (const auto &block : blocks)
            plastic_update += block->update_plastic_strain();
        }
        const double change = std::sqrt(plastic_update.change2 /
                                        std::max(plastic_update.norm2, 1e-300));
        // The initial-stress iteration converges linearly, at a rate
        // that nears 1 as the plastic zone grows: what is left to go is
        // about change * rate / (1 - rate), not the change itself.
        const double rate =
          (previous_change > 0. ? change / previous_change : 0.);
        previous_change = change;
        // Progress on long runs: a line every 100 iterations, or every
        // Newton iteration (few, each with new factorisations).
        if (newton && !parameters.run.test_mode)
          pcout << "    Newton iteration " << plastic_iterations
                << ": residual " << std::scientific << std::setprecision(3)
                << change << std::defaultfloat << ", "
                << plastic_update.n_yielded << " points yielded"
                << std::setprecision(6) << "\n";
        else if (plastic_iterations % 100 == 0 && !parameters.run.test_mode)
          pcout << "    plastic iteration " << plastic_iterations << ": change "
                << std::scientific << std::setprecision(3) << change
                << ", relaxation " << std::defaultfloat << omega << ", "
                << plastic_update.n_yielded << " points yielded"
                << std::setprecision(6) << "\n";
        const double remaining =
          (rate < 1. ? change * std::max(rate / (1. - rate), 1.) :
                       change * 1e3);
        if (plastic_update.change2 == 0. || remaining < plasticity.tolerance)
          break;
        AssertThrow(
          plastic_iterations < plasticity.max_iterations,
          Exceptions::ExcIncrementNotConverged(
            "Increment " + std::to_string(k) + " (t = " + std::to_string(time) +
            "): the plastic strain still changes " + "by " +
            std::to_string(change) + " (relative) after " +
            std::to_string(plastic_iterations) +
            " iterations ('Plasticity/Maximum iterations'). The rock may "
            "be failing (no equilibrium with this strength), or the "
            "increment is too large: use more load increments. Results "
            "of the earlier increments are in " +
            parameters.output.directory + "."));

        // Aitken's relaxation of the fixed point x = F(x): omega from
        // the last two residuals (plain steps converge at a rate near 1
        // once the plastic zone is large, e.g. with dilatancy).
        if (newton)
          continue; // the new tangent goes in before the next pass
        omega = (!plasticity.aitken || plastic_iterations == 1 ||
                     plastic_update.aitken_denominator <= 0. ?
                   1. :
                   std::min(20.,
                            std::max(0.05,
                                     -omega * plastic_update.aitken_numerator /
                                       plastic_update.aitken_denominator)));
        for (const auto &block : blocks)
          block->relax_plastic_strain(omega);
      }
    return plastic_iterations;
  }



  template <int dim>
  bool
  MultiBodyProblem<dim>::give_way_to_initial_stress(
    const ExceptionBase &failure,
    const unsigned int   plastic_iterations)
  {
    // The tangent of perfect plasticity is singular along the flow; with
    // slipping pairs around a yielded band the condensed system can be too,
    // while the elastic one is not.
    bool suspended = false;
    for (const auto &block : blocks)
      suspended = block->suspend_newton(true) || suspended;
    if (!suspended)
      throw; // the elastic stiffness would fail alike: not Newton's fault
    ++newton_suspensions;
    const std::string reason = message_of(failure);
    if (!parameters.run.test_mode)
      pcout << "    Newton iteration " << plastic_iterations + 1
            << ": no solution with the tangent stiffness ("
            << reason.substr(0, reason.find('\n'))
            << "); the rest of the step uses the elastic stiffness "
            << "(initial-stress method)\n";
    return false;
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::update_tangent_stiffness()
  {
    bool changed = false;
    for (const auto &block : blocks)
      if (block->tangent_changed())
        {
          changed = true;
          {
            TimerOutput::Scope t(timer, "assembly");
            block->assemble_stiffness();
          }
          TimerOutput::Scope t(timer, "factorisation");
          Timer              clock;
          block->factorize();
          condensed_seconds += clock.wall_time();
        }
    if (changed && contact)
      {
        TimerOutput::Scope t(timer, "flexibility");
        Timer              clock;
        contact->setup(blocks);
        condensed_seconds += clock.wall_time();
      }
  }



  template <int dim>
  double
  MultiBodyProblem<dim>::max_slip(const ContactSolver<dim> &solver)
  {
    double largest = 0.;
    for (unsigned int k = 0; k < solver.pairs().size(); ++k)
      largest = std::max(largest, solver.slip(k).norm());
    return largest;
  }



  template <int dim>
  std::string
  MultiBodyProblem<dim>::format_difference(const double e) const
  {
    std::ostringstream s;
    if (e < 1e-9 && parameters.run.test_mode)
      s << "below 1e-9";
    else
      s << std::scientific << std::setprecision(2) << e;
    return s.str();
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::compare_formulations()
  {
    // Forces relative to the largest pair force; gaps and slips relative to
    // the largest displacement of the model (while all pairs stick, gaps
    // and slips are round-off of zero and cannot be their own scale).
    const unsigned int n_pairs     = contact->pairs().size();
    double             force_scale = 1e-300, displacement_scale = 1e-300;
    for (unsigned int i = 0; i < n_pairs; ++i)
      force_scale = std::max(force_scale, contact->local_force(i).norm());
    for (const auto &block : blocks)
      displacement_scale =
        std::max(displacement_scale, block->max_displacement());
    double       force = 0., gap = 0., slip = 0.;
    unsigned int differ = 0;
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        if (contact->state(i) != reference->state(i) ||
            contact->broken(i) != reference->broken(i))
          ++differ;
        force = std::max(
          force,
          (contact->local_force(i) - reference->local_force(i)).norm() /
            force_scale);
        gap  = std::max(gap,
                       std::abs(contact->gap(i) - reference->gap(i)) /
                         displacement_scale);
        slip = std::max(slip,
                        (contact->slip(i) - reference->slip(i)).norm() /
                          displacement_scale);
      }
    largest_force_difference = std::max(largest_force_difference, force);
    largest_gap_difference   = std::max(largest_gap_difference, gap);
    largest_slip_difference  = std::max(largest_slip_difference, slip);
    state_differences += differ;
    last_comparison = {{static_cast<double>(differ), force, gap, slip}};

    // Round-off differences vary by machine: below 1e-9 they are printed as
    // such, so that the tests compare what matters.
    const auto difference = [this](const double e) {
      return format_difference(e);
    };
    pcout << "    monolithic reference: stick/slip/open "
          << reference->count(ContactState::stick) << "/"
          << reference->count(ContactState::slip) << "/"
          << reference->count(ContactState::open) << ", states differ at "
          << differ << " of " << n_pairs << " pairs; differences (relative) "
          << "forces " << difference(force) << ", gaps " << difference(gap)
          << ", slips " << difference(slip) << "\n";
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::write_summary(const unsigned int k,
                                       const double       time,
                                       const unsigned int iterations,
                                       const unsigned int reference_iterations)
  {
    if (summary_csv.empty())
      {
        summary_csv = "# " + to_string(contact->formulation()) +
                      " formulation" +
                      (reference ? " with the monolithic reference" : "") +
                      "; slip = tangential relative displacement; seconds = "
                      "wall time of the increment's contact iterations; "
                      "method = which state iteration concluded the "
                      "increment (fast or load path)\n";
        summary_csv += "increment,t,iterations,stick,slip,open,max_gap,"
                       "max_slip,max_normal_traction,seconds,method,"
                       "fast_iterations,path_switches";
        if (reference)
          summary_csv += ",reference_iterations,reference_seconds,"
                         "states_differ,force_difference,gap_difference,"
                         "slip_difference";
        summary_csv += "\n";
      }
    double max_gap = 0., max_p = 0.;
    for (unsigned int i = 0; i < contact->pairs().size(); ++i)
      {
        max_gap = std::max(max_gap, contact->gap(i));
        max_p   = std::max(max_p,
                         contact->local_force(i)[0] / contact->pairs()[i].area);
      }
    char buffer[256];
    std::snprintf(buffer,
                  sizeof(buffer),
                  "%u,%.10g,%u,%u,%u,%u,%.10e,%.10e,%.10e,%.4f",
                  k,
                  time,
                  iterations,
                  contact->count(ContactState::stick),
                  contact->count(ContactState::slip),
                  contact->count(ContactState::open),
                  max_gap,
                  max_slip(*contact),
                  max_p,
                  last_contact_seconds);
    summary_csv += buffer;
    // Which method concluded the state iteration, and its share of the
    // iterations (doc/state_iteration.md).
    summary_csv += "," + to_string(contact->last_method()) + "," +
                   std::to_string(contact->last_iterations().first) + "," +
                   std::to_string(contact->last_iterations().second);
    if (reference)
      {
        std::snprintf(buffer,
                      sizeof(buffer),
                      ",%u,%.4f,%u,%.3e,%.3e,%.3e",
                      reference_iterations,
                      last_reference_seconds,
                      static_cast<unsigned int>(last_comparison[0]),
                      last_comparison[1],
                      last_comparison[2],
                      last_comparison[3]);
        summary_csv += buffer;
      }
    summary_csv += "\n";
    write_file_atomically(parameters.output.directory + "/" +
                            parameters.output.base_name + "-summary.csv",
                          summary_csv);
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_increment(const unsigned int k,
                                         const double       time,
                                         const unsigned int iterations) const
  {
    double max_u = 0., max_von_mises = 0.;
    for (const auto &block : blocks)
      {
        max_u         = std::max(max_u, block->max_displacement());
        max_von_mises = std::max(max_von_mises, block->max_von_mises_stress());
      }
    pcout << "  increment " << k << "/" << parameters.load_history.n_increments
          << ", t = " << time << ": ";
    if (contact)
      {
        double min_normal = 0., max_normal = 0., max_tangential = 0.,
               max_gap = 0.;
        for (unsigned int i = 0; i < contact->pairs().size(); ++i)
          {
            if (contact->pairs()[i].tied)
              continue; // its frame is the global axes
            const Tensor<1, dim> rho        = contact->local_force(i);
            const double         area       = contact->pairs()[i].area;
            Tensor<1, dim>       tangential = rho;
            tangential[0]                   = 0.;
            min_normal     = std::min(min_normal, rho[0] / area);
            max_normal     = std::max(max_normal, rho[0] / area);
            max_tangential = std::max(max_tangential, tangential.norm() / area);
            max_gap        = std::max(max_gap, contact->gap(i));
          }
        // Which method concluded the state iteration: named only where
        // the fast iteration did not (the screen lines of the increments
        // it concludes stay as they were).
        pcout << iterations << " iteration(s)";
        if (contact->last_method() != StateMethod::fast)
          pcout << " (fast " << contact->last_iterations().first << ", "
                << to_string(contact->last_method()) << " "
                << contact->last_iterations().second << ")";
        pcout << ", stick/slip/open " << contact->count(ContactState::stick)
              << "/" << contact->count(ContactState::slip) << "/"
              << contact->count(ContactState::open) << ", p in ["
              << std::scientific << std::setprecision(6) << min_normal << ", "
              << max_normal << "], max |q| = " << max_tangential
              << ", max gap = " << max_gap
              << ", max slip = " << max_slip(*contact) << ", ";
      }
    pcout << "max |u| = " << std::scientific << std::setprecision(6) << max_u
          << ", max von Mises = " << max_von_mises << std::defaultfloat
          << std::setprecision(6) << "\n";

    // The resultant each interface transmits (force on its side b).
    if (contact)
      for (unsigned int i = 0; i < parameters.contact.interfaces.size(); ++i)
        {
          Tensor<1, dim> resultant;
          for (unsigned int p = 0; p < contact->pairs().size(); ++p)
            if (contact->pairs()[p].interface == i)
              resultant += contact->force(p);
          pcout << "    interface " << i + 1 << ": resultant force on side b ("
                << std::scientific << std::setprecision(6);
          for (unsigned int d = 0; d < dim; ++d)
            pcout << (d > 0 ? ", " : "")
                  << (std::abs(resultant[d]) < 1e-12 * resultant.norm() ?
                        0. :
                        resultant[d]);
          pcout << ")" << std::defaultfloat << std::setprecision(6) << "\n";
        }
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_interface_summary() const
  {
    const auto &pairs = contact->pairs();
    const auto &data  = parameters.contact;
    for (unsigned int i = 0; i < data.interfaces.size(); ++i)
      {
        double p_max = 0., q_max = 0., p_error2 = 0., p_norm2 = 0.,
               q_error2 = 0., q_norm2 = 0.;
        // The same measured against the closed form averaged over each
        // pair's tributary segment: force / area is such an average, which
        // matters where the traction is not smooth (the contact edge).
        double p_error2_avg = 0., q_error2_avg = 0.;
        double closed[2] = {1e300, -1e300}, stuck[2] = {1e300, -1e300};
        for (unsigned int k = 0; k < pairs.size(); ++k)
          if (pairs[k].interface == i)
            {
              const Tensor<1, dim> rho =
                contact->local_force(k) / pairs[k].area;
              Tensor<1, dim> q = rho;
              q[0]             = 0.;
              p_max            = std::max(p_max, rho[0]);
              q_max            = std::max(q_max, q.norm());
              const double x   = pairs[k].midpoint()[0];
              if (contact->state(k) != ContactState::open)
                {
                  closed[0] = std::min(closed[0], x);
                  closed[1] = std::max(closed[1], x);
                }
              if (contact->state(k) == ContactState::stick)
                {
                  stuck[0] = std::min(stuck[0], x);
                  stuck[1] = std::max(stuck[1], x);
                }
              if (dim == 2 && data.compute_traction_errors)
                {
                  const Point<2> point(x, pairs[k].midpoint()[1]);
                  const double   p_exact =
                    data.exact_normal_traction->value(point);
                  const double q_exact =
                    data.exact_tangential_traction->value(point);
                  p_error2 += pairs[k].area * std::pow(rho[0] - p_exact, 2);
                  p_norm2 += pairs[k].area * p_exact * p_exact;
                  q_error2 += pairs[k].area * std::pow(rho[1] - q_exact, 2);
                  q_norm2 += pairs[k].area * q_exact * q_exact;

                  // Midpoint rule with 64 points along the tangent.
                  Tensor<1, 2> tangent;
                  tangent[0]       = pairs[k].frame[1][0];
                  tangent[1]       = pairs[k].frame[1][1];
                  double p_average = 0., q_average = 0.;
                  for (unsigned int j = 0; j < 64; ++j)
                    {
                      const Point<2> y = point + ((j + 0.5) / 64 - 0.5) *
                                                   pairs[k].area * tangent;
                      p_average += data.exact_normal_traction->value(y) / 64;
                      q_average +=
                        data.exact_tangential_traction->value(y) / 64;
                    }
                  p_error2_avg +=
                    pairs[k].area * std::pow(rho[0] - p_average, 2);
                  q_error2_avg +=
                    pairs[k].area * std::pow(rho[1] - q_average, 2);
                }
            }
        const auto span = [](const double range[2]) {
          std::ostringstream s;
          if (range[0] > range[1])
            s << "none";
          else
            s << std::fixed << std::setprecision(5) << "x from " << range[0]
              << " to " << range[1] << " (half-width "
              << 0.5 * (range[1] - range[0]) << ")";
          return s.str();
        };
        // Table 1 at the end: slipping pairs on the Mohr-Coulomb cone,
        // stuck pairs inside it (to 1e-8 of the largest pair force).
        double largest_force = 0., off_cone = 0., outside = 0.;
        for (unsigned int k = 0; k < pairs.size(); ++k)
          if (pairs[k].interface == i)
            largest_force =
              std::max(largest_force, contact->local_force(k).norm());
        for (unsigned int k = 0; k < pairs.size(); ++k)
          if (pairs[k].interface == i && !pairs[k].tied &&
              contact->state(k) != ContactState::open)
            {
              const Tensor<1, dim> rho        = contact->local_force(k);
              Tensor<1, dim>       tangential = rho;
              tangential[0]                   = 0.;
              const double limit =
                pairs[k].joint.shear_strength(rho[0],
                                              pairs[k].area,
                                              contact->broken(k));
              if (contact->state(k) == ContactState::slip)
                off_cone =
                  std::max(off_cone, std::abs(tangential.norm() - limit));
              else
                outside = std::max(outside, tangential.norm() - limit);
            }
        const double tolerance = 1e-8 * std::max(largest_force, 1e-300);
        pcout << "  interface " << i + 1
              << " at the end: max p = " << std::setprecision(6) << p_max
              << ", max |q| = " << q_max
              << "\n    closed pairs: " << span(closed)
              << "\n    stuck pairs:  " << span(stuck) << "\n"
              << "    Coulomb: slipping pairs on the cone "
              << (off_cone <= tolerance ? "yes" : "NO")
              << ", stuck pairs inside it "
              << (outside <= tolerance ? "yes" : "NO") << "\n";
        // Where the exact q is zero (a geostatic joint), q is measured
        // against the size of p instead.
        if (q_norm2 == 0.)
          q_norm2 = p_norm2;
        if (dim == 2 && data.compute_traction_errors)
          pcout << "    relative L2 error against Contact/Exact traction: p "
                << std::fixed << std::setprecision(4)
                << std::sqrt(p_error2 / std::max(p_norm2, 1e-300)) << ", q "
                << std::sqrt(q_error2 / std::max(q_norm2, 1e-300))
                << " (at the pairs); p "
                << std::sqrt(p_error2_avg / std::max(p_norm2, 1e-300)) << ", q "
                << std::sqrt(q_error2_avg / std::max(q_norm2, 1e-300))
                << " (averaged over each pair's area)" << std::defaultfloat
                << std::setprecision(6) << "\n";
      }
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_errors(const double time) const
  {
    parameters.exact_solution.displacement->set_time(time);
    parameters.exact_solution.stress->set_time(time);
    double u_error2 = 0., u_norm2 = 0., s_error2 = 0., s_norm2 = 0.;
    for (const auto &block : blocks)
      {
        const ErrorNorms e =
          block->compute_errors(*parameters.exact_solution.displacement,
                                *parameters.exact_solution.stress);
        u_error2 += e.displacement * e.displacement;
        s_error2 += e.stress * e.stress;
        if (e.displacement_relative > 0.)
          u_norm2 += std::pow(e.displacement / e.displacement_relative, 2);
        if (e.stress_relative > 0.)
          s_norm2 += std::pow(e.stress / e.stress_relative, 2);
      }
    const double u_relative = std::sqrt(u_error2 / std::max(u_norm2, 1e-300));
    const double s_relative = std::sqrt(s_error2 / std::max(s_norm2, 1e-300));
    pcout << "  L2 errors against the exact solution (relative): "
          << "displacement " << std::scientific << std::setprecision(3)
          << u_relative << ", stress " << s_relative << std::defaultfloat
          << std::setprecision(6) << "\n";

    // numdiff takes numbers within 1e-6 of each other as equal, which
    // would let any change of a small error pass: compare logarithms.
    // Below 1e-9 an error is round-off, whose digits vary by machine.
    if (parameters.run.test_mode)
      {
        const auto log_error = [](const double e) {
          std::ostringstream s;
          if (e < 1e-9)
            s << "below 1e-9";
          else
            s << std::fixed << std::setprecision(4) << std::log10(e);
          return s.str();
        };
        pcout << "  log10 of the relative errors: displacement "
              << log_error(u_relative) << ", stress " << log_error(s_relative)
              << "\n";
      }
  }



  template <int dim>
  std::string
  MultiBodyProblem<dim>::write_pairs(const unsigned int k,
                                     const double       time) const
  {
    const auto       &pairs = contact->pairs();
    const std::string stem =
      parameters.output.base_name + "-pairs-" + Utilities::int_to_string(k, 4);
    const char        *axes[] = {"x", "y", "z"};
    std::ostringstream csv;
    csv << "# increment " << k << ", t = " << time << "\n";
    csv << "pair,interface";
    for (unsigned int d = 0; d < dim; ++d)
      csv << "," << axes[d];
    csv << ",normal_force,normal_traction";
    for (unsigned int d = 1; d < dim; ++d)
      csv << ",tangential_force_" << d << ",tangential_traction_" << d;
    csv << ",gap";
    for (unsigned int d = 1; d < dim; ++d)
      csv << ",slip_" << d;
    csv << ",state,broken,area,initial_gap\n";

    std::ostringstream points, state, traction, gap, slip, normal;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const auto          &pair = pairs[i];
        const Point<dim>     x    = pair.midpoint();
        const Tensor<1, dim> rho  = contact->local_force(i);
        const Tensor<1, dim> s    = contact->slip(i);
        char                 buffer[64];
        csv << i << "," << pair.interface + 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            std::snprintf(buffer, sizeof(buffer), ",%.10e", x[d]);
            csv << buffer;
          }
        std::snprintf(
          buffer, sizeof(buffer), ",%.10e,%.10e", rho[0], rho[0] / pair.area);
        csv << buffer;
        for (unsigned int d = 1; d < dim; ++d)
          {
            std::snprintf(buffer,
                          sizeof(buffer),
                          ",%.10e,%.10e",
                          rho[d],
                          rho[d] / pair.area);
            csv << buffer;
          }
        std::snprintf(buffer, sizeof(buffer), ",%.10e", contact->gap(i));
        csv << buffer;
        for (unsigned int d = 1; d < dim; ++d)
          {
            std::snprintf(buffer, sizeof(buffer), ",%.10e", s[d]);
            csv << buffer;
          }
        std::snprintf(
          buffer, sizeof(buffer), ",%.10e,%.10e", pair.area, pair.initial_gap);
        csv << "," << to_string(contact->state(i)) << ","
            << (contact->broken(i) ? 1 : 0) << buffer << "\n";

        // VTU point data, global components.
        const Tensor<1, dim> r = contact->force(i) / pair.area;
        Tensor<1, dim>       slip_global;
        for (unsigned int d = 1; d < dim; ++d)
          slip_global += s[d] * pair.frame[d];
        for (unsigned int d = 0; d < 3; ++d)
          {
            points << (d < dim ? x[d] : 0.) << " ";
            traction << (d < dim ? r[d] : 0.) << " ";
            slip << (d < dim ? slip_global[d] : 0.) << " ";
            normal << (d < dim ? pair.frame[0][d] : 0.) << " ";
          }
        state << static_cast<int>(contact->state(i)) << " ";
        gap << contact->gap(i) << " ";
      }
    write_file_atomically(parameters.output.directory + "/" + stem + ".csv",
                          csv.str());

    if (!parameters.output.write_vtu)
      return "";
    const unsigned int n = pairs.size();
    std::ostringstream vtu;
    vtu << std::setprecision(10)
        << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
           "<UnstructuredGrid><Piece NumberOfPoints=\""
        << n << "\" NumberOfCells=\"" << n << "\">\n"
        << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
           "format=\"ascii\">"
        << points.str() << "</DataArray></Points>\n<Cells>\n"
        << "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">";
    for (unsigned int i = 0; i < n; ++i)
      vtu << i << " ";
    vtu << "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" "
           "format=\"ascii\">";
    for (unsigned int i = 0; i < n; ++i)
      vtu << i + 1 << " ";
    vtu << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
           "format=\"ascii\">";
    for (unsigned int i = 0; i < n; ++i)
      vtu << "1 "; // VTK_VERTEX
    vtu << "</DataArray>\n</Cells>\n<PointData Scalars=\"state\">\n"
        << "<DataArray type=\"Int32\" Name=\"state\" format=\"ascii\">"
        << state.str() << "</DataArray>\n"
        << "<DataArray type=\"Float64\" Name=\"traction\" "
           "NumberOfComponents=\"3\" format=\"ascii\">"
        << traction.str() << "</DataArray>\n"
        << "<DataArray type=\"Float64\" Name=\"gap\" format=\"ascii\">"
        << gap.str() << "</DataArray>\n"
        << "<DataArray type=\"Float64\" Name=\"slip\" NumberOfComponents=\"3\" "
           "format=\"ascii\">"
        << slip.str() << "</DataArray>\n"
        << "<DataArray type=\"Float64\" Name=\"normal\" "
           "NumberOfComponents=\"3\" format=\"ascii\">"
        << normal.str() << "</DataArray>\n"
        << "</PointData>\n</Piece></UnstructuredGrid>\n</VTKFile>\n";
    write_file_atomically(parameters.output.directory + "/" + stem + ".vtu",
                          vtu.str());
    return stem + ".vtu";
  }



  template <int dim>
  const std::vector<std::unique_ptr<Block<dim>>> &
  MultiBodyProblem<dim>::get_blocks() const
  {
    return blocks;
  }



  template <int dim>
  const ContactSolver<dim> *
  MultiBodyProblem<dim>::get_contact() const
  {
    return contact.get();
  }



  template class MultiBodyProblem<2>;
  template class MultiBodyProblem<3>;
} // namespace mbfem

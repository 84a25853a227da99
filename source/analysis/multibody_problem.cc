#include <mbfem/analysis/block_measures.h>
#include <mbfem/analysis/input_checks.h>
#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/parameters.h>
#include <mbfem/base/exceptions.h>
#include <mbfem/base/interruption.h>
#include <mbfem/base/parallel.h>
#include <mbfem/mesh/mesh_checks.h>
#include <mbfem/output/interface_report.h>
#include <mbfem/output/pair_output.h>
#include <mbfem/output/screen_detail.h>

#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <utility>

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
    , comparison(parameters.run.test_mode)
  {}



  template <int dim>
  void
  MultiBodyProblem<dim>::make_blocks()
  {
    TimerOutput::Scope t(timer, "mesh");
    Triangulation<dim> mesh;
    create_mesh(parameters.mesh, mesh);
    // Everything the input names must exist before anything is built.
    check_ids_against_mesh(parameters, mesh);

    const auto &materials = parameters.block_materials;
    const auto &excavated = parameters.excavation.excavated_ids;
    for (const auto id : block_ids(mesh))
      {
        if (std::find(excavated.begin(), excavated.end(), id) !=
            excavated.end())
          continue; // removed rock: not a block
        const Material &material =
          materials.empty() ? parameters.material : materials.at(id);
        blocks.push_back(
          std::make_unique<Block<dim>>(material,
                                       parameters.discretisation,
                                       parameters.linear_solver.package,
                                       id));
        Block<dim> &block = *blocks.back();
        block.extract_mesh(mesh);
        const auto refinements = parameters.mesh.block_refinements.find(id);
        if (refinements != parameters.mesh.block_refinements.end())
          block.refine_mesh(refinements->second);
        check_cell_geometry(block.get_triangulation(),
                            block.get_mapping(),
                            block.get_fe().degree,
                            block.name());
        block.set_initial_state(&parameters.in_situ_stress,
                                &parameters.excavation);
        block.plastic_state().initialize(parameters.plasticity, block);
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
        AssertThrow(!in_situ.enabled ||
                      parameters.boundary_conditions.gravity_ramp_time == 0.,
                    ExcMessage("'Boundary conditions/Gravity ramp time' must "
                               "be 0 with an in-situ stress: sigma_0 is in "
                               "equilibrium with the full weight from the "
                               "start."));
      }
    assign_block_owners();
    check_point_supports(parameters.boundary_conditions,
                         blocks,
                         pcout.get_stream());
    check_functions_are_finite(parameters, blocks);
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::assign_block_owners()
  {
    // Under mpirun each block is factorised and solved on one rank; every
    // rank holds the meshes and runs the contact iteration (doc/parallel.md).
    std::vector<double> costs;
    for (const auto &block : blocks)
      costs.push_back(block->cost());
    const std::vector<unsigned int> owners =
      Parallel::assign_owners(costs, Parallel::n_ranks());
    if (Parallel::n_ranks() > 1)
      for (unsigned int b = 0; b < blocks.size(); ++b)
        blocks[b]->set_owner(MPI_COMM_WORLD, owners[b]);
  }



  template <int dim>
  bool
  MultiBodyProblem<dim>::factorises_blocks() const
  {
    return !parameters.contact.declares_interfaces() ||
           parameters.contact_solver.runs_condensed();
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::setup_blocks()
  {
    parameters.boundary_conditions.set_time(0.);
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (const auto &block : blocks)
        {
          TimerOutput::Scope t(timer, "assembly");
          block->setup_system(parameters.boundary_conditions);
          if (factorises_blocks())
            block->assemble_stiffness();
        }
    });
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::factorize_blocks(
    const std::vector<ContactPair<dim>> &pairs)
  {
    if (!factorises_blocks())
      return;
    // Under mpirun each rank factorises its own blocks at the same time.
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          const std::size_t n_contact_dofs =
            CondensedSystem<dim>::contact_dofs(pairs, b).size();
          if (CondensedSystem<dim>::is_on_demand(
                *blocks[b],
                n_contact_dofs,
                parameters.contact_solver.flexibility_columns))
            blocks[b]->set_flexibility_on_demand();
          TimerOutput::Scope t(timer, "factorisation");
          Timer              clock;
          blocks[b]->factorize();
          condensed_seconds += clock.wall_time();
        }
    });
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::run()
  {
    // A signal during the set-up ends the run between its steps.
    Timer setup_clock;
    make_blocks();
    check_staged_model();
    stop_if_signalled(-1);
    setup_blocks();
    print_blocks();
    stop_if_signalled(-1);
    make_contact();
    stop_if_signalled(-1);
    make_writers();
    if (parameters.run.mode == "strength reduction")
      run_strength_reduction(setup_clock.wall_time());
    else
      run_load_history();
    print_run_summary();
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::run_load_history()
  {
    // With an in-situ stress, increment 0 is the geostatic stage at t = 0:
    // nothing released yet, zero displacement, the interfaces in the
    // compression of sigma_0.
    const unsigned int first_increment =
      parameters.in_situ_stress.enabled ? 0 : 1;
    for (unsigned int k = first_increment;
         k <= parameters.load_history.n_increments;
         ++k)
      do_increment(k);
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_blocks() const
  {
    const auto &first = *blocks.front();
    pcout << "mbfem: "
          << (blocks.size() == 1 ?
                (parameters.plasticity.enabled ? "one elastic-plastic block" :
                                                 "one elastic block") :
                std::to_string(blocks.size()) + " blocks")
          << ", " << dim << "D" << (dim == 2 ? " plane strain" : "")
          << ", FE_Q(" << first.get_fe().degree << ")^" << dim << ", MappingQ("
          << first.get_mapping().get_degree() << ")\n";
    screen =
      std::make_unique<ScreenDetail>(parameters.output, blocks.size(), pcout);
    if (screen->summary())
      print_block_counts();
    ConditionalOStream &out = screen->detail("blocks");
    for (const auto &block : blocks)
      {
        out << (blocks.size() == 1 ? "" : "  " + block->name() + ":\n")
            << "  cells: " << block->get_triangulation().n_active_cells()
            << ", degrees of freedom: " << block->n_dofs()
            << (parameters.discretisation.block_degrees.empty() ?
                  std::string() :
                  ", FE_Q(" + std::to_string(block->get_fe().degree) + ")")
            << "\n"
            << "  E = " << block->get_material().youngs_modulus
            << ", nu = " << block->get_material().poissons_ratio << "\n";
        const auto &free_modes = block->free_rigid_body_modes();
        if (!free_modes.empty())
          {
            out << "  floating: free rigid-body modes";
            for (const auto &mode : free_modes)
              out << " [" << Block<dim>::describe_rigid_body_mode(mode) << "]";
            out << ", held by contact\n";
          }
      }
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_block_counts() const
  {
    types::global_dof_index n_dofs  = 0;
    unsigned int            n_cells = 0, n_floating = 0;
    double                  smallest = 1e300, largest = 0.;
    for (const auto &block : blocks)
      {
        n_dofs += block->n_dofs();
        n_cells += block->get_triangulation().n_active_cells();
        n_floating += !block->free_rigid_body_modes().empty();
        smallest =
          std::min(smallest, GridTools::volume(block->get_triangulation()));
        largest =
          std::max(largest, GridTools::volume(block->get_triangulation()));
      }
    pcout << "  cells: " << n_cells << ", degrees of freedom: " << n_dofs
          << "; " << n_floating << " floating block(s) held by contact; "
          << (dim == 2 ? "areas " : "volumes ") << smallest << " to " << largest
          << " (detail per block in " << parameters.output.directory << "/"
          << parameters.output.base_name << "-blocks.txt)\n";
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::check_blocks_held(
    const std::vector<ContactPair<dim>> &pairs) const
  {
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
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::make_contact()
  {
    std::vector<ContactPair<dim>> pairs;
    if (parameters.contact.declares_interfaces())
      pairs = find_contact_pairs(blocks, parameters.contact, pcout);
    check_blocks_held(pairs);
    factorize_blocks(pairs);

    const ContactSolverParameters &contact_parameters =
      parameters.contact_solver;
    AssertThrow(!parameters.plasticity.newton || pairs.empty() ||
                  !contact_parameters.runs_monolithic(),
                ExcMessage(
                  "'Plasticity/Method = Newton' works with the condensed "
                  "contact formulation only (its tangent flexibilities); "
                  "set 'Contact/Formulation = condensed' or use the "
                  "initial-stress method."));
    if (pairs.empty())
      return;
    const auto make_solver = [&](const ContactFormulation      formulation,
                                 std::vector<ContactPair<dim>> solver_pairs) {
      auto solver =
        std::make_unique<ContactSolver<dim>>(std::move(solver_pairs),
                                             contact_parameters.max_iterations,
                                             formulation,
                                             parameters.linear_solver.package,
                                             contact_parameters.state_system);
      solver->set_state_methods(contact_parameters.state_method);
      solver->set_flexibility_columns(contact_parameters.flexibility_columns);
      return solver;
    };
    if (contact_parameters.runs_condensed())
      {
        TimerOutput::Scope t(timer, "flexibility");
        Timer              clock;
        make_configurations(pairs, [&](std::vector<ContactPair<dim>> subset) {
          return make_solver(ContactFormulation::condensed, std::move(subset));
        });
        condensed_seconds += clock.wall_time();
      }
    // A line every 10 s of a long state iteration (not in test mode: its
    // lines depend on the machine), also in the silent trials of strength
    // reduction.
    if (contact && pcout.is_active() && !parameters.run.test_mode)
      contact->report_progress(&pcout.get_stream());
    if (contact_parameters.runs_monolithic())
      {
        TimerOutput::Scope t(timer, "monolithic assembly");
        Timer              clock;
        auto solver = make_solver(ContactFormulation::monolithic, pairs);
        solver->setup(blocks);
        if (contact)
          reference = std::move(solver);
        else
          {
            configurations.resize(1);
            configurations[0].present.assign(blocks.size(), true);
            for (unsigned int k = 0; k < pairs.size(); ++k)
              configurations[0].pairs.push_back(k);
            configurations[0].solver = std::move(solver);
            contact                  = configurations[0].solver.get();
          }
        monolithic_seconds += clock.wall_time();
      }
    make_water();
    print_formulation(pairs.size());
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::make_water()
  {
    if (!parameters.water_pressure.enabled())
      return;
    for (auto &configuration : configurations)
      configuration.water =
        std::make_unique<JointWater<dim>>(parameters.water_pressure,
                                          parameters.contact,
                                          configuration.solver->pairs(),
                                          blocks.size());
    water = configurations[0].water.get();
    // The stage with the most pairs (the model finished, unless some
    // stage removes blocks).
    const Configuration &most =
      *std::max_element(configurations.begin(),
                        configurations.end(),
                        [](const Configuration &a, const Configuration &b) {
                          return a.pairs.size() < b.pairs.size();
                        });
    pcout << "  water pressure on " << most.water->n_wet_pairs() << " of "
          << most.pairs.size() << " pairs (both faces of the joint)\n";
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_formulation(const unsigned int n_pairs) const
  {
    const ContactSolverParameters &contact_parameters =
      parameters.contact_solver;
    pcout << "  contact formulation: "
          << (!contact_parameters.runs_monolithic() ? "condensed" :
              !contact_parameters.runs_condensed()  ? "monolithic" :
                                                      "both");
    if (contact_parameters.runs_monolithic())
      {
        types::global_dof_index n = n_pairs * dim;
        for (const auto &block : blocks)
          n += block->n_dofs();
        pcout << " (monolithic system of " << n << " unknowns)";
      }
    pcout << "\n";
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::make_writers()
  {
    create_output_directory(parameters.output.directory);
    if (!parameters.output.write_vtu)
      return;
    writer = std::make_unique<OutputWriter>(parameters.output);
    if (contact)
      {
        OutputParameters pair_output = parameters.output;
        pair_output.base_name += "-pairs";
        pair_writer = std::make_unique<OutputWriter>(pair_output);
      }
  }



  namespace
  {
    /**
     * Clears the progress line that @p contact shows in place on a terminal
     * when the increment's solve ends, however it ends.
     */
    template <int dim>
    struct ProgressLine
    {
      ContactSolver<dim> *contact;
      ~ProgressLine()
      {
        if (contact)
          contact->end_progress();
      }
    };
  } // namespace



  template <int dim>
  void
  MultiBodyProblem<dim>::do_increment(const unsigned int k)
  {
    const double  time       = parameters.load_history.time(k);
    unsigned int  iterations = 0, reference_iterations = 0;
    PlasticUpdate plastic_update;
    // Before the solve: its step halvings and progress lines belong to it.
    if (!trial_run)
      print_stage(k);
    switch_configuration(k);
    if (contact)
      contact->start_progress(k);
    increment_contact_seconds       = 0.;
    unsigned int plastic_iterations = 0;
    {
      const ProgressLine<dim> line{contact};
      plastic_iterations =
        solve_increment(k, iterations, reference_iterations, plastic_update);
    }
    for (const auto &block : blocks)
      block->plastic_state().commit();
    if (dim == 3 && !trial_run && contact &&
        contact->count(ContactState::slip) > 0)
      pcout << "    friction against the slip made: largest angle "
            << std::fixed << std::setprecision(1) << contact->misalignment()
            << " degrees" << std::defaultfloat << std::setprecision(6) << "\n";
    for (const auto &block : blocks)
      AssertThrow(std::isfinite(block->get_solution().l2_norm()),
                  ExcMessage(
                    "Increment " + std::to_string(k) +
                    " (t = " + std::to_string(time) +
                    "): the displacement of " + block->name() +
                    " is not finite. A load or prescribed displacement "
                    "function gives NaN or inf at this time. " +
                    earlier_results()));

    if (!trial_run)
      print_increment(k, time, iterations);
    if (parameters.plasticity.enabled)
      print_plasticity(plastic_iterations, plastic_update);
    if (reference)
      compare_formulations();
    std::string pair_file;
    if (contact)
      {
        if (!trial_run)
          pair_file =
            write_contact_files(k, time, iterations, reference_iterations);
        check_ranks_agree();
        contact->commit();
        if (reference)
          reference->commit();
      }
    if (trial_run)
      {
        stop_if_signalled(-2); // -2: in a trial, nothing written
        return;
      }
    write_blocks(k, time, pair_file);
    last_written_increment = k;
    stop_if_signalled(k); // SIGINT/SIGTERM: end here, files complete
  }



  template <int dim>
  std::string
  MultiBodyProblem<dim>::write_contact_files(
    const unsigned int k,
    const double       time,
    const unsigned int iterations,
    const unsigned int reference_iterations)
  {
    std::vector<double> water_pressure;
    for (unsigned int i = 0; water && i < contact->pairs().size(); ++i)
      water_pressure.push_back(water->pressure(i, time));
    const std::string pair_file =
      write_pair_files(*contact,
                       parameters.output,
                       k,
                       time,
                       water_pressure,
                       parameters.load_history.changes_model() ?
                         configurations[active_configuration].pairs :
                         std::vector<unsigned int>());
    if (parameters.output.write_contact_problems &&
        contact->formulation() == ContactFormulation::condensed)
      contact->condensed_problem(k, time).write(problem_stem(k, ""));
    write_summary(k, time, iterations, reference_iterations);
    return pair_file;
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::write_blocks(const unsigned int k,
                                      const double       time,
                                      const std::string &pair_file)
  {
    if (!writer)
      return;
    TimerOutput::Scope       t(timer, "output");
    std::vector<std::string> files;
    // Each rank writes the blocks it owns; an error on one ends all.
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (const auto &block : blocks)
        if (block->presence(time) > 0.) // not before a stage adds it
          files.push_back(writer->write_block(*block, block->get_id(), k));
    });
    writer->add_step(time, files);
    if (pair_writer)
      pair_writer->add_step(time, {pair_file});
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_stage(const unsigned int k) const
  {
    const LoadHistory &history = parameters.load_history;
    if (!history.starts_stage(k))
      return;
    const unsigned int s     = history.stage(k);
    const auto        &stage = history.stages[s];
    pcout << "stage " << s + 1 << "/" << history.stages.size() << " '"
          << stage.name << "': t from "
          << (s == 0 ? 0. : history.stages[s - 1].end_time) << " to "
          << stage.end_time << " in " << stage.n_increments
          << " increment(s)\n";
  }



  template <int dim>
  std::string
  MultiBodyProblem<dim>::problem_stem(const unsigned int k,
                                      const std::string &prefix) const
  {
    return parameters.output.directory + "/" + parameters.output.base_name +
           "-" + prefix + "problem-" + Utilities::int_to_string(k, 4);
  }



  template <int dim>
  std::string
  MultiBodyProblem<dim>::write_failed_problem(const unsigned int k,
                                              const double       time) const
  {
    if (trial_run || !contact ||
        contact->formulation() != ContactFormulation::condensed)
      return "";
    const std::string stem = problem_stem(k, "failed-");
    contact->condensed_problem(k, time, false).write(stem);
    return "    The increment's contact problem, from the start of the step "
           "that failed, is in " +
           stem + ".json (doc/contact_problems.md).\n";
  }



  template <int dim>
  std::string
  MultiBodyProblem<dim>::earlier_results() const
  {
    if (last_written_increment < 0)
      return "No increment had converged, so no results were written.";
    return "Results of the earlier increments are in " +
           parameters.output.directory + ".";
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_plasticity(
    const unsigned int   plastic_iterations,
    const PlasticUpdate &plastic_update) const
  {
    pcout << "    plasticity: " << plastic_iterations
          << " iteration(s), yielded " << plastic_update.n_yielded << " of "
          << plastic_update.n_points << " quadrature points ("
          << (dim == 2 ? "area " : "volume ") << std::scientific
          << std::setprecision(6) << plastic_update.yielded_measure
          << "), largest equivalent plastic strain "
          << plastic_update.max_equivalent << std::defaultfloat
          << std::setprecision(6) << "\n";
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_run_summary()
  {
    if (newton_suspensions > 0)
      pcout << "  Newton's tangent system had no solution in "
            << newton_suspensions << " step(s); the elastic stiffness "
            << "(initial-stress method) took over in them\n";
    if (contact)
      print_interface_summary(*contact,
                              parameters.contact,
                              screen->detail("interfaces"));
    if (reference)
      comparison.print_summary(pcout);
    if (contact && !parameters.run.test_mode)
      print_formulation_times();
    const LoadHistory &history = parameters.load_history;
    if (parameters.exact_solution.enabled)
      print_errors(history.time(history.n_increments));

    if (writer)
      pcout << "  wrote " << history.n_increments << " VTU file(s)"
            << (blocks.size() > 1 ? " per block" : "") << " indexed by "
            << writer->pvd_file() << "\n";
    const std::string base =
      parameters.output.directory + "/" + parameters.output.base_name;
    if (contact && !parameters.run.test_mode)
      pcout << "  contact pairs per increment in " << base
            << "-pairs-*.csv, a line per increment in " << base
            << "-summary.csv\n";
    if (screen && screen->summary())
      pcout << "  " << screen->files() << "\n";
    if (!parameters.run.test_mode)
      timer.print_summary();
  }



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
      // The verdict first: whatever way the state iteration ended (a cycle,
      // a singular state), the certificate is what proves it.
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
      // Statics with every joint the path broke counted unbroken admits
      // forces, but the increment's own loads broke them on the way.
      if (const auto path = contact->certify_path_breaking();
          path && path->verdict == Verdict::none)
        {
          std::ostringstream verdict;
          verdict << "No equilibrium at t = " << time
                  << " once the joints the load path broke have lost their "
                     "strength: no contact forces within what is left of "
                     "it balance the floating blocks' loads (the second "
                     "statics certificate below). Breaking is for good, and "
                     "the path broke them in the order of its events from "
                     "an equilibrium (doc/decisions.md, \"Joints the load "
                     "path broke\", says what this proves); rigid-block "
                     "statics with those joints whole (the first "
                     "certificate) cannot see this.\n    "
                  << text.str() << "    Statics certificate at t = " << time
                  << " after the load path: " << path->description << "\n"
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
  void
  MultiBodyProblem<dim>::print_formulation_times() const
  {
    const ContactSolverParameters &contact_parameters =
      parameters.contact_solver;
    pcout << "  time of the contact formulation(s) alone (wall, s): ";
    if (contact_parameters.runs_condensed())
      pcout << "condensed " << std::setprecision(3) << condensed_seconds
            << " (factorisation, flexibility, load response, contact "
               "iterations, recovery)";
    std::size_t computed = 0, all = 0;
    for (const auto &configuration : configurations)
      if (configuration.solver != nullptr)
        {
          computed += configuration.solver->columns_on_demand().first;
          all += configuration.solver->columns_on_demand().second;
        }
    if (all > 0)
      pcout << ", flexibility on demand: " << computed << " of " << all
            << " columns computed";
    if (contact_parameters.runs_condensed() &&
        contact_parameters.runs_monolithic())
      pcout << "; ";
    if (contact_parameters.runs_monolithic())
      pcout << "monolithic " << std::setprecision(3) << monolithic_seconds
            << " (assembly, contact iterations with one sparse LU "
               "each, recovery)";
    pcout << std::setprecision(6) << "\n";
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
    // failure's, at the increment's own size, not the last retry's, with
    // the statics certificate's verdict (end_with_certificate()).
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
        end_with_certificate<dim>(
          contact,
          first_failure +
            (history.max_halvings == 0 ?
               "" :
               "    The increment was also tried in steps down to 1/" +
                 std::to_string(1u << halvings) +
                 " of its size ('Load history/Maximum step halvings = " +
                 std::to_string(history.max_halvings) + "').\n") +
            "    " + earlier_results() + "\n",
          target,
          std::is_same_v<std::decay_t<decltype(failure)>,
                         Exceptions::ExcNoEquilibrium>,
          [&]() { return write_failed_problem(k, target); });
      for (const auto &block : blocks)
        block->plastic_state().restore();
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
    certify_sliding_blocks(k, time);
    return plastic_iterations;
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::certify_sliding_blocks(const unsigned int k,
                                                const double       time) const
  {
    // A floating block none of whose pairs sticks may have converged to a
    // sliding state whose forces balance it only with tension or against
    // the cone (the 3D wedge beyond its limit did, with |u| ~ 1e8 m):
    // such an increment stands only if admissible forces exist.
    if (!contact)
      return;
    const std::vector<std::string> sliding =
      contact->blocks_without_stuck_pairs();
    if (sliding.empty())
      return;
    // Only the verdict decides here: the mechanism factor's LPs wait
    // until it is none.
    if (contact->certify(false).verdict !=
        StaticAdmissibility<dim>::Verdict::none)
      return;
    const auto  result = contact->certify();
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
         << earlier_results();
    throw Exceptions::ExcNoEquilibrium(text.str());
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::share_solutions()
  {
    if (Parallel::n_ranks() > 1)
      for (const auto &block : blocks)
        block->share_solution();
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::check_ranks_agree() const
  {
    if (Parallel::n_ranks() == 1)
      return;
    std::vector<unsigned long long> states;
    for (unsigned int k = 0; k < contact->pairs().size(); ++k)
      {
        states.push_back(static_cast<unsigned int>(contact->state(k)));
        states.push_back(contact->broken(k));
      }
    Parallel::check_same_on_all_ranks(states,
                                      "the states of the contact pairs");
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::commit_step()
  {
    for (const auto &block : blocks)
      block->plastic_state().commit();
    if (contact)
      {
        check_ranks_agree();
        contact->commit();
      }
    if (reference)
      reference->commit();
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::assemble_loads(const double time,
                                        const bool   condensed,
                                        const bool   loads_everywhere)
  {
    TimerOutput::Scope t(timer, "load response");
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          Block<dim> &block = *blocks[b];
          block.assemble_load(parameters.boundary_conditions,
                              time,
                              loads_everywhere);
          if (water)
            water->add_load(b, block, time);
          add_released_forces(b, time); // from the pairs of removed blocks
          if (condensed)
            {
              Timer clock;
              block.solve(); // on the block's owner
              condensed_seconds += clock.wall_time();
            }
        }
    });
    if (Parallel::n_ranks() > 1)
      for (const auto &block : blocks)
        block->share_load_resultant();
    if (condensed)
      share_solutions();
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::recover_fields(const bool condensed)
  {
    TimerOutput::Scope t(timer, "field recovery");
    Timer              clock;
    Parallel::together(MPI_COMM_WORLD, [&]() {
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
          {
            Vector<double> displacement;
            contact->block_solution(b, *blocks[b], displacement);
            blocks[b]->set_solution(std::move(displacement));
          }
    });
    if (condensed)
      share_solutions();
    (condensed ? condensed_seconds : monolithic_seconds) += clock.wall_time();
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
    // The condensed formulation needs a block's load on its owner alone
    // (the floating blocks' F_e is shared below); the monolithic system
    // assembles every block's on every rank.
    const bool loads_everywhere = !condensed || reference != nullptr;
    assemble_loads(time, condensed, loads_everywhere);
    if (contact)
      {
        {
          TimerOutput::Scope t(timer, "contact iterations");
          Timer              clock;
          iterations = contact->solve_increment(blocks, k, from_last_solve);
          last_contact_seconds = clock.wall_time();
          increment_contact_seconds += last_contact_seconds;
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
        recover_fields(condensed);
      }
  }



  template <int dim>
  PlasticUpdate
  MultiBodyProblem<dim>::update_plastic_strain()
  {
    PlasticUpdate      update;
    TimerOutput::Scope t(timer, "plasticity");
    for (const auto &block : blocks)
      update += block->plastic_state().update(*block);
    return update;
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::check_plastic_iterations(
    const unsigned int k,
    const double       time,
    const double       change,
    const unsigned int plastic_iterations) const
  {
    AssertThrow(plastic_iterations < parameters.plasticity.max_iterations,
                Exceptions::ExcIncrementNotConverged(
                  "Increment " + std::to_string(k) +
                  " (t = " + std::to_string(time) +
                  "): the plastic strain still changes " + "by " +
                  std::to_string(change) + " (relative) after " +
                  std::to_string(plastic_iterations) +
                  " iterations ('Plasticity/Maximum iterations'). The rock may "
                  "be failing (no equilibrium with this strength), or the "
                  "increment is too large: use more load increments. " +
                  earlier_results()));
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
    // the step (see PlasticState::suspend_newton()).
    bool newton = plasticity.newton;
    for (const auto &block : blocks)
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
        print_plastic_progress(plastic_iterations,
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
        for (const auto &block : blocks)
          block->plastic_state().relax(omega);
      }
    return plastic_iterations;
  }



  template <int dim>
  bool
  MultiBodyProblem<dim>::pass_with_fallback(
    const unsigned int k,
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
  void
  MultiBodyProblem<dim>::print_plastic_progress(
    const unsigned int plastic_iterations,
    const double       change,
    const double       omega,
    const unsigned int n_yielded) const
  {
    // Progress on long runs: a line every 100 iterations, or every Newton
    // iteration (few, each with new factorisations).
    if (parameters.run.test_mode)
      return;
    if (omega < 0.)
      pcout << "    Newton iteration " << plastic_iterations << ": residual "
            << std::scientific << std::setprecision(3) << change
            << std::defaultfloat << ", " << n_yielded << " points yielded"
            << std::setprecision(6) << "\n";
    else if (plastic_iterations % 100 == 0)
      pcout << "    plastic iteration " << plastic_iterations << ": change "
            << std::scientific << std::setprecision(3) << change
            << ", relaxation " << std::defaultfloat << omega << ", "
            << n_yielded << " points yielded" << std::setprecision(6) << "\n";
  }



  template <int dim>
  double
  MultiBodyProblem<dim>::aitken_relaxation(const double         omega,
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
  MultiBodyProblem<dim>::give_way_to_initial_stress(
    const ExceptionBase &failure,
    const unsigned int   plastic_iterations)
  {
    // The tangent of perfect plasticity is singular along the flow; with
    // slipping pairs around a yielded band the condensed system can be too,
    // while the elastic one is not.
    bool suspended = false;
    for (const auto &block : blocks)
      suspended = block->plastic_state().suspend_newton(true) || suspended;
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
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (const auto &block : blocks)
        if (block->plastic_state().tangent_changed())
          {
            changed = true;
            {
              TimerOutput::Scope t(timer, "assembly");
              block->assemble_stiffness();
            }
            TimerOutput::Scope t(timer, "factorisation");
            Timer              clock;
            block->factorize(); // on the block's owner
            condensed_seconds += clock.wall_time();
          }
    });
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
  void
  MultiBodyProblem<dim>::compare_formulations()
  {
    double displacement_scale = 1e-300;
    for (const auto &block : blocks)
      displacement_scale =
        std::max(displacement_scale, max_displacement(*block));
    comparison.compare(*contact, *reference, displacement_scale, pcout);
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
                      "method = the state method that concluded the "
                      "increment (fast, load path, semismooth Newton, "
                      "Lemke or load continuation); fast_iterations = "
                      "the fast iteration's; path_switches = the "
                      "concluding method's iterations, if not the fast "
                      "iteration's, with those of its final fast "
                      "iteration (load path switches, Lemke pivots, "
                      "Newton steps, continuation iterations)\n";
        summary_csv += "increment,t,iterations,stick,slip,open,max_gap,"
                       "max_slip,max_normal_traction,seconds,method,"
                       "fast_iterations,path_switches";
        if (reference)
          summary_csv += ",reference_iterations,reference_seconds,"
                         "states_differ,force_difference,gap_difference,"
                         "slip_difference";
        if (parameters.load_history.has_stages())
          summary_csv += ",stage";
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
                  increment_contact_seconds);
    summary_csv += buffer;
    // Which method concluded the state iteration, and its share of the
    // iterations (doc/state_iteration.md).
    summary_csv += "," + contact->last_method() + "," +
                   std::to_string(contact->last_iterations().first) + "," +
                   std::to_string(contact->last_iterations().second);
    if (reference)
      {
        std::snprintf(buffer,
                      sizeof(buffer),
                      ",%u,%.4f,%u,%.3e,%.3e,%.3e",
                      reference_iterations,
                      last_reference_seconds,
                      static_cast<unsigned int>(comparison.last()[0]),
                      comparison.last()[1],
                      comparison.last()[2],
                      comparison.last()[3]);
        summary_csv += buffer;
      }
    const LoadHistory &history = parameters.load_history;
    if (history.has_stages())
      summary_csv += "," + history.stages[history.stage(k)].name;
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
        max_u         = std::max(max_u, max_displacement(*block));
        max_von_mises = std::max(max_von_mises, max_von_mises_stress(*block));
      }
    pcout << "  increment " << k << "/" << parameters.load_history.n_increments
          << ", t = " << time << ": ";
    if (contact)
      {
        // The range of the normal traction over the pairs that are not
        // tied (0 and 0 where every pair is tied).
        double min_normal = 1e300, max_normal = -1e300, max_tangential = 0.,
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
        if (min_normal > max_normal)
          min_normal = max_normal = 0.;
        // Which method concluded the state iteration: named only where
        // the fast iteration did not (the screen lines of the increments
        // it concludes stay as they were).
        pcout << iterations << " iteration(s)";
        if (contact->last_method() != "fast")
          pcout << " (fast " << contact->last_iterations().first << ", "
                << contact->last_method() << " "
                << contact->last_iterations().second << ")";
        if (!parameters.run.test_mode)
          pcout << " in " << std::setprecision(3) << increment_contact_seconds
                << " s" << std::setprecision(6);
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

    if (water)
      pcout << "    water in the joints: sum of p_w A = " << std::scientific
            << std::setprecision(6) << water->resultant(time)
            << std::defaultfloat << std::setprecision(6) << "\n";
    if (contact)
      print_resultants(k, time);
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_resultants(const unsigned int k,
                                          const double       time) const
  {
    // The resultant each interface transmits (force on its side b).
    std::vector<Tensor<1, dim>> resultant(parameters.contact.interfaces.size());
    for (unsigned int p = 0; p < contact->pairs().size(); ++p)
      resultant[contact->pairs()[p].interface] += contact->force(p);
    ConditionalOStream &out = screen->detail("interfaces");
    if (screen->summary())
      out << "  increment " << k << ", t = " << time << ":\n";
    for (unsigned int i = 0; i < resultant.size(); ++i)
      {
        out << "    interface " << i + 1 << ": resultant force on side b ("
            << std::scientific << std::setprecision(6);
        for (unsigned int d = 0; d < dim; ++d)
          out << (d > 0 ? ", " : "")
              << (std::abs(resultant[i][d]) < 1e-12 * resultant[i].norm() ?
                    0. :
                    resultant[i][d]);
        out << ")" << std::defaultfloat << std::setprecision(6) << "\n";
      }
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_errors(const double time) const
  {
    parameters.exact_solution.displacement->set_time(time);
    parameters.exact_solution.stress->set_time(time);
    std::vector<ErrorNorms> errors;
    for (const auto &block : blocks)
      errors.push_back(compute_errors(*block,
                                      *parameters.exact_solution.displacement,
                                      *parameters.exact_solution.stress));
    const ErrorNorms total    = combine_errors(errors);
    const double     u_error2 = std::pow(total.displacement, 2);
    const double     s_error2 = std::pow(total.stress, 2);
    const double     u_norm2  = std::pow(total.displacement_norm, 2);
    const double     s_norm2  = std::pow(total.stress_norm, 2);
    AssertThrow(std::isfinite(u_error2 + u_norm2 + s_error2 + s_norm2),
                ExcMessage("The L2 error against 'Exact solution' at t = " +
                           std::to_string(time) +
                           " is not finite: the exact displacement or stress "
                           "is not finite somewhere in the blocks, or so "
                           "large that its square overflows. Check its "
                           "functions; the results of the increments are on "
                           "disk."));
    // An exact field that is zero throughout has no relative error: the
    // absolute one is shown, and said to be so.
    const auto error_text = [](const double error2, const double norm2) {
      std::ostringstream text;
      text << std::scientific << std::setprecision(3)
           << std::sqrt(error2 / (norm2 > 0. ? norm2 : 1.))
           << (norm2 > 0. ? "" : " (absolute: the exact field is zero)");
      return text.str();
    };
    const double u_relative = total.displacement_relative;
    const double s_relative = total.stress_relative;
    pcout << "  L2 errors against the exact solution (relative): "
          << "displacement " << error_text(u_error2, u_norm2) << ", stress "
          << error_text(s_error2, s_norm2) << "\n";

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
  const std::vector<std::unique_ptr<Block<dim>>> &
  MultiBodyProblem<dim>::get_blocks() const
  {
    return blocks;
  }



  template <int dim>
  const ContactSolver<dim> *
  MultiBodyProblem<dim>::get_contact() const
  {
    return contact;
  }



  template class MultiBodyProblem<2>;
  template class MultiBodyProblem<3>;
} // namespace mbfem

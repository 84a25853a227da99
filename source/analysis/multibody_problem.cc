#include <mbfem/analysis/block_measures.h>
#include <mbfem/analysis/input_checks.h>
#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/parameters.h>
#include <mbfem/analysis/reliability_run.h>
#include <mbfem/analysis/strength_reduction_run.h>
#include <mbfem/base/exceptions.h>
#include <mbfem/base/files.h>
#include <mbfem/base/interruption.h>
#include <mbfem/base/parallel.h>
#include <mbfem/mesh/mesh_checks.h>
#include <mbfem/mesh/rock_mass.h>

#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>
#include <utility>

namespace mbfem
{
  template <int dim>
  Model<dim>::Model(Parameters<dim> &parameters, ConditionalOStream &pcout)
    : parameters(parameters)
    , pcout(pcout)
    // Summary printed at the end of a run that finished, not on the way
    // out of one that failed.
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
  {}



  template <int dim>
  MultiBodyProblem<dim>::MultiBodyProblem(Parameters<dim>    &parameters,
                                          ConditionalOStream &pcout)
    : model(parameters, pcout)
    , stages(model)
    , report(model, stages)
    , steps(model, stages, report)
  {}



  template <int dim>
  void
  MultiBodyProblem<dim>::build_rock_mass_mesh()
  {
    Parameters<dim>         &parameters = model.parameters;
    const auto              &origin     = parameters.mesh.rock_mass.origin;
    std::vector<JointPlanes> sets;
    for (const JointSet &set : parameters.contact.joint_sets)
      {
        if (set.spacing == 0. && set.point.empty())
          continue; // a law only (a set with a point alone: one plane)
        AssertThrow(set.point.empty() || set.point.size() == dim,
                    ExcMessage("Contact/Joint sets: the point of the set '" +
                               set.name + "' has " +
                               std::to_string(set.point.size()) +
                               " coordinates; a " + std::to_string(dim) +
                               "D model needs " + std::to_string(dim) + "."));
        JointPlanes planes;
        planes.name            = set.name;
        planes.spacing         = set.spacing;
        const Tensor<1, dim> n = set.normal<dim>();
        for (unsigned int d = 0; d < dim; ++d)
          {
            planes.normal[d] = n[d];
            planes.point[d]  = !set.point.empty() ? set.point[d] :
                               d < origin.size()  ? origin[d] :
                                                    0.;
          }
        sets.push_back(planes);
      }
    const OutputParameters &output = parameters.output;
    create_output_directory(output.directory);
    const std::string file =
      output.directory + "/" + output.base_name + "-rock-mass.msh";
    RockMassSummary    summary;
    TimerOutput::Scope timer(model.timer, "rock mass (gmsh)");
    Parallel::on_owner(MPI_COMM_WORLD, 0, [&]() {
      summary = build_rock_mass<dim>(parameters.mesh.rock_mass, sets, file);
    });
    parameters.mesh.mesh_file = file;
    print_rock_mass(summary, sets, file);
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::print_rock_mass(const RockMassSummary &summary,
                                         const std::vector<JointPlanes> &sets,
                                         const std::string &file) const
  {
    ConditionalOStream &pcout = model.pcout;
    pcout << "rock mass: " << summary.n_blocks << " blocks"
          << (summary.has_base ? " (block 1 the base)" : "") << " cut by ";
    for (unsigned int s = 0; s < sets.size(); ++s)
      pcout << (s > 0 ? ", " : "") << sets[s].name << " ("
            << summary.planes_per_set[s] << " planes)";
    if (sets.empty())
      pcout << "no joint set with a spacing or a point";
    pcout << "; " << (dim == 2 ? "areas " : "volumes ") << summary.smallest
          << " to " << summary.largest << ", their sum "
          << std::setprecision(12) << summary.blocks_measure
          << " of the domain's " << summary.domain_measure
          << std::setprecision(6) << "; " << summary.n_cells
          << (dim == 2 ? " quadrilaterals" : " hexahedra") << ", written to "
          << file << "\n";
    if (summary.n_small > 0)
      pcout << "  warning: " << summary.n_small
            << " block(s) smaller than half an element ('Mesh/Rock "
               "mass/Mesh size' to the power "
            << dim << ", halved), the smallest " << summary.smallest
            << "; they are kept (a set cutting a corner off the domain)\n";
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::make_blocks()
  {
    if (model.parameters.mesh.source == "rock mass")
      build_rock_mass_mesh();
    TimerOutput::Scope t(model.timer, "mesh");
    Triangulation<dim> mesh;
    create_mesh(model.parameters.mesh, mesh, &joint_faces);
    // Everything the input names must exist before anything is built.
    check_ids_against_mesh(model.parameters, mesh);

    const auto &materials = model.parameters.block_materials;
    const auto &excavated = model.parameters.excavation.excavated_ids;
    for (const auto id : block_ids(mesh))
      {
        if (std::find(excavated.begin(), excavated.end(), id) !=
            excavated.end())
          continue; // removed rock: not a block
        const Material &material =
          materials.empty() ? model.parameters.material : materials.at(id);
        model.blocks.push_back(
          std::make_unique<Block<dim>>(material,
                                       model.parameters.discretisation,
                                       model.parameters.linear_solver.package,
                                       id));
        Block<dim> &block = *model.blocks.back();
        block.extract_mesh(mesh);
        const auto refinements =
          model.parameters.mesh.block_refinements.find(id);
        if (refinements != model.parameters.mesh.block_refinements.end())
          block.refine_mesh(refinements->second);
        check_cell_geometry(block.get_triangulation(),
                            block.get_mapping(),
                            block.get_fe().degree,
                            block.name());
        block.set_initial_state(&model.parameters.in_situ_stress,
                                &model.parameters.excavation);
        block.plastic_state().initialize(model.parameters.plasticity, block);
        const InSituStress &in_situ = model.parameters.in_situ_stress;
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
                      model.parameters.boundary_conditions.gravity_ramp_time ==
                        0.,
                    ExcMessage("'Boundary conditions/Gravity ramp time' must "
                               "be 0 with an in-situ stress: sigma_0 is in "
                               "equilibrium with the full weight from the "
                               "start."));
      }
    assign_block_owners();
    check_point_supports(model.parameters.boundary_conditions,
                         model.blocks,
                         model.pcout.get_stream());
    check_functions_are_finite(model.parameters, model.blocks);
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::assign_block_owners()
  {
    // Under mpirun each block is factorised and solved on one rank; every
    // rank holds the meshes and runs the contact iteration (doc/parallel.md).
    std::vector<double> costs;
    for (const auto &block : model.blocks)
      costs.push_back(block->cost());
    const std::vector<unsigned int> owners =
      Parallel::assign_owners(costs, Parallel::n_ranks());
    if (Parallel::n_ranks() > 1)
      for (unsigned int b = 0; b < model.blocks.size(); ++b)
        model.blocks[b]->set_owner(MPI_COMM_WORLD, owners[b]);
  }



  template <int dim>
  bool
  MultiBodyProblem<dim>::factorises_blocks() const
  {
    return !model.parameters.contact.declares_interfaces() ||
           model.parameters.contact_solver.runs_condensed();
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::setup_blocks()
  {
    model.parameters.boundary_conditions.set_time(0.);
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (const auto &block : model.blocks)
        {
          TimerOutput::Scope t(model.timer, "assembly");
          block->setup_system(model.parameters.boundary_conditions);
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
      for (unsigned int b = 0; b < model.blocks.size(); ++b)
        {
          const std::size_t n_contact_dofs =
            CondensedSystem<dim>::contact_dofs(pairs, b).size();
          if (CondensedSystem<dim>::is_on_demand(
                *model.blocks[b],
                n_contact_dofs,
                model.parameters.contact_solver.flexibility_columns))
            model.blocks[b]->set_flexibility_on_demand();
          TimerOutput::Scope t(model.timer, "factorisation");
          Timer              clock;
          model.blocks[b]->factorize();
          model.condensed_seconds += clock.wall_time();
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
    stages.check_staged_model();
    stop_if_signalled(-1);
    setup_blocks();
    report.print_blocks();
    stop_if_signalled(-1);
    make_contact();
    stop_if_signalled(-1);
    report.make_writers();
    StrengthReductionRun<dim> strength_reduction(
      model,
      stages,
      [this](const unsigned int k) { do_increment(k); },
      [this]() { run_load_history(); });
    if (model.parameters.run.mode == "strength reduction")
      strength_reduction.run(setup_clock.wall_time());
    else if (model.parameters.run.mode == "reliability")
      ReliabilityRun<dim>(model, stages, strength_reduction)
        .run(setup_clock.wall_time());
    else
      run_load_history();
    report.print_run_summary();
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::run_load_history()
  {
    // With an in-situ stress, increment 0 is the geostatic stage at t = 0:
    // nothing released yet, zero displacement, the interfaces in the
    // compression of sigma_0.
    const unsigned int first_increment =
      model.parameters.in_situ_stress.enabled ? 0 : 1;
    for (unsigned int k = first_increment;
         k <= model.parameters.load_history.n_increments;
         ++k)
      do_increment(k);
  }



  template <int dim>
  void
  MultiBodyProblem<dim>::check_blocks_held(
    const std::vector<ContactPair<dim>> &pairs) const
  {
    for (unsigned int b = 0; b < model.blocks.size(); ++b)
      {
        const auto  free_modes = model.blocks[b]->free_rigid_body_modes();
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
            model.blocks[b]->name() + " is not held: its supports " +
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
    if (model.parameters.contact.declares_interfaces())
      pairs = find_contact_pairs(model.blocks,
                                 model.parameters.contact,
                                 joint_faces,
                                 model.pcout);
    check_blocks_held(pairs);
    factorize_blocks(pairs);

    const ContactSolverParameters &contact_parameters =
      model.parameters.contact_solver;
    AssertThrow(!model.parameters.plasticity.newton || pairs.empty() ||
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
      auto solver = std::make_unique<ContactSolver<dim>>(
        std::move(solver_pairs),
        contact_parameters.max_iterations,
        formulation,
        model.parameters.linear_solver.package,
        contact_parameters.state_system);
      solver->set_state_methods(contact_parameters.state_method);
      solver->set_flexibility_columns(contact_parameters.flexibility_columns);
      return solver;
    };
    if (contact_parameters.runs_condensed())
      {
        TimerOutput::Scope t(model.timer, "flexibility");
        Timer              clock;
        stages.make_configurations(
          pairs, [&](std::vector<ContactPair<dim>> subset) {
            return make_solver(ContactFormulation::condensed,
                               std::move(subset));
          });
        model.condensed_seconds += clock.wall_time();
      }
    // A line every 10 s of a long state iteration (not in test mode: its
    // lines depend on the machine), also in the silent trials of strength
    // reduction.
    if (model.contact && model.pcout.is_active() &&
        !model.parameters.run.test_mode)
      model.contact->report_progress(&model.pcout.get_stream());
    if (contact_parameters.runs_monolithic())
      {
        TimerOutput::Scope t(model.timer, "monolithic assembly");
        Timer              clock;
        auto solver = make_solver(ContactFormulation::monolithic, pairs);
        solver->setup(model.blocks);
        if (model.contact)
          model.reference = std::move(solver);
        else
          {
            stages.adopt(std::move(solver), pairs.size());
          }
        model.monolithic_seconds += clock.wall_time();
      }
    stages.make_water();
    report.print_formulation(pairs.size());
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
    const double  time       = model.parameters.load_history.time(k);
    unsigned int  iterations = 0, reference_iterations = 0;
    PlasticUpdate plastic_update;
    // Before the solve: its step halvings and progress lines belong to it.
    if (!model.trial_run)
      report.print_stage(k);
    stages.switch_configuration(k);
    if (model.contact)
      model.contact->start_progress(k);
    model.increment_contact_seconds = 0.;
    unsigned int plastic_iterations = 0;
    {
      const ProgressLine<dim> line{model.contact};
      plastic_iterations = steps.solve_increment(k,
                                                 iterations,
                                                 reference_iterations,
                                                 plastic_update);
    }
    for (const auto &block : model.blocks)
      block->plastic_state().commit();
    if (dim == 3 && !model.trial_run && model.contact &&
        model.contact->count(ContactState::slip) > 0)
      model.pcout << "    friction against the slip made: largest angle "
                  << std::fixed << std::setprecision(1)
                  << model.contact->misalignment() << " degrees"
                  << std::defaultfloat << std::setprecision(6) << "\n";
    for (const auto &block : model.blocks)
      AssertThrow(std::isfinite(block->get_solution().l2_norm()),
                  ExcMessage(
                    "Increment " + std::to_string(k) +
                    " (t = " + std::to_string(time) +
                    "): the displacement of " + block->name() +
                    " is not finite. A load or prescribed displacement "
                    "function gives NaN or inf at this time. " +
                    report.earlier_results()));

    if (!model.trial_run)
      report.print_increment(k, time, iterations);
    if (model.parameters.plasticity.enabled)
      report.print_plasticity(plastic_iterations, plastic_update);
    if (model.reference)
      report.compare_formulations();
    std::string pair_file;
    if (model.contact)
      {
        if (!model.trial_run)
          pair_file = report.write_contact_files(k,
                                                 time,
                                                 iterations,
                                                 reference_iterations);
        steps.check_ranks_agree();
        model.contact->commit();
        if (model.reference)
          model.reference->commit();
      }
    if (model.trial_run)
      {
        stop_if_signalled(-2); // -2: in a trial, nothing written
        return;
      }
    report.write_blocks(k, time, pair_file);
    stop_if_signalled(k); // SIGINT/SIGTERM: end here, files complete
  }



  template <int dim>
  const std::vector<std::unique_ptr<Block<dim>>> &
  MultiBodyProblem<dim>::get_blocks() const
  {
    return model.blocks;
  }



  template <int dim>
  const ContactSolver<dim> *
  MultiBodyProblem<dim>::get_contact() const
  {
    return model.contact;
  }



  template struct Model<2>;
  template struct Model<3>;
  template class MultiBodyProblem<2>;
  template class MultiBodyProblem<3>;
} // namespace mbfem

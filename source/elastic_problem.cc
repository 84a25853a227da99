#include <mbfem/elastic_problem.h>
#include <mbfem/parameters.h>

#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace mbfem
{
  template <int dim>
  ElasticProblem<dim>::ElasticProblem(Parameters<dim>    &parameters,
                                      ConditionalOStream &pcout)
    : parameters(parameters)
    , pcout(pcout)
  {}



  template <int dim>
  void
  ElasticProblem<dim>::run()
  {
    // Summary printed at the end of a run that finished, not on the way
    // out of one that failed.
    TimerOutput timer(pcout, TimerOutput::never, TimerOutput::wall_times);

    Block<dim> block(parameters.material,
                     parameters.discretisation,
                     parameters.linear_solver.package);
    {
      TimerOutput::Scope t(timer, "mesh");
      create_mesh(parameters.mesh, block.triangulation);
      parameters.boundary_conditions.check_boundary_ids(
        boundary_ids_of(block.triangulation));
    }
    {
      TimerOutput::Scope t(timer, "assembly");
      parameters.boundary_conditions.set_time(0.);
      block.setup_system(parameters.boundary_conditions);

      const std::vector<Vector<double>> free_modes =
        block.free_rigid_body_modes(parameters.boundary_conditions);
      std::string description;
      for (const auto &mode : free_modes)
        description += "\n      " + Block<dim>::describe_rigid_body_mode(mode);
      AssertThrow(free_modes.empty(),
                  ExcMessage(
                    "The block is not held: 'Boundary conditions/Prescribed "
                    "displacement boundary ids' leaves " +
                    std::to_string(free_modes.size()) +
                    " rigid-body mode(s) free, so its stiffness is singular:" +
                    description +
                    "\n    Prescribe the displacement components that "
                    "remove them."));
      block.assemble_stiffness();
    }
    {
      TimerOutput::Scope t(timer, "factorisation");
      block.factorize();
    }

    pcout << "mbfem: one elastic block, " << dim << "D"
          << (dim == 2 ? " plane strain" : "") << ", FE_Q(" << block.fe.degree
          << ")^" << dim << ", MappingQ(" << block.mapping.get_degree() << ")\n"
          << "  cells: " << block.triangulation.n_active_cells()
          << ", degrees of freedom: " << block.n_dofs() << "\n"
          << "  E = " << parameters.material.youngs_modulus
          << ", nu = " << parameters.material.poissons_ratio << "\n";

    std::unique_ptr<OutputWriter> writer;
    if (parameters.output.write_vtu)
      writer = std::make_unique<OutputWriter>(parameters.output);

    const LoadHistory &history = parameters.load_history;
    for (unsigned int k = 1; k <= history.n_increments; ++k)
      {
        const double time = history.time(k);
        {
          TimerOutput::Scope t(timer, "load assembly and solve");
          block.assemble_load(parameters.boundary_conditions, time);
          block.solve();
        }
        AssertThrow(std::isfinite(block.solution.l2_norm()),
                    ExcMessage("Increment " + std::to_string(k) +
                               " (t = " + std::to_string(time) +
                               "): the displacement is not finite. A load or "
                               "prescribed displacement function gives NaN or "
                               "inf at this time. Results of the earlier "
                               "increments are in " +
                               parameters.output.directory + "."));
        pcout << "  increment " << k << "/" << history.n_increments
              << ", t = " << time << ": max |u| = " << std::scientific
              << std::setprecision(6) << block.max_displacement()
              << ", max von Mises = " << block.max_von_mises_stress()
              << std::defaultfloat << std::setprecision(6) << "\n";
        if (writer)
          {
            TimerOutput::Scope t(timer, "output");
            writer->add_step(time, {writer->write_block(block, 0, k)});
          }
      }

    if (parameters.exact_solution.enabled)
      {
        parameters.exact_solution.displacement->set_time(
          history.time(history.n_increments));
        parameters.exact_solution.stress->set_time(
          history.time(history.n_increments));
        const ErrorNorms errors =
          block.compute_errors(*parameters.exact_solution.displacement,
                               *parameters.exact_solution.stress);
        pcout << "  L2 errors against the exact solution (relative): "
              << "displacement " << std::scientific << std::setprecision(3)
              << errors.displacement_relative << ", stress "
              << errors.stress_relative << std::defaultfloat
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
                  << log_error(errors.displacement_relative) << ", stress "
                  << log_error(errors.stress_relative) << "\n";
          }
      }

    if (writer)
      pcout << "  wrote " << history.n_increments << " VTU file(s) indexed by "
            << writer->pvd_file() << "\n";
    if (!parameters.run.test_mode)
      timer.print_summary();
  }



  template class ElasticProblem<2>;
  template class ElasticProblem<3>;
} // namespace mbfem

// What a run shows and writes (RunReport): the screen's lines, the detail
// files of a model of many blocks, the VTU, CSV and JSON files of every
// increment, and the summary at the end.

#include <mbfem/analysis/block_measures.h>
#include <mbfem/analysis/parameters.h>
#include <mbfem/analysis/run_report.h>
#include <mbfem/base/files.h>
#include <mbfem/base/parallel.h>
#include <mbfem/output/interface_report.h>
#include <mbfem/output/pair_output.h>

#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace mbfem
{
  template <int dim>
  RunReport<dim>::RunReport(Model<dim> &model, const StageSequence<dim> &stages)
    : model(model)
    , stages(stages)
    , comparison(model.parameters.run.test_mode)
  {}



  template <int dim>
  void
  RunReport<dim>::print_blocks() const
  {
    const auto &first = *model.blocks.front();
    model.pcout << "mbfem: "
                << (model.blocks.size() == 1 ?
                      (model.parameters.plasticity.enabled ?
                         "one elastic-plastic block" :
                         "one elastic block") :
                      std::to_string(model.blocks.size()) + " blocks")
                << ", " << dim << "D" << (dim == 2 ? " plane strain" : "")
                << ", FE_Q(" << first.get_fe().degree << ")^" << dim
                << ", MappingQ(" << first.get_mapping().get_degree() << ")\n";
    screen = std::make_unique<ScreenDetail>(model.parameters.output,
                                            model.blocks.size(),
                                            model.pcout);
    if (screen->summary())
      print_block_counts();
    ConditionalOStream &out = screen->detail("blocks");
    for (const auto &block : model.blocks)
      {
        out << (model.blocks.size() == 1 ? "" : "  " + block->name() + ":\n")
            << "  cells: " << block->get_triangulation().n_active_cells()
            << ", degrees of freedom: " << block->n_dofs()
            << (model.parameters.discretisation.block_degrees.empty() ?
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
  RunReport<dim>::print_block_counts() const
  {
    types::global_dof_index n_dofs  = 0;
    unsigned int            n_cells = 0, n_floating = 0;
    double                  smallest = 1e300, largest = 0.;
    for (const auto &block : model.blocks)
      {
        n_dofs += block->n_dofs();
        n_cells += block->get_triangulation().n_active_cells();
        n_floating += !block->free_rigid_body_modes().empty();
        smallest =
          std::min(smallest, GridTools::volume(block->get_triangulation()));
        largest =
          std::max(largest, GridTools::volume(block->get_triangulation()));
      }
    model.pcout << "  cells: " << n_cells << ", degrees of freedom: " << n_dofs
                << "; " << n_floating << " floating block(s) held by contact; "
                << (dim == 2 ? "areas " : "volumes ") << smallest << " to "
                << largest << " (detail per block in "
                << model.parameters.output.directory << "/"
                << model.parameters.output.base_name << "-blocks.txt)\n";
  }



  template <int dim>
  void
  RunReport<dim>::print_formulation(const unsigned int n_pairs) const
  {
    const ContactSolverParameters &contact_parameters =
      model.parameters.contact_solver;
    model.pcout << "  contact formulation: "
                << (!contact_parameters.runs_monolithic() ? "condensed" :
                    !contact_parameters.runs_condensed()  ? "monolithic" :
                                                            "both");
    if (contact_parameters.runs_monolithic())
      {
        types::global_dof_index n = n_pairs * dim;
        for (const auto &block : model.blocks)
          n += block->n_dofs();
        model.pcout << " (monolithic system of " << n << " unknowns)";
      }
    model.pcout << "\n";
  }



  template <int dim>
  void
  RunReport<dim>::make_writers()
  {
    create_output_directory(model.parameters.output.directory);
    if (!model.parameters.output.write_vtu)
      return;
    writer = std::make_unique<OutputWriter>(model.parameters.output);
    if (model.contact)
      {
        OutputParameters pair_output = model.parameters.output;
        pair_output.base_name += "-pairs";
        pair_writer = std::make_unique<OutputWriter>(pair_output);
      }
  }



  template <int dim>
  std::string
  RunReport<dim>::write_contact_files(const unsigned int k,
                                      const double       time,
                                      const unsigned int iterations,
                                      const unsigned int reference_iterations)
  {
    std::vector<double> water_pressure;
    for (unsigned int i = 0; model.water && i < model.contact->pairs().size();
         ++i)
      water_pressure.push_back(model.water->pressure(i, time));
    const std::string pair_file = write_pair_files(*model.contact,
                                                   model.parameters.output,
                                                   k,
                                                   time,
                                                   water_pressure,
                                                   stages.present_pairs());
    if (model.parameters.output.write_contact_problems &&
        model.contact->formulation() == ContactFormulation::condensed)
      model.contact->condensed_problem(k, time).write(problem_stem(k, ""));
    write_summary(k, time, iterations, reference_iterations);
    return pair_file;
  }



  template <int dim>
  void
  RunReport<dim>::write_blocks(const unsigned int k,
                               const double       time,
                               const std::string &pair_file)
  {
    if (writer)
      {
        TimerOutput::Scope       t(model.timer, "output");
        std::vector<std::string> files;
        // Each rank writes the blocks it owns; an error on one ends all.
        Parallel::together(MPI_COMM_WORLD, [&]() {
          for (const auto &block : model.blocks)
            if (block->presence(time) > 0.) // not before a stage adds it
              files.push_back(writer->write_block(*block, block->get_id(), k));
        });
        writer->add_step(time, files);
        if (pair_writer)
          pair_writer->add_step(time, {pair_file});
      }
    last_written_increment = k;
  }



  template <int dim>
  void
  RunReport<dim>::print_stage(const unsigned int k) const
  {
    const LoadHistory &history = model.parameters.load_history;
    if (!history.starts_stage(k))
      return;
    const unsigned int s     = history.stage(k);
    const auto        &stage = history.stages[s];
    model.pcout << "stage " << s + 1 << "/" << history.stages.size() << " '"
                << stage.name << "': t from "
                << (s == 0 ? 0. : history.stages[s - 1].end_time) << " to "
                << stage.end_time << " in " << stage.n_increments
                << " increment(s)\n";
  }



  template <int dim>
  std::string
  RunReport<dim>::problem_stem(const unsigned int k,
                               const std::string &prefix) const
  {
    return model.parameters.output.directory + "/" +
           model.parameters.output.base_name + "-" + prefix + "problem-" +
           Utilities::int_to_string(k, 4);
  }



  template <int dim>
  std::string
  RunReport<dim>::write_failed_problem(const unsigned int k,
                                       const double       time) const
  {
    if (model.trial_run || !model.contact ||
        model.contact->formulation() != ContactFormulation::condensed)
      return "";
    const std::string stem = problem_stem(k, "failed-");
    model.contact->condensed_problem(k, time, false).write(stem);
    return "    The increment's contact problem, from the start of the step "
           "that failed, is in " +
           stem + ".json (doc/contact_problems.md).\n";
  }



  template <int dim>
  std::string
  RunReport<dim>::earlier_results() const
  {
    if (last_written_increment < 0)
      return "No increment had converged, so no results were written.";
    return "Results of the earlier increments are in " +
           model.parameters.output.directory + ".";
  }



  template <int dim>
  void
  RunReport<dim>::print_plasticity(const unsigned int   plastic_iterations,
                                   const PlasticUpdate &plastic_update) const
  {
    model.pcout << "    plasticity: " << plastic_iterations
                << " iteration(s), yielded " << plastic_update.n_yielded
                << " of " << plastic_update.n_points << " quadrature points ("
                << (dim == 2 ? "area " : "volume ") << std::scientific
                << std::setprecision(6) << plastic_update.yielded_measure
                << "), largest equivalent plastic strain "
                << plastic_update.max_equivalent << std::defaultfloat
                << std::setprecision(6) << "\n";
  }



  template <int dim>
  void
  RunReport<dim>::print_run_summary()
  {
    if (model.newton_suspensions > 0)
      model.pcout << "  Newton's tangent system had no solution in "
                  << model.newton_suspensions
                  << " step(s); the elastic stiffness "
                  << "(initial-stress method) took over in them\n";
    // A reliability run's samples are trials, which write nothing: the
    // last one's interfaces are no result.
    const bool samples_only = (model.parameters.run.mode == "reliability");
    if (model.contact && !samples_only)
      print_interface_summary(*model.contact,
                              model.parameters.contact,
                              screen->detail("interfaces"));
    if (model.reference)
      comparison.print_summary(model.pcout);
    if (model.contact && !model.parameters.run.test_mode)
      print_formulation_times();
    const LoadHistory &history = model.parameters.load_history;
    if (model.parameters.exact_solution.enabled)
      print_errors(history.time(history.n_increments));

    if (writer && !samples_only)
      model.pcout << "  wrote " << history.n_increments << " VTU file(s)"
                  << (model.blocks.size() > 1 ? " per block" : "")
                  << " indexed by " << writer->pvd_file() << "\n";
    const std::string base = model.parameters.output.directory + "/" +
                             model.parameters.output.base_name;
    if (model.contact && !model.parameters.run.test_mode && !samples_only)
      model.pcout << "  contact pairs per increment in " << base
                  << "-pairs-*.csv, a line per increment in " << base
                  << "-summary.csv\n";
    if (screen && screen->summary())
      model.pcout << "  " << screen->files() << "\n";
    if (!model.parameters.run.test_mode)
      model.timer.print_summary();
  }



  template <int dim>
  void
  RunReport<dim>::print_formulation_times() const
  {
    const ContactSolverParameters &contact_parameters =
      model.parameters.contact_solver;
    model.pcout << "  time of the contact formulation(s) alone (wall, s): ";
    if (contact_parameters.runs_condensed())
      model.pcout << "condensed " << std::setprecision(3)
                  << model.condensed_seconds
                  << " (factorisation, flexibility, load response, contact "
                     "iterations, recovery)";
    const auto [computed, all] = stages.columns_on_demand();
    if (all > 0)
      model.pcout << ", flexibility on demand: " << computed << " of " << all
                  << " columns computed";
    if (contact_parameters.runs_condensed() &&
        contact_parameters.runs_monolithic())
      model.pcout << "; ";
    if (contact_parameters.runs_monolithic())
      model.pcout << "monolithic " << std::setprecision(3)
                  << model.monolithic_seconds
                  << " (assembly, contact iterations with one sparse LU "
                     "each, recovery)";
    model.pcout << std::setprecision(6) << "\n";
  }



  template <int dim>
  void
  RunReport<dim>::print_plastic_progress(const unsigned int plastic_iterations,
                                         const double       change,
                                         const double       omega,
                                         const unsigned int n_yielded) const
  {
    // Progress on long runs: a line every 100 iterations, or every Newton
    // iteration (few, each with new factorisations).
    if (model.parameters.run.test_mode)
      return;
    if (omega < 0.)
      model.pcout << "    Newton iteration " << plastic_iterations
                  << ": residual " << std::scientific << std::setprecision(3)
                  << change << std::defaultfloat << ", " << n_yielded
                  << " points yielded" << std::setprecision(6) << "\n";
    else if (plastic_iterations % 100 == 0)
      model.pcout << "    plastic iteration " << plastic_iterations
                  << ": change " << std::scientific << std::setprecision(3)
                  << change << ", relaxation " << std::defaultfloat << omega
                  << ", " << n_yielded << " points yielded"
                  << std::setprecision(6) << "\n";
  }



  template <int dim>
  void
  RunReport<dim>::compare_formulations()
  {
    double displacement_scale = 1e-300;
    for (const auto &block : model.blocks)
      displacement_scale =
        std::max(displacement_scale, max_displacement(*block));
    comparison.compare(*model.contact,
                       *model.reference,
                       displacement_scale,
                       model.pcout);
  }



  template <int dim>
  std::string
  RunReport<dim>::summary_header() const
  {
    std::string header =
      "# " + to_string(model.contact->formulation()) + " formulation" +
      (model.reference ? " with the monolithic reference" : "") +
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
    header += "increment,t,iterations,stick,slip,open,max_gap,"
              "max_slip,max_normal_traction,seconds,method,"
              "fast_iterations,path_switches";
    if (model.reference)
      header += ",reference_iterations,reference_seconds,"
                "states_differ,force_difference,gap_difference,"
                "slip_difference";
    if (model.parameters.load_history.has_stages())
      header += ",stage";
    header += "\n";
    return header;
  }



  template <int dim>
  void
  RunReport<dim>::write_summary(const unsigned int k,
                                const double       time,
                                const unsigned int iterations,
                                const unsigned int reference_iterations)
  {
    if (summary_csv.empty())
      summary_csv = summary_header();
    double max_gap = 0., max_p = 0.;
    for (unsigned int i = 0; i < model.contact->pairs().size(); ++i)
      {
        max_gap = std::max(max_gap, model.contact->gap(i));
        max_p   = std::max(max_p,
                         model.contact->local_force(i)[0] /
                           model.contact->pairs()[i].area);
      }
    char buffer[256];
    std::snprintf(buffer,
                  sizeof(buffer),
                  "%u,%.10g,%u,%u,%u,%u,%.10e,%.10e,%.10e,%.4f",
                  k,
                  time,
                  iterations,
                  model.contact->count(ContactState::stick),
                  model.contact->count(ContactState::slip),
                  model.contact->count(ContactState::open),
                  max_gap,
                  max_slip(*model.contact),
                  max_p,
                  model.increment_contact_seconds);
    summary_csv += buffer;
    // Which method concluded the state iteration, and its share of the
    // iterations (doc/state_iteration.md).
    summary_csv += "," + model.contact->last_method() + "," +
                   std::to_string(model.contact->last_iterations().first) +
                   "," +
                   std::to_string(model.contact->last_iterations().second);
    if (model.reference)
      {
        std::snprintf(buffer,
                      sizeof(buffer),
                      ",%u,%.4f,%u,%.3e,%.3e,%.3e",
                      reference_iterations,
                      model.last_reference_seconds,
                      static_cast<unsigned int>(comparison.last()[0]),
                      comparison.last()[1],
                      comparison.last()[2],
                      comparison.last()[3]);
        summary_csv += buffer;
      }
    const LoadHistory &history = model.parameters.load_history;
    if (history.has_stages())
      summary_csv += "," + history.stages[history.stage(k)].name;
    summary_csv += "\n";
    write_file_atomically(model.parameters.output.directory + "/" +
                            model.parameters.output.base_name + "-summary.csv",
                          summary_csv);
  }



  template <int dim>
  void
  RunReport<dim>::print_increment(const unsigned int k,
                                  const double       time,
                                  const unsigned int iterations) const
  {
    double max_u = 0., max_von_mises = 0.;
    for (const auto &block : model.blocks)
      {
        max_u         = std::max(max_u, max_displacement(*block));
        max_von_mises = std::max(max_von_mises, max_von_mises_stress(*block));
      }
    model.pcout << "  increment " << k << "/"
                << model.parameters.load_history.n_increments
                << ", t = " << time << ": ";
    if (model.contact)
      {
        // The range of the normal traction over the pairs that are not
        // tied (0 and 0 where every pair is tied).
        double min_normal = 1e300, max_normal = -1e300, max_tangential = 0.,
               max_gap = 0.;
        for (unsigned int i = 0; i < model.contact->pairs().size(); ++i)
          {
            if (model.contact->pairs()[i].tied)
              continue; // its frame is the global axes
            const Tensor<1, dim> rho        = model.contact->local_force(i);
            const double         area       = model.contact->pairs()[i].area;
            Tensor<1, dim>       tangential = rho;
            tangential[0]                   = 0.;
            min_normal     = std::min(min_normal, rho[0] / area);
            max_normal     = std::max(max_normal, rho[0] / area);
            max_tangential = std::max(max_tangential, tangential.norm() / area);
            max_gap        = std::max(max_gap, model.contact->gap(i));
          }
        if (min_normal > max_normal)
          min_normal = max_normal = 0.;
        // Which method concluded the state iteration: named only where
        // the fast iteration did not (the screen lines of the increments
        // it concludes stay as they were).
        model.pcout << iterations << " iteration(s)";
        if (model.contact->last_method() != "fast")
          model.pcout << " (fast " << model.contact->last_iterations().first
                      << ", " << model.contact->last_method() << " "
                      << model.contact->last_iterations().second << ")";
        if (!model.parameters.run.test_mode)
          model.pcout << " in " << std::setprecision(3)
                      << model.increment_contact_seconds << " s"
                      << std::setprecision(6);
        model.pcout << ", stick/slip/open "
                    << model.contact->count(ContactState::stick) << "/"
                    << model.contact->count(ContactState::slip) << "/"
                    << model.contact->count(ContactState::open) << ", p in ["
                    << std::scientific << std::setprecision(6) << min_normal
                    << ", " << max_normal << "], max |q| = " << max_tangential
                    << ", max gap = " << max_gap
                    << ", max slip = " << max_slip(*model.contact) << ", ";
      }
    model.pcout << "max |u| = " << std::scientific << std::setprecision(6)
                << max_u << ", max von Mises = " << max_von_mises
                << std::defaultfloat << std::setprecision(6) << "\n";

    if (model.water)
      model.pcout << "    water in the joints: sum of p_w A = "
                  << std::scientific << std::setprecision(6)
                  << model.water->resultant(time) << std::defaultfloat
                  << std::setprecision(6) << "\n";
    if (model.contact)
      print_resultants(k, time);
  }



  template <int dim>
  void
  RunReport<dim>::print_resultants(const unsigned int k,
                                   const double       time) const
  {
    // The resultant each interface transmits (force on its side b).
    std::vector<Tensor<1, dim>> resultant(
      model.parameters.contact.interfaces.size());
    for (unsigned int p = 0; p < model.contact->pairs().size(); ++p)
      resultant[model.contact->pairs()[p].interface] += model.contact->force(p);
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
  RunReport<dim>::print_errors(const double time) const
  {
    model.parameters.exact_solution.displacement->set_time(time);
    model.parameters.exact_solution.stress->set_time(time);
    std::vector<ErrorNorms> errors;
    for (const auto &block : model.blocks)
      errors.push_back(
        compute_errors(*block,
                       *model.parameters.exact_solution.displacement,
                       *model.parameters.exact_solution.stress));
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
    model.pcout << "  L2 errors against the exact solution (relative): "
                << "displacement " << error_text(u_error2, u_norm2)
                << ", stress " << error_text(s_error2, s_norm2) << "\n";

    // numdiff takes numbers within 1e-6 of each other as equal, which
    // would let any change of a small error pass: compare logarithms.
    // Below 1e-9 an error is round-off, whose digits vary by machine.
    if (model.parameters.run.test_mode)
      {
        const auto log_error = [](const double e) {
          std::ostringstream s;
          if (e < 1e-9)
            s << "below 1e-9";
          else
            s << std::fixed << std::setprecision(4) << std::log10(e);
          return s.str();
        };
        model.pcout << "  log10 of the relative errors: displacement "
                    << log_error(u_relative) << ", stress "
                    << log_error(s_relative) << "\n";
      }
  }



  template class RunReport<2>;
  template class RunReport<3>;
} // namespace mbfem

#include <mbfem/analysis/block_measures.h>
#include <mbfem/analysis/order_study.h>
#include <mbfem/base/parallel.h>
#include <mbfem/base/parameters.h>
#include <mbfem/base/text_input.h>

#include <deal.II/base/timer.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <sstream>

namespace mbfem
{
  void
  OrderStudyParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Order study");
    {
      prm.declare_entry("Polynomial degrees",
                        "1, 2, 3, 4",
                        Patterns::List(Patterns::Integer(1, 4)),
                        "Element degrees p compared in Mode = order study.");
      prm.declare_entry(
        "Refinement levels",
        "0, 1, 2, 3",
        Patterns::List(Patterns::Integer(0, 12)),
        "Global refinements of the mesh of subsection Mesh, in increasing "
        "order; each halves the cell size, which defines the rates. "
        "'Mesh/Initial global refinement' is ignored in an order study.");
      prm.declare_entry(
        "Round-off floor",
        "1e-12",
        Patterns::Double(0.),
        "Relative errors below this are taken as round-off and get no rate: "
        "where the exact solution lies in the finite element space (a "
        "polynomial of degree <= p) the error is only the solver's round-off, "
        "which grows with the number of unknowns.");
      prm.declare_entry("Table file",
                        "order_study.csv",
                        Patterns::Anything(),
                        "CSV file, in Output/Directory, of the study table.");
    }
    prm.leave_subsection();
  }



  void
  OrderStudyParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Order study");
    {
      degrees.clear();
      refinements.clear();
      for (const unsigned int p :
           parse_id_list(prm.get("Polynomial degrees"),
                         "Order study/Polynomial degrees"))
        degrees.push_back(p);
      for (const unsigned int r :
           parse_id_list(prm.get("Refinement levels"),
                         "Order study/Refinement levels"))
        refinements.push_back(r);
      table_file      = prm.get("Table file");
      round_off_floor = prm.get_double("Round-off floor");
    }
    prm.leave_subsection();
    AssertThrow(!table_file.empty() &&
                  table_file.find('/') == std::string::npos &&
                  table_file != "." && table_file != "..",
                ExcMessage("Order study/Table file = '" + table_file +
                           "': name a file (written in Output/Directory), "
                           "e.g. 'order_study.csv'."));
    AssertThrow(!degrees.empty() && !refinements.empty(),
                ExcMessage("Order study: 'Polynomial degrees' and 'Refinement "
                           "levels' each need at least one value; the study "
                           "would have no rows."));
    for (unsigned int i = 1; i < refinements.size(); ++i)
      AssertThrow(refinements[i] > refinements[i - 1],
                  ExcMessage("Order study/Refinement levels must increase."));
  }



  template <int dim>
  OrderStudy<dim>::OrderStudy(const Parameters<dim> &parameters,
                              ConditionalOStream    &pcout)
    : parameters(parameters)
    , pcout(pcout)
  {}



  template <int dim>
  OrderStudyRow
  OrderStudy<dim>::solve_one(const unsigned int degree,
                             const unsigned int refinement) const
  {
    DiscretisationParameters discretisation = parameters.discretisation;
    discretisation.degree                   = degree;
    discretisation.mapping_degree           = degree;
    discretisation.mapping_follows_degree   = false;
    discretisation.block_degrees.clear();
    MeshParameters mesh     = parameters.mesh;
    mesh.initial_refinement = refinement;

    // The functions are evaluated at the end of the load history; the
    // study is of the discretisation, not of the path.
    BoundaryConditions<dim> boundary_conditions =
      parameters.boundary_conditions;
    const double time =
      parameters.load_history.time(parameters.load_history.n_increments);
    boundary_conditions.set_time(time);

    Block<dim> block(parameters.material,
                     discretisation,
                     parameters.linear_solver.package);
    block.create_mesh(mesh);
    boundary_conditions.check_boundary_ids(
      boundary_ids_of(block.get_triangulation()));
    block.setup_system(boundary_conditions);
    block.assemble_stiffness();
    block.factorize();
    block.assemble_load(boundary_conditions, time);
    block.solve();

    parameters.exact_solution.displacement->set_time(time);
    parameters.exact_solution.stress->set_time(time);
    const ErrorNorms errors =
      compute_errors(block,
                     *parameters.exact_solution.displacement,
                     *parameters.exact_solution.stress);
    // The study does not run the simulation's checks of the functions: a
    // load of y^0.5 (NaN below y = 0) filled the table with -nan.
    AssertThrow(std::isfinite(block.get_solution().l2_norm()) &&
                  std::isfinite(errors.displacement) &&
                  std::isfinite(errors.stress),
                ExcMessage("Order study, p = " + std::to_string(degree) +
                           ", refinement level " + std::to_string(refinement) +
                           ": the displacement or its L2 error against "
                           "'Exact solution' is not finite. A load, "
                           "prescribed displacement or exact-solution "
                           "function is not finite on the mesh (or so large "
                           "that its square overflows); check the "
                           "functions."));

    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {degree,
            refinement,
            block.get_triangulation().n_active_cells(),
            static_cast<unsigned int>(block.n_dofs()),
            errors.displacement_relative,
            errors.stress_relative,
            nan,
            nan};
  }



  template <int dim>
  void
  OrderStudy<dim>::compute_rates(std::vector<OrderStudyRow> &rows,
                                 const double                round_off_floor)
  {
    const auto rate = [round_off_floor](const double e_coarse,
                                        const double e_fine,
                                        const double levels) {
      if (e_coarse < round_off_floor || e_fine < round_off_floor)
        return std::numeric_limits<double>::quiet_NaN();
      return std::log2(e_coarse / e_fine) / levels;
    };
    for (unsigned int i = 1; i < rows.size(); ++i)
      if (rows[i].degree == rows[i - 1].degree)
        {
          const double levels = rows[i].refinement - rows[i - 1].refinement;
          rows[i].displacement_rate = rate(rows[i - 1].displacement_error,
                                           rows[i].displacement_error,
                                           levels);
          rows[i].stress_rate =
            rate(rows[i - 1].stress_error, rows[i].stress_error, levels);
        }
  }



  namespace
  {
    std::string
    format(const char *format, const double value)
    {
      if (std::isnan(value))
        return "-";
      char buffer[64];
      std::snprintf(buffer, sizeof(buffer), format, value);
      return buffer;
    }
  } // namespace



  template <int dim>
  void
  OrderStudy<dim>::print_table(const std::vector<OrderStudyRow> &rows) const
  {
    pcout << "\n"
          << "   p  level    cells     DoFs   L2 error u  rate   "
             "L2 error sigma  rate\n";
    for (const auto &row : rows)
      {
        char line[256];
        std::snprintf(line,
                      sizeof(line),
                      "%4u %6u %8u %8u   %10.3e %5s   %14.3e %5s\n",
                      row.degree,
                      row.refinement,
                      row.n_cells,
                      row.n_dofs,
                      row.displacement_error,
                      format("%.2f", row.displacement_rate).c_str(),
                      row.stress_error,
                      format("%.2f", row.stress_rate).c_str());
        pcout << line;
      }
    pcout << "  (relative L2 errors; rate = log2 of the error ratio between "
             "levels; '-' where an\n   error is below the round-off floor "
          << parameters.order_study.round_off_floor
          << " and no rate can be observed)\n";
  }



  template <int dim>
  void
  OrderStudy<dim>::write_csv(const std::vector<OrderStudyRow> &rows) const
  {
    std::ostringstream csv;
    csv << "degree,refinement,cells,dofs,displacement_error,"
           "displacement_rate,stress_error,stress_rate\n";
    for (const auto &row : rows)
      {
        char line[256];
        std::snprintf(line,
                      sizeof(line),
                      "%u,%u,%u,%u,%.6e,%s,%.6e,%s\n",
                      row.degree,
                      row.refinement,
                      row.n_cells,
                      row.n_dofs,
                      row.displacement_error,
                      format("%.4f", row.displacement_rate).c_str(),
                      row.stress_error,
                      format("%.4f", row.stress_rate).c_str());
        csv << line;
      }
    create_output_directory(parameters.output.directory);
    const std::string path =
      parameters.output.directory + "/" + parameters.order_study.table_file;
    write_file_atomically(path, csv.str());
    if (!parameters.run.test_mode)
      pcout << "  table written to " << path << "\n";
  }



  template <int dim>
  std::vector<OrderStudyRow>
  OrderStudy<dim>::solve_all(const Timer &timer) const
  {
    std::vector<std::pair<unsigned int, unsigned int>> cases;
    for (const auto p : parameters.order_study.degrees)
      for (const auto r : parameters.order_study.refinements)
        cases.emplace_back(p, r);

    // Under mpirun the cases are independent: each rank solves its share
    // (balanced by cells x DoFs per cell, 2^(dim r) (p + 1)^dim), and the
    // rows go from the rank that computed each to all.
    const unsigned int  n_ranks = Parallel::n_ranks();
    std::vector<double> costs;
    for (const auto &[p, r] : cases)
      costs.push_back(std::pow(2., dim * r) * std::pow(p + 1., dim));
    const std::vector<unsigned int> owners =
      Parallel::assign_owners(costs, n_ranks);
    const unsigned int rank =
      n_ranks > 1 ? Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) : 0;

    std::vector<OrderStudyRow> rows(cases.size(), OrderStudyRow());
    // A failure ends the study with the message of the first case that
    // failed, in the table's order, as on one process.
    unsigned int       first_failure = cases.size();
    std::exception_ptr failure;
    for (unsigned int i = 0; i < cases.size(); ++i)
      if (owners[i] == rank)
        {
          const auto &[p, r] = cases[i];
          try
            {
              rows[i] = solve_one(p, r);
            }
          catch (...)
            {
              first_failure = i;
              failure       = std::current_exception();
              break;
            }
          if (!parameters.run.test_mode && n_ranks == 1)
            pcout << "  p = " << p << ", level " << r << ": " << rows[i].n_dofs
                  << " DoFs, " << timer.wall_time() << " s so far" << std::endl;
        }
    if (n_ranks > 1)
      first_failure = Utilities::MPI::min(first_failure, MPI_COMM_WORLD);
    if (first_failure < cases.size())
      Parallel::on_owner(MPI_COMM_WORLD, owners[first_failure], [&]() {
        std::rethrow_exception(failure);
      });
    if (n_ranks > 1)
      {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (unsigned int i = 0; i < cases.size(); ++i)
          {
            std::array<double, 6> values = {{double(rows[i].degree),
                                             double(rows[i].refinement),
                                             double(rows[i].n_cells),
                                             double(rows[i].n_dofs),
                                             rows[i].displacement_error,
                                             rows[i].stress_error}};
            Parallel::broadcast(MPI_COMM_WORLD,
                                owners[i],
                                values.data(),
                                values.size());
            rows[i] = {static_cast<unsigned int>(values[0]),
                       static_cast<unsigned int>(values[1]),
                       static_cast<unsigned int>(values[2]),
                       static_cast<unsigned int>(values[3]),
                       values[4],
                       values[5],
                       nan, // compute_rates() sets them
                       nan};
          }
        if (!parameters.run.test_mode)
          pcout << "  " << cases.size() << " cases on " << n_ranks
                << " MPI ranks: " << timer.wall_time() << " s" << std::endl;
      }
    return rows;
  }



  template <int dim>
  void
  OrderStudy<dim>::run()
  {
    pcout << "mbfem: element-order study, " << dim << "D"
          << (dim == 2 ? " plane strain" : "") << ", degrees";
    for (const auto p : parameters.order_study.degrees)
      pcout << " " << p;
    pcout << ", refinement levels";
    for (const auto r : parameters.order_study.refinements)
      pcout << " " << r;
    pcout << std::endl;

    Timer                      timer;
    std::vector<OrderStudyRow> rows = solve_all(timer);
    compute_rates(rows, parameters.order_study.round_off_floor);
    print_table(rows);
    write_csv(rows);
    if (!parameters.run.test_mode)
      pcout << "  wall time: " << timer.wall_time() << " s\n";
  }



  template class OrderStudy<2>;
  template class OrderStudy<3>;
} // namespace mbfem

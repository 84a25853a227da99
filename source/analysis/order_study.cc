#include <mbfem/analysis/block_measures.h>
#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/order_study.h>
#include <mbfem/analysis/parameters.h>
#include <mbfem/base/parallel.h>
#include <mbfem/base/text_input.h>
#include <mbfem/mesh/mesh.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <limits>
#include <set>
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
      prm.declare_entry(
        "Block degrees",
        "same",
        Patterns::Selection("same|all combinations"),
        "Models of several blocks (each is run whole, contact included, and "
        "the table has the errors of every block): 'same' gives every block "
        "each degree of 'Polynomial degrees' in turn; 'all combinations' "
        "every assignment of those degrees to the blocks (n_degrees^n_blocks "
        "rows per level, at most 64). 'Finite element/Block degrees' is "
        "ignored in an order study; 'Mesh/Block refinements' is added to each "
        "level. A one-block model ignores this.");
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
      block_degrees   = prm.get("Block degrees");
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
  std::vector<std::vector<unsigned int>>
  OrderStudy<dim>::degree_cases() const
  {
    const std::vector<unsigned int> &degrees  = parameters.order_study.degrees;
    const unsigned int               n_blocks = block_ids.size();
    std::vector<std::vector<unsigned int>> cases;
    if (n_blocks <= 1 || parameters.order_study.block_degrees == "same")
      {
        for (const unsigned int p : degrees)
          cases.emplace_back(std::max(n_blocks, 1u), p);
        return cases;
      }
    const double n_cases = std::pow(double(degrees.size()), double(n_blocks));
    AssertThrow(n_cases <= 64,
                ExcMessage("Order study/Block degrees = all combinations: " +
                           std::to_string(degrees.size()) + " degrees over " +
                           std::to_string(n_blocks) + " blocks make " +
                           std::to_string(static_cast<long>(n_cases)) +
                           " combinations per level (at most 64). List fewer "
                           "'Polynomial degrees', or use 'same'."));
    // Like an odometer: the last block's degree varies fastest.
    std::vector<unsigned int> index(n_blocks, 0);
    for (unsigned int c = 0; c < static_cast<unsigned int>(n_cases); ++c)
      {
        std::vector<unsigned int> combination;
        for (const unsigned int i : index)
          combination.push_back(degrees[i]);
        cases.push_back(combination);
        for (int b = n_blocks - 1; b >= 0; --b)
          if (++index[b] < degrees.size())
            break;
          else
            index[b] = 0;
      }
    return cases;
  }



  template <int dim>
  OrderStudyRow
  OrderStudy<dim>::solve_one(const std::vector<unsigned int> &degrees,
                             const unsigned int               refinement) const
  {
    return whole_model ? solve_model(degrees, refinement) :
                         solve_block(degrees[0], refinement);
  }



  template <int dim>
  OrderStudyRow
  OrderStudy<dim>::solve_block(const unsigned int degree,
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

    OrderStudyRow row;
    row.degrees                  = {degree};
    row.refinement               = refinement;
    row.n_cells                  = block.get_triangulation().n_active_cells();
    row.n_dofs                   = block.n_dofs();
    row.total.displacement_error = errors.displacement_relative;
    row.total.stress_error       = errors.stress_relative;
    return row;
  }



  namespace
  {
    /**
     * "1/3/2": the degrees of a row's blocks, or "2" where @p same (a short
     * name however many blocks the model has; 'all combinations' is
     * refused beyond 64 rows, i.e. 6 blocks).
     */
    std::string
    degrees_text(const std::vector<unsigned int> &degrees,
                 const char                      *separator,
                 const bool                       same)
    {
      if (same)
        return std::to_string(degrees[0]);
      std::string text;
      for (unsigned int b = 0; b < degrees.size(); ++b)
        text += (b > 0 ? separator : "") + std::to_string(degrees[b]);
      return text;
    }



  } // namespace



  template <int dim>
  Parameters<dim>
  OrderStudy<dim>::case_parameters(const std::vector<unsigned int> &degrees,
                                   const unsigned int refinement) const
  {
    Parameters<dim> model         = parameters;
    model.run.mode                = "simulation";
    model.run.test_mode           = true; // no timings: the run is silent
    model.mesh.initial_refinement = refinement;
    model.discretisation.mapping_follows_degree = true;
    model.discretisation.degree = degrees[0]; // blocks a stage removes
    model.discretisation.block_degrees.clear();
    for (unsigned int b = 0; b < block_ids.size(); ++b)
      model.discretisation.block_degrees[block_ids[b]] = degrees[b];
    model.output.base_name = parameters.output.base_name + "-p" +
                             degrees_text(degrees, "_", same_degrees) +
                             "-level" + std::to_string(refinement);
    return model;
  }



  template <int dim>
  OrderStudyRow
  OrderStudy<dim>::solve_model(const std::vector<unsigned int> &degrees,
                               const unsigned int refinement) const
  {
    Parameters<dim> model = case_parameters(degrees, refinement);
    // The run prints nothing; a failure ends the study with its message
    // (and exit code) after the line that names the case.
    ConditionalOStream    silent(std::cout, false);
    MultiBodyProblem<dim> problem(model, silent);
    try
      {
        problem.run();
      }
    catch (...)
      {
        pcout << "  the case p = " << degrees_text(degrees, "/", same_degrees)
              << ", level " << refinement
              << " failed (whatever it wrote is under "
              << model.output.directory << "/" << model.output.base_name
              << "-*):" << std::endl;
        throw;
      }

    OrderStudyRow row = errors_of(problem.get_blocks());
    row.degrees       = degrees;
    row.refinement    = refinement;
    AssertThrow(std::isfinite(row.total.displacement_error) &&
                  std::isfinite(row.total.stress_error),
                ExcMessage("Order study, p = " +
                           degrees_text(degrees, "/", same_degrees) +
                           ", refinement level " + std::to_string(refinement) +
                           ": the L2 error against 'Exact solution' is not "
                           "finite; check its functions."));
    return row;
  }



  template <int dim>
  OrderStudyRow
  OrderStudy<dim>::errors_of(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks) const
  {
    const double time =
      parameters.load_history.time(parameters.load_history.n_increments);
    parameters.exact_solution.displacement->set_time(time);
    parameters.exact_solution.stress->set_time(time);
    OrderStudyRow           row;
    std::vector<ErrorNorms> errors;
    for (const auto &block : blocks)
      {
        // Blocks that a stage removed are not part of the final body.
        if (std::find(block_ids.begin(), block_ids.end(), block->get_id()) ==
            block_ids.end())
          continue;
        errors.push_back(compute_errors(*block,
                                        *parameters.exact_solution.displacement,
                                        *parameters.exact_solution.stress));
        row.n_cells += block->get_triangulation().n_active_cells();
        row.n_dofs += block->n_dofs();
        OrderStudyErrors e;
        e.displacement_error = errors.back().displacement_relative;
        e.stress_error       = errors.back().stress_relative;
        row.blocks.push_back(e);
      }
    const ErrorNorms total       = combine_errors(errors);
    row.total.displacement_error = total.displacement_relative;
    row.total.stress_error       = total.stress_relative;
    return row;
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
    const auto set_rates = [&rate](const OrderStudyErrors &coarse,
                                   OrderStudyErrors       &fine,
                                   const double            levels) {
      fine.displacement_rate =
        rate(coarse.displacement_error, fine.displacement_error, levels);
      fine.stress_rate = rate(coarse.stress_error, fine.stress_error, levels);
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (unsigned int i = 0; i < rows.size(); ++i)
      {
        rows[i].total.displacement_rate = rows[i].total.stress_rate = nan;
        for (auto &block : rows[i].blocks)
          block.displacement_rate = block.stress_rate = nan;
        if (i == 0 || rows[i].degrees != rows[i - 1].degrees)
          continue;
        const double levels = rows[i].refinement - rows[i - 1].refinement;
        set_rates(rows[i - 1].total, rows[i].total, levels);
        for (unsigned int b = 0; b < rows[i].blocks.size(); ++b)
          set_rates(rows[i - 1].blocks[b], rows[i].blocks[b], levels);
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



    /**
     * The displacement error, its rate, the stress error and its rate of
     * @p e, laid out by @p layout (four fields: %e, %s, %e, %s), the
     * rates by @p rate_format ('-' where there is none).
     */
    std::string
    errors_text(const char             *layout,
                const char             *rate_format,
                const OrderStudyErrors &e)
    {
      char text[128];
      std::snprintf(text,
                    sizeof(text),
                    layout,
                    e.displacement_error,
                    format(rate_format, e.displacement_rate).c_str(),
                    e.stress_error,
                    format(rate_format, e.stress_rate).c_str());
      return text;
    }
  } // namespace



  template <int dim>
  void
  OrderStudy<dim>::print_table(const std::vector<OrderStudyRow> &rows) const
  {
    if (whole_model)
      return print_block_table(rows);
    pcout << "\n"
          << "   p  level    cells     DoFs   L2 error u  rate   "
             "L2 error sigma  rate\n";
    for (const auto &row : rows)
      {
        char line[256];
        std::snprintf(line,
                      sizeof(line),
                      "%4u %6u %8u %8u   %10.3e %5s   %14.3e %5s\n",
                      row.degrees[0],
                      row.refinement,
                      row.n_cells,
                      row.n_dofs,
                      row.total.displacement_error,
                      format("%.2f", row.total.displacement_rate).c_str(),
                      row.total.stress_error,
                      format("%.2f", row.total.stress_rate).c_str());
        pcout << line;
      }
    pcout << "  (relative L2 errors; rate = log2 of the error ratio between "
             "levels; '-' where an\n   error is below the round-off floor "
          << parameters.order_study.round_off_floor
          << " and no rate can be observed)\n";
  }



  template <int dim>
  void
  OrderStudy<dim>::print_block_table(
    const std::vector<OrderStudyRow> &rows) const
  {
    // The model's errors and rates first, then each block's.
    pcout << "\n  degrees p of blocks";
    for (const auto id : block_ids)
      pcout << " " << static_cast<unsigned int>(id);
    pcout << "; relative L2 errors of the model, then of each block\n";
    std::string header = "  p        level     DoFs    u model  rate  "
                         "sigma model  rate";
    for (const auto id : block_ids)
      {
        const std::string b = std::to_string(id);
        char              column[128];
        std::snprintf(column,
                      sizeof(column),
                      "  %8s  rate  %10s  rate",
                      ("u " + b).c_str(),
                      ("sigma " + b).c_str());
        header += column;
      }
    pcout << header << "\n";
    for (const auto &row : rows)
      {
        pcout << "  " << std::left << std::setw(8)
              << degrees_text(row.degrees, "/", same_degrees) << std::right
              << " " << std::setw(5) << row.refinement << " " << std::setw(8)
              << row.n_dofs
              << errors_text("  %9.3e %5s  %11.3e %5s", "%.2f", row.total);
        for (const auto &block : row.blocks)
          pcout << errors_text("  %8.2e %5s  %10.2e %5s", "%.2f", block);
        pcout << "\n";
      }
    pcout << "  (rate = log2 of the error ratio between levels; '-' where an "
             "error is below the\n   round-off floor "
          << parameters.order_study.round_off_floor
          << " and no rate can be observed)\n";
  }



  template <int dim>
  void
  OrderStudy<dim>::write_csv(const std::vector<OrderStudyRow> &rows) const
  {
    // A one-block table keeps its columns; a model of several blocks adds
    // each block's degree and errors (columns named by block id).
    const bool         several = whole_model;
    std::ostringstream csv;
    csv << (several ? "degrees" : "degree")
        << ",refinement,cells,dofs,displacement_error,"
           "displacement_rate,stress_error,stress_rate";
    if (several)
      {
        for (const auto id : block_ids)
          csv << ",degree_" << static_cast<unsigned int>(id);
        for (const auto id : block_ids)
          {
            const std::string b = std::to_string(id);
            csv << ",displacement_error_" << b << ",displacement_rate_" << b
                << ",stress_error_" << b << ",stress_rate_" << b;
          }
      }
    csv << "\n";
    for (const auto &row : rows)
      {
        csv << degrees_text(row.degrees, "/", same_degrees) << ","
            << row.refinement << "," << row.n_cells << "," << row.n_dofs
            << errors_text(",%.6e,%s,%.6e,%s", "%.4f", row.total);
        if (several)
          {
            for (const unsigned int p : row.degrees)
              csv << "," << p;
            for (const auto &block : row.blocks)
              csv << errors_text(",%.6e,%s,%.6e,%s", "%.4f", block);
          }
        csv << "\n";
      }
    create_output_directory(parameters.output.directory);
    const std::string path =
      parameters.output.directory + "/" + parameters.order_study.table_file;
    write_file_atomically(path, csv.str());
    if (!parameters.run.test_mode)
      pcout << "  table written to " << path << "\n";
  }



  namespace
  {
    /**
     * Under mpirun: each row of @p rows from the rank that computed it
     * (@p owners) to all (the rates are computed afterwards).
     */
    void
    share_rows(const std::vector<unsigned int> &owners,
               std::vector<OrderStudyRow>      &rows)
    {
      for (unsigned int i = 0; i < rows.size(); ++i)
        {
          std::array<double, 6> values = {
            {double(rows[i].degrees.empty() ? 0 : rows[i].degrees[0]),
             double(rows[i].refinement),
             double(rows[i].n_cells),
             double(rows[i].n_dofs),
             rows[i].total.displacement_error,
             rows[i].total.stress_error}};
          Parallel::broadcast(MPI_COMM_WORLD,
                              owners[i],
                              values.data(),
                              values.size());
          rows[i].degrees    = {static_cast<unsigned int>(values[0])};
          rows[i].refinement = static_cast<unsigned int>(values[1]);
          rows[i].n_cells    = static_cast<unsigned int>(values[2]);
          rows[i].n_dofs     = static_cast<unsigned int>(values[3]);
          rows[i].total.displacement_error = values[4];
          rows[i].total.stress_error       = values[5];
          // compute_rates() sets the rates
        }
    }
  } // namespace



  template <int dim>
  std::vector<OrderStudyRow>
  OrderStudy<dim>::solve_all(const Timer &timer) const
  {
    std::vector<std::pair<std::vector<unsigned int>, unsigned int>> cases;
    for (const auto &degrees : degree_cases())
      for (const auto r : parameters.order_study.refinements)
        cases.emplace_back(degrees, r);

    // Under mpirun the cases of a one-block study are independent: each
    // rank solves its share (balanced by cells x DoFs per cell,
    // 2^(dim r) (p + 1)^dim), and the rows go from the rank that computed
    // each to all. A model of several blocks is shared out by blocks
    // instead (MultiBodyProblem), so every rank takes part in every case.
    const bool          by_cases = block_ids.size() <= 1;
    const unsigned int  n_ranks  = by_cases ? Parallel::n_ranks() : 1;
    std::vector<double> costs;
    for (const auto &[degrees, r] : cases)
      costs.push_back(
        std::pow(2., dim * r) *
        std::pow(*std::max_element(degrees.begin(), degrees.end()) + 1., dim));
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
          const auto &[degrees, r] = cases[i];
          try
            {
              rows[i] = solve_one(degrees, r);
            }
          catch (...)
            {
              first_failure = i;
              failure       = std::current_exception();
              break;
            }
          if (!parameters.run.test_mode && n_ranks == 1)
            pcout << "  p = " << degrees_text(degrees, "/", same_degrees)
                  << ", level " << r << ": " << rows[i].n_dofs << " DoFs, "
                  << timer.wall_time() << " s so far" << std::endl;
        }
    if (n_ranks > 1)
      first_failure = Utilities::MPI::min(first_failure, MPI_COMM_WORLD);
    if (first_failure < cases.size())
      Parallel::on_owner(MPI_COMM_WORLD, owners[first_failure], [&]() {
        std::rethrow_exception(failure);
      });
    if (n_ranks > 1)
      {
        share_rows(owners, rows);
        if (!parameters.run.test_mode)
          pcout << "  " << cases.size() << " cases on " << n_ranks
                << " MPI ranks: " << timer.wall_time() << " s" << std::endl;
      }
    return rows;
  }



  template <int dim>
  void
  OrderStudy<dim>::find_blocks()
  {
    MeshParameters mesh     = parameters.mesh;
    mesh.initial_refinement = 0;
    Triangulation<dim> triangulation;
    create_mesh(mesh, triangulation);
    const std::vector<types::material_id> ids = mbfem::block_ids(triangulation);
    // A mesh of several material ids is a model of blocks even where
    // excavation leaves one: only the simulation removes excavated rock.
    whole_model = ids.size() > 1;

    std::set<unsigned int> gone(parameters.excavation.excavated_ids.begin(),
                                parameters.excavation.excavated_ids.end());
    for (const auto &stage : parameters.load_history.stages)
      gone.insert(stage.removed_blocks.begin(), stage.removed_blocks.end());
    block_ids.clear();
    for (const auto id : ids)
      if (gone.count(id) == 0)
        block_ids.push_back(id);

    // Node-to-node pairs join facing nodes one to one: blocks of different
    // degrees need mortar interfaces.
    const ContactParameters &contact = parameters.contact;
    if (whole_model && parameters.order_study.block_degrees != "same" &&
        parameters.order_study.degrees.size() > 1)
      {
        AssertThrow(!contact.all_shared_faces,
                    ExcMessage(
                      "Order study/Block degrees = all combinations gives "
                      "neighbouring blocks different degrees, which the "
                      "node-to-node pairs of 'Contact/Interfaces = all' "
                      "cannot join (their nodes must face each other one to "
                      "one). Declare the interfaces with 'mortar' ('blocks "
                      "1:2 mortar'), or use 'Block degrees = same'."));
        for (const auto &interface : contact.interfaces)
          AssertThrow(interface.mortar,
                      ExcMessage(
                        "Order study/Block degrees = all combinations gives "
                        "neighbouring blocks different degrees, which the "
                        "node-to-node interface '" +
                        interface.description +
                        "' cannot join (its nodes must face each other one "
                        "to one). Declare it '" +
                        interface.description +
                        " mortar', or use 'Block degrees = same'."));
      }
  }



  template <int dim>
  void
  OrderStudy<dim>::run()
  {
    find_blocks();
    degree_cases(); // refuses too many combinations before any output
    same_degrees = parameters.order_study.block_degrees == "same";

    pcout << "mbfem: element-order study, " << dim << "D"
          << (dim == 2 ? " plane strain" : "");
    if (whole_model)
      pcout << ", " << block_ids.size()
            << (block_ids.size() == 1 ? " block (" : " blocks (")
            << (parameters.order_study.block_degrees == "same" ?
                  "the same degree in each" :
                  "all combinations of degrees")
            << ")";
    pcout << ", degrees";
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

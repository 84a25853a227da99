#include <mbfem/analysis/parameters.h>
#include <mbfem/base/exceptions.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace mbfem
{
  void
  RunParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension: 2 (plane strain) or 3.");
    prm.declare_entry(
      "Mode",
      "simulation",
      Patterns::Selection(
        "simulation|order study|strength reduction|reliability"),
      "'simulation': run the load history once. 'order study': solve the "
      "problem for every degree and refinement level in subsection 'Order "
      "study' and tabulate the errors against subsection 'Exact solution'. "
      "'strength reduction': the factor of safety F, the largest divisor of "
      "the joints' tan(phi) and cohesion at which the load history still "
      "converges (subsection 'Strength reduction'); the results written are "
      "those at F. 'reliability': samples of random joint strengths "
      "(subsection 'Reliability'), each sample's factor of safety or its "
      "verdict at F = 1, and P(F < 1).");
    prm.declare_entry(
      "Test mode",
      "false",
      Patterns::Bool(),
      "Leave timings and machine-dependent text out of the screen output, "
      "so that it can be compared with stored output (ctest).");
  }



  void
  RunParameters::parse_parameters(ParameterHandler &prm)
  {
    dimension = prm.get_integer("Dimension");
    mode      = prm.get("Mode");
    test_mode = prm.get_bool("Test mode");
  }



  template <int dim>
  void
  Parameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    RunParameters::declare_parameters(prm);
    MeshParameters::declare_parameters(prm);
    DiscretisationParameters::declare_parameters(prm);
    Material::declare_parameters(prm);
    DirectSolver::Parameters::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm);
    LoadHistory::declare_parameters(prm);
    ExactSolution<dim>::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    OrderStudyParameters::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    ContactSolverParameters::declare_parameters(prm);
    InSituStress::declare_parameters(prm);
    Excavation::declare_parameters(prm);
    PlasticityParameters::declare_parameters(prm);
    StrengthReductionParameters::declare_parameters(prm);
    ReliabilityParameters::declare_parameters(prm);
    WaterPressureParameters<dim>::declare_parameters(prm);
  }



  namespace
  {
    /**
     * The modes that change the joints' strength (strength reduction,
     * reliability) need interfaces and the condensed formulation, and no
     * plasticity; entries of a mode not run are refused, not ignored.
     */
    template <int dim>
    void
    check_strength_modes(const Parameters<dim> &parameters)
    {
      const bool reduces = parameters.run.mode == "strength reduction" ||
                           parameters.run.mode == "reliability";
      const bool reliability = (parameters.run.mode == "reliability");
      AssertThrow(!reduces || parameters.contact.declares_interfaces(),
                  ExcMessage(
                    "Mode = " + parameters.run.mode +
                    (reliability ? " changes" : " divides") +
                    " the joints' strength, but the model declares no contact "
                    "interface (Contact/Interfaces)."));
      AssertThrow(
        !reduces || parameters.contact_solver.formulation ==
                      ContactSolverParameters::Formulation::condensed,
        ExcMessage(
          "Mode = " + parameters.run.mode +
          " runs the condensed formulation only: the monolithic one has "
          "neither the load path nor the Newton method, "
          "so near the limit it would decide F, not the "
          "model. Set 'Contact/Formulation = condensed'."));
      AssertThrow(!parameters.output.write_contact_problems ||
                    parameters.contact_solver.formulation !=
                      ContactSolverParameters::Formulation::monolithic,
                  ExcMessage("Output/Write contact problems writes the "
                             "condensed problem, which the monolithic "
                             "formulation does not form. Set "
                             "'Contact/Formulation = condensed' or 'both'."));
      // Entries read only by strength reduction would be ignored silently.
      AssertThrow(parameters.run.mode == "strength reduction" ||
                    parameters.strength_reduction.closed_form_text.empty(),
                  ExcMessage("'Strength reduction/Closed-form factor of "
                             "safety' is given, but Mode = " +
                             parameters.run.mode +
                             " runs no strength reduction: set Mode = "
                             "strength reduction, or remove the entry."));
      AssertThrow(
        !reduces || !parameters.plasticity.enabled,
        ExcMessage(
          "Mode = " + parameters.run.mode +
          (reliability ? " changes" : " reduces") +
          " the joints' strength only; with 'Plasticity/Enabled = true' "
          "the rock's strength would stay as it is, and "
          "the plastic strain would have to be reset per "
          "trial. Not supported yet: run the plastic model "
          "at chosen strengths with Mode = simulation."));
      AssertThrow(parameters.run.mode == "reliability" ||
                    parameters.reliability.variables.empty(),
                  ExcMessage("'Reliability/Random variables' is given, but "
                             "Mode = " +
                             parameters.run.mode +
                             ": set Mode = reliability, or remove the "
                             "entry."));
    }
  } // namespace



  template <int dim>
  void
  Parameters<dim>::parse_parameters(ParameterHandler  &prm,
                                    const std::string &input_folder)
  {
    run.parse_parameters(prm);
    mesh.parse_parameters(prm, input_folder);
    discretisation.parse_parameters(prm);
    material.parse_parameters(prm);
    block_materials = Material::parse_block_materials(prm);
    linear_solver.parse_parameters(prm);
    boundary_conditions.parse_parameters(prm);
    load_history.parse_parameters(prm);
    exact_solution.parse_parameters(prm);
    output.parse_parameters(prm);
    order_study.parse_parameters(prm);
    contact.parse_parameters(prm);
    contact_solver.parse_parameters(prm);
    in_situ_stress.parse_parameters(prm);
    excavation.parse_parameters(prm);
    plasticity.parse_parameters(prm);
    strength_reduction.parse_parameters(prm);
    reliability.parse_parameters(prm);
    water_pressure.parse_parameters(prm);
    AssertThrow(!water_pressure.enabled() || contact.declares_interfaces(),
                ExcMessage("Water pressure/Interfaces names wet joints, but "
                           "the model declares no contact interface "
                           "(Contact/Interfaces)."));
    check_strength_modes(*this);
    const bool excavates = !excavation.excavated_ids.empty() ||
                           !excavation.released_boundaries.empty();
    AssertThrow(!excavates || in_situ_stress.enabled,
                ExcMessage("Excavation: an excavation releases the in-situ "
                           "stress, so it needs 'In-situ stress/Enabled = "
                           "true'."));

    AssertThrow(run.mode != "order study" || exact_solution.enabled,
                ExcMessage("Mode = order study measures errors: set 'Exact "
                           "solution/Compute errors = true' and give the "
                           "exact displacement and stress."));
  }



  namespace
  {
    void
    check_readable(const std::string &filename)
    {
      AssertThrow(std::filesystem::is_regular_file(filename) &&
                    std::ifstream(filename).good(),
                  ExcMessage("Cannot read the parameter file <" + filename +
                             ">."));
    }

    /** Deeper includes are taken to be a cycle that escaped detection. */
    constexpr unsigned int max_include_depth = 16;

    /**
     * Deeper JSON is refused: deal.II's reader recurses once per level and
     * overflows the stack on a few thousand (parameter files have five).
     */
    constexpr unsigned int max_json_depth = 32;

    /** Where a line of the expanded text came from. */
    struct Origin
    {
      std::string  file;
      unsigned int line;
    };

    /** The text of a line before its comment ('#', not '\#'). */
    std::string
    without_comment(const std::string &line)
    {
      for (std::size_t i = 0; i < line.size(); ++i)
        if (line[i] == '#' && (i == 0 || line[i - 1] != '\\'))
          return Utilities::trim(line.substr(0, i));
      return Utilities::trim(line);
    }

    /**
     * @p path as written in @p file: a relative path is taken from the
     * folder of @p file, wherever the run is started.
     */
    std::filesystem::path
    resolve(const std::string &path, const std::filesystem::path &file)
    {
      const std::filesystem::path written(path);
      if (written.is_absolute())
        return written;
      return (std::filesystem::absolute(file).parent_path() / written)
        .lexically_normal();
    }

    /**
     * Appends @p file to @p out with its includes expanded in place (deal.II
     * would open them from the working folder) and, in included files, a
     * relative 'Mesh file' made absolute, so that each relative path is
     * taken from the folder of the file that writes it.
     */
    void
    expand_includes(const std::filesystem::path        &file,
                    std::vector<std::filesystem::path> &open,
                    std::ostringstream                 &out,
                    std::vector<Origin>                &origins)
    {
      std::ifstream in(file);
      std::string   line;
      for (unsigned int n = 1; std::getline(in, line); ++n)
        {
          const std::string text = without_comment(line);
          const std::string where =
            file.string() + ", line " + std::to_string(n) + ": ";
          if (text.rfind("include ", 0) == 0 || text.rfind("INCLUDE ", 0) == 0)
            {
              const auto target =
                resolve(Utilities::trim(text.substr(8)), file);
              AssertThrow(std::filesystem::is_regular_file(target) &&
                            std::ifstream(target).good(),
                          ExcMessage(where + "cannot read the included file <" +
                                     target.filename().string() +
                                     "> in the folder <" +
                                     target.parent_path().string() +
                                     "> (a relative path is taken from the "
                                     "folder of the file that includes it)."));
              const auto canonical = std::filesystem::canonical(target);
              AssertThrow(std::find(open.begin(), open.end(), canonical) ==
                            open.end(),
                          ExcMessage(where + "<" + target.string() +
                                     "> includes itself, directly or "
                                     "through other files."));
              AssertThrow(open.size() < max_include_depth,
                          ExcMessage(where + "includes are nested more than " +
                                     std::to_string(max_include_depth) +
                                     " deep."));
              open.push_back(canonical);
              expand_includes(target, open, out, origins);
              open.pop_back();
              continue;
            }
          const auto equals = text.find('=');
          if (open.size() > 1 && text.rfind("set ", 0) == 0 &&
              equals != std::string::npos &&
              Utilities::trim(text.substr(4, equals - 4)) == "Mesh file")
            {
              const std::string path = Utilities::trim(text.substr(equals + 1));
              if (!path.empty())
                line = "set Mesh file = " + resolve(path, file).string();
            }
          out << line << '\n';
          origins.push_back({file.string(), n});
        }
    }

    /** deal.II names the line of the expanded text: name the real one. */
    std::string
    with_real_lines(const std::string         &message,
                    const std::vector<Origin> &origins)
    {
      const std::regex line_of_file("Line <([0-9]+)> of file <[^>]*>");
      std::smatch      match;
      if (!std::regex_search(message, match, line_of_file))
        return message;
      const unsigned int line = std::stoul(match[1].str());
      if (line == 0 || line > origins.size())
        return message;
      return match.prefix().str() + "Line <" +
             std::to_string(origins[line - 1].line) + "> of file <" +
             origins[line - 1].file + ">" + match.suffix().str();
    }

    void
    check_json_depth(const std::string &filename)
    {
      std::ifstream in(filename);
      unsigned int  depth = 0, deepest = 0;
      bool          in_string = false, escaped = false;
      for (char c; in.get(c);)
        {
          if (in_string)
            {
              in_string = escaped || c != '"';
              escaped   = !escaped && c == '\\';
            }
          else if (c == '"')
            in_string = true;
          else if (c == '{' || c == '[')
            deepest = std::max(deepest, ++depth);
          else if ((c == '}' || c == ']') && depth > 0)
            --depth;
        }
      AssertThrow(deepest <= max_json_depth,
                  ExcMessage("The JSON file <" + filename + "> is nested " +
                             std::to_string(deepest) +
                             " levels deep; a parameter file needs a few, "
                             "and mbfem reads at most " +
                             std::to_string(max_json_depth) + "."));
    }

    /**
     * Reads @p filename into @p prm: JSON (and XML) as deal.II does, a .prm
     * file with its includes expanded by expand_includes().
     */
    void
    parse_file(ParameterHandler  &prm,
               const std::string &filename,
               const bool         skip_undefined)
    {
      check_readable(filename);
      const std::string extension =
        std::filesystem::path(filename).extension().string();
      if (extension == ".json" || extension == ".xml")
        {
          if (extension == ".json")
            check_json_depth(filename);
          try
            {
              prm.parse_input(filename, "", skip_undefined);
            }
          catch (ExceptionBase &e)
            {
              // deal.II's text names Boost and "<unspecified file>(21)":
              // keep the line and the reason only.
              const std::string text = message_of(e);
              const std::regex  boost(
                "[\\s\\S]*<unspecified file>\\(([0-9]+)\\): "
                 "([^\\n]*)[\\s\\S]*");
              std::smatch match;
              if (!std::regex_match(text, match, boost))
                throw;
              AssertThrow(false,
                          ExcMessage(
                            "The " +
                            (extension == ".json" ? std::string("JSON") :
                                                    std::string("XML")) +
                            " file <" + filename + "> is not valid: line " +
                            match[1].str() + ": " + match[2].str()));
            }
          return;
        }
      std::vector<std::filesystem::path> open = {
        std::filesystem::canonical(filename)};
      std::ostringstream  text;
      std::vector<Origin> origins;
      expand_includes(filename, open, text, origins);
      std::istringstream in(text.str());
      try
        {
          prm.parse_input(in, filename, "", skip_undefined);
        }
      catch (ExceptionBase &e)
        {
          const bool included =
            std::any_of(origins.begin(), origins.end(), [&](const Origin &o) {
              return o.file != filename;
            });
          if (!included)
            throw;
          AssertThrow(false,
                      ExcMessage(with_real_lines(message_of(e), origins)));
        }
    }
  } // namespace



  unsigned int
  read_dimension(const std::string &filename)
  {
    ParameterHandler prm;
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    // Everything else is read (and checked) by read_parameters().
    parse_file(prm, filename, true);
    return prm.get_integer("Dimension");
  }



  template <int dim>
  void
  read_parameters(const std::string &filename, Parameters<dim> &parameters)
  {
    ParameterHandler prm;
    Parameters<dim>::declare_parameters(prm);
    parse_file(prm, filename, false);

    const std::filesystem::path folder =
      std::filesystem::path(filename).parent_path();
    parameters.parse_parameters(prm, folder.empty() ? "." : folder.string());
  }



  template struct Parameters<2>;
  template struct Parameters<3>;
  template void
  read_parameters(const std::string &, Parameters<2> &);
  template void
  read_parameters(const std::string &, Parameters<3> &);
} // namespace mbfem

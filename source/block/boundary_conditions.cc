#include <mbfem/base/exceptions.h>
#include <mbfem/base/text_input.h>
#include <mbfem/block/boundary_conditions.h>

#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace mbfem
{
  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    {
      prm.declare_entry(
        "Prescribed displacement boundary ids",
        "",
        Patterns::Map(Patterns::Integer(0, 255),
                      Patterns::Anything(),
                      0,
                      Patterns::Map::max_int_value,
                      ",",
                      ":"),
        "Boundary ids with prescribed displacement and the components "
        "prescribed there, e.g. '0: xy, 2: y' clamps boundary 0 and puts "
        "boundary 2 on rollers that move freely in x. Components are letters "
        "from 'xyz'. The values come from the function in subsection "
        "'Prescribed displacement'.");
      prm.enter_subsection("Prescribed displacement");
      Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
      prm.leave_subsection();

      prm.declare_entry(
        "Point supports",
        "",
        Patterns::Anything(),
        "Supports at single nodes, as 'x,y(,z): components' separated by "
        "';', e.g. '0,-16: x' holds the node at (0,-16) in x. The node must "
        "be a support point of the mesh (within 1e-6 of the block size). "
        "The displacement is zero there.");
      prm.declare_entry(
        "Rigid platen boundary ids",
        "",
        Patterns::Map(Patterns::Integer(0),
                      Patterns::Selection("x|y|z"),
                      0,
                      Patterns::Map::max_int_value,
                      ",",
                      ":"),
        "Faces that carry a rigid loading platen, as 'id: component', e.g. "
        "'5: y': every node of boundary 5 has the same y displacement, so "
        "the face translates but cannot rotate, as under a stiff loading "
        "plate; the platen carries the moment of the loads applied to that "
        "face (tractions on it are summed onto the platen).");

      prm.declare_entry(
        "Traction boundary ids",
        "",
        Patterns::List(Patterns::Integer(0, 255)),
        "Boundary ids loaded by the traction in subsection 'Traction' "
        "(force per unit area in global x, y(, z); a pressure p on a face "
        "with outward normal n is the traction -p n).");
      prm.enter_subsection("Traction");
      Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
      prm.leave_subsection();

      prm.enter_subsection("Body force");
      Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
      prm.leave_subsection();

      prm.declare_entry(
        "Gravity ramp time",
        "0",
        Patterns::Double(0.),
        "How the weight of 'Material/Unit weight' follows the load history. "
        "0: in full at every increment, from the first. T > 0: scaled by "
        "min(t / T, 1), like any load of the history, so that it grows over "
        "the increments up to t = T (and smaller steps after a halving "
        "carry a smaller part of it); e.g. T = 'Load history/End time' "
        "ramps it over the whole run, T = 0.5 over the first half, before "
        "other loads ramp. Must be 0 with an in-situ stress, which is in "
        "equilibrium with the full weight.");
    }
    prm.leave_subsection();
  }



  namespace
  {
    /**
     * 'Boundary conditions/Point supports' (@p text: 'x,y: components;
     * ...') into @p point_supports, each point once.
     */
    template <int dim, typename Supports>
    void
    parse_point_supports(const std::string &text, Supports &point_supports)
    {
      const std::string where = "Boundary conditions/Point supports";
      for (const auto &entry : split_list(text, ';', where))
        {
          const std::vector<std::string> parts =
            Utilities::split_string_list(entry, ':');
          AssertThrow(parts.size() == 2,
                      ExcMessage("'" + where + "': cannot read '" + entry +
                                 "'; write 'x,y: components'."));
          std::vector<double> x;
          for (const auto &coordinate : split_list(parts[0], ',', where))
            x.push_back(parse_finite_number(coordinate, where));
          AssertThrow(x.size() == dim,
                      ExcMessage("'" + where + "': '" + parts[0] +
                                 "' is not a point in " + std::to_string(dim) +
                                 "D."));
          Point<dim> point;
          for (unsigned int d = 0; d < dim; ++d)
            point[d] = x[d];
          const auto masks = parse_component_map<dim>("0: " + parts[1], where);
          for (const auto &[other, other_mask] : point_supports)
            AssertThrow(other.distance(point) > 0.,
                        ExcMessage("'" + where + "': the point " + parts[0] +
                                   " is supported twice; give each point "
                                   "once, with all its components."));
          point_supports.emplace_back(point, masks.begin()->second);
        }
    }
  } // namespace



  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    {
      dirichlet = parse_component_map<dim>(
        prm.get("Prescribed displacement boundary ids"),
        "Boundary conditions/Prescribed displacement boundary ids");

      rigid_platens.clear();
      for (const auto &[id, mask] : parse_component_map<dim>(
             prm.get("Rigid platen boundary ids"),
             "Boundary conditions/Rigid platen boundary ids"))
        for (unsigned int c = 0; c < dim; ++c)
          if (mask[c])
            rigid_platens[id] = c;

      point_supports.clear();
      parse_point_supports<dim>(prm.get("Point supports"), point_supports);

      traction_boundaries.clear();
      for (const unsigned int id :
           parse_id_list(prm.get("Traction boundary ids"),
                         "Boundary conditions/Traction boundary ids"))
        traction_boundaries.insert(static_cast<types::boundary_id>(id));

      prm.enter_subsection("Prescribed displacement");
      prescribed_displacement =
        parse_function<dim>(prm,
                            dim,
                            "Boundary conditions/Prescribed displacement");
      prm.leave_subsection();

      prm.enter_subsection("Traction");
      traction = parse_function<dim>(prm, dim, "Boundary conditions/Traction");
      prm.leave_subsection();

      prm.enter_subsection("Body force");
      body_force =
        parse_function<dim>(prm, dim, "Boundary conditions/Body force");
      body_force_is_zero = true;
      for (const std::string &expression :
           Utilities::split_string_list(prm.get("Function expression"), ';'))
        {
          char        *end   = nullptr;
          const double value = std::strtod(expression.c_str(), &end);
          body_force_is_zero = body_force_is_zero &&
                               end != expression.c_str() && *end == '\0' &&
                               value == 0.;
        }
      prm.leave_subsection();

      gravity_ramp_time = prm.get_double("Gravity ramp time");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  BoundaryConditions<dim>::check_boundary_ids(
    const std::set<types::boundary_id> &present) const
  {
    const auto check = [&](const types::boundary_id id,
                           const std::string       &entry) {
      check_boundary_id(id, "Boundary conditions/" + entry, present);
    };
    for (const auto &[id, mask] : dirichlet)
      check(id, "Prescribed displacement boundary ids");
    for (const auto id : traction_boundaries)
      check(id, "Traction boundary ids");
    for (const auto &[id, component] : rigid_platens)
      check(id, "Rigid platen boundary ids");
  }



  template <int dim>
  void
  BoundaryConditions<dim>::set_time(const double time)
  {
    prescribed_displacement->set_time(time);
    traction->set_time(time);
    body_force->set_time(time);
    gravity_factor =
      (gravity_ramp_time > 0. ? std::min(time / gravity_ramp_time, 1.) : 1.);
  }



  std::vector<ParsedFunctionEntry> &
  parsed_functions()
  {
    static std::vector<ParsedFunctionEntry> functions;
    return functions;
  }



  namespace
  {
    /** 'a=1, b=2' (ParsedFunction's 'Function constants') as a map. */
    std::map<std::string, double>
    constants_of(const std::string &text)
    {
      std::map<std::string, double> constants;
      for (const auto &entry : Utilities::split_string_list(text, ','))
        {
          const auto equals = entry.find('=');
          if (equals != std::string::npos)
            constants[Utilities::trim(entry.substr(0, equals))] =
              Utilities::string_to_double(entry.substr(equals + 1));
        }
      return constants;
    }

    /**
     * Records @p function, read from @p prm's present subsection, in
     * parsed_functions(), with the way to read it again with other
     * constants.
     */
    template <int dim>
    void
    record_function(
      ParameterHandler                                      &prm,
      const std::shared_ptr<Functions::ParsedFunction<dim>> &function,
      const unsigned int                                     n_components,
      const std::string                                     &where)
    {
      const std::string expression = prm.get("Function expression");
      const std::string variables  = prm.get("Variable names");
      const auto        set_constants =
        [=](const std::map<std::string, double> &constants) {
          ParameterHandler local;
          Functions::ParsedFunction<dim>::declare_parameters(local,
                                                             n_components);
          std::ostringstream text;
          text << std::setprecision(17);
          for (const auto &[name, value] : constants)
            text << (text.tellp() > 0 ? ", " : "") << name << "=" << value;
          local.set("Function expression", expression);
          local.set("Variable names", variables);
          local.set("Function constants", text.str());
          const QuietCerr quiet;
          function->parse_parameters(local);
        };
      parsed_functions().push_back(
        {where, constants_of(prm.get("Function constants")), set_constants});
    }
  } // namespace



  template <int dim>
  std::shared_ptr<Functions::ParsedFunction<dim>>
  parse_function(ParameterHandler  &prm,
                 const unsigned int n_components,
                 const std::string &where)
  {
    auto function =
      std::make_shared<Functions::ParsedFunction<dim>>(n_components);
    check_variable_names(prm.get("Variable names"), dim, where);
    check_function_constants(prm.get("Function constants"),
                             prm.get("Variable names"),
                             where);
    try
      {
        const QuietCerr quiet;
        function->parse_parameters(prm);
        // muparser compiles an expression when it is first evaluated; do
        // that now, so that a typo is reported here and not in the middle
        // of a run (or never, for a function that is not used).
        Vector<double> value(n_components);
        function->vector_value(Point<dim>(), value);
      }
    catch (ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        AssertThrow(false,
                    ExcMessage(
                      "The function in subsection '" + where +
                      "' cannot be parsed (it needs " +
                      std::to_string(n_components) +
                      " expressions separated by ';', in the variables of "
                      "'Variable names' and the names of 'Function "
                      "constants'): " +
                      Utilities::trim(message.str())));
      }
    catch (...)
      {
        // muparser's own exceptions are no std::exception.
        AssertThrow(false,
                    ExcMessage("The function in subsection '" + where +
                               "' cannot be parsed (it needs " +
                               std::to_string(n_components) +
                               " expressions separated by ';', in the "
                               "variables of 'Variable names' and the "
                               "names of 'Function constants')."));
      }
    record_function<dim>(prm, function, n_components, where);
    return function;
  }



  template <int dim>
  std::map<types::boundary_id, ComponentMask>
  parse_component_map(const std::string &text, const std::string &where)
  {
    static const std::string letters = "xyz";

    std::map<types::boundary_id, ComponentMask> result;
    for (const auto &entry : split_list(text, ',', where))
      {
        const std::vector<std::string> parts =
          Utilities::split_string_list(entry, ':');
        AssertThrow(parts.size() == 2,
                    ExcMessage("'" + where + "': cannot read '" + entry +
                               "'; write 'id: components', e.g. '0: xy'."));
        const types::boundary_id id =
          static_cast<types::boundary_id>(Utilities::string_to_int(parts[0]));
        std::vector<bool> selected(dim, false);
        AssertThrow(!parts[1].empty(),
                    ExcMessage("'" + where + "': no components for id " +
                               parts[0] + "."));
        for (const char c : parts[1])
          {
            const std::size_t component = letters.find(c);
            AssertThrow(component != std::string::npos && component < dim,
                        ExcMessage("'" + where + "': '" + std::string(1, c) +
                                   "' is not a component of a " +
                                   std::to_string(dim) +
                                   "D displacement (use letters from '" +
                                   letters.substr(0, dim) + "')."));
            selected[component] = true;
          }
        AssertThrow(result.count(id) == 0,
                    ExcMessage("'" + where + "': boundary id " + parts[0] +
                               " appears twice."));
        result.emplace(id, ComponentMask(selected));
      }
    return result;
  }



  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
  template std::shared_ptr<Functions::ParsedFunction<2>>
  parse_function<2>(ParameterHandler &,
                    const unsigned int,
                    const std::string &);
  template std::shared_ptr<Functions::ParsedFunction<3>>
  parse_function<3>(ParameterHandler &,
                    const unsigned int,
                    const std::string &);
  template std::map<types::boundary_id, ComponentMask>
  parse_component_map<2>(const std::string &, const std::string &);
  template std::map<types::boundary_id, ComponentMask>
  parse_component_map<3>(const std::string &, const std::string &);
} // namespace mbfem

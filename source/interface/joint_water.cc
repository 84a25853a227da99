#include <mbfem/base/exceptions.h>
#include <mbfem/base/text_input.h>
#include <mbfem/block/boundary_conditions.h>
#include <mbfem/interface/joint_water.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mbfem
{
  template <int dim>
  void
  WaterPressureParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Water pressure");
    {
      prm.declare_entry(
        "Interfaces",
        "",
        Patterns::Anything(),
        "The joints with water in them, separated by ';': 'all', entries as "
        "in Contact/Interfaces ('blocks 1:2', 'boundaries 3:4') or names of "
        "joint sets. The pressure p_w pushes both faces of the joint apart; "
        "the joints' strength then acts on the effective normal force.");
      prm.declare_entry(
        "Water level",
        "",
        Patterns::Anything(),
        "Hydrostatic pressure: p_w = (Unit weight of water) * max(level - "
        "y, 0) (z in 3D), the level a function of t (for example '30' or "
        "'30 * t'). Empty: p_w is 'Function expression' instead.");
      prm.declare_entry("Unit weight of water",
                        "9810",
                        Patterns::Double(0.),
                        "gamma_w of the hydrostatic pressure (N/m^3).");
      Functions::ParsedFunction<dim>::declare_parameters(prm, 1);
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  WaterPressureParameters<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Water pressure");
    {
      const std::string list = Utilities::trim(prm.get("Interfaces"));
      interfaces.clear();
      if (!list.empty())
        interfaces = split_list(list, ';', "Water pressure/Interfaces");
      const std::string level_text = Utilities::trim(prm.get("Water level"));
      const bool        has_function =
        Utilities::trim(prm.get("Function expression")) != "0";
      unit_weight = prm.get_double("Unit weight of water");
      AssertThrow(!(has_function && !level_text.empty()),
                  ExcMessage("Water pressure: give either 'Water level' "
                             "(hydrostatic) or 'Function expression', not "
                             "both."));
      AssertThrow(interfaces.empty() || has_function || !level_text.empty(),
                  ExcMessage("Water pressure/Interfaces names wet joints, "
                             "but neither 'Function expression' nor 'Water "
                             "level' gives their pressure."));
      AssertThrow(!interfaces.empty() || (!has_function && level_text.empty()),
                  ExcMessage("Water pressure: a pressure is given but "
                             "'Interfaces' names no joint for it."));
      function = parse_function<dim>(prm, 1, "Water pressure");
      level.reset();
      if (!level_text.empty())
        {
          level = std::make_shared<FunctionParser<1>>();
          try
            {
              const QuietCerr quiet;
              level->initialize("t",
                                level_text,
                                {{"pi", numbers::PI}, {"Pi", numbers::PI}},
                                false);
              level->value(Point<1>(0.));
            }
          catch (...)
            {
              AssertThrow(false,
                          ExcMessage("Water pressure/Water level: cannot "
                                     "read '" +
                                     level_text +
                                     "' as a function of t alone."));
            }
        }
    }
    prm.leave_subsection();
  }



  template <int dim>
  double
  WaterPressureParameters<dim>::pressure(const Point<dim> &point,
                                         const double      time) const
  {
    if (level)
      return unit_weight *
             std::max(level->value(Point<1>(time)) - point[dim - 1], 0.);
    function->set_time(time);
    return function->value(point);
  }



  namespace
  {
    /** Whether entry @p entry of Water pressure/Interfaces names @p joint. */
    bool
    names_interface(const std::string &entry, const InterfaceDeclaration &joint)
    {
      if (entry == "all" || entry == joint.joint_set)
        return true;
      std::istringstream in(entry);
      std::string        kind, sides;
      in >> kind >> sides;
      const auto ids = Utilities::split_string_list(sides, ':');
      if (ids.size() != 2 || (kind == "blocks") != joint.by_blocks ||
          (kind != "blocks" && kind != "boundaries"))
        return false;
      const auto a = Utilities::string_to_int(ids[0]);
      const auto b = Utilities::string_to_int(ids[1]);
      return (a == int(joint.side_a) && b == int(joint.side_b)) ||
             (a == int(joint.side_b) && b == int(joint.side_a));
    }
  } // namespace



  template <int dim>
  JointWater<dim>::JointWater(const WaterPressureParameters<dim>  &parameters,
                              const ContactParameters             &contact,
                              const std::vector<ContactPair<dim>> &pairs,
                              const unsigned int                   n_blocks)
    : parameters(parameters)
    , pairs(pairs)
    , sides_on_block(n_blocks)
  {
    std::vector<bool> wet_interface(contact.interfaces.size(), false);
    for (const auto &entry : parameters.interfaces)
      {
        bool        found = false;
        std::string known;
        for (unsigned int i = 0; i < contact.interfaces.size(); ++i)
          {
            if (names_interface(entry, contact.interfaces[i]))
              wet_interface[i] = found = true;
            known += (known.empty() ? "'" : ", '") +
                     contact.interfaces[i].description + "'";
          }
        AssertThrow(found,
                    ExcMessage("Water pressure/Interfaces: '" + entry +
                               "' names no contact interface of the model "
                               "(they are " +
                               known + ", and joint sets by name)."));
      }
    wet.assign(pairs.size(), false);
    for (unsigned int k = 0; k < pairs.size(); ++k)
      if (wet_interface[pairs[k].interface])
        {
          wet[k] = true;
          sides_on_block[pairs[k].a.block].emplace_back(k, -1);
          sides_on_block[pairs[k].b.block].emplace_back(k, 1);
        }
  }



  template <int dim>
  double
  JointWater<dim>::pressure(const unsigned int k, const double time) const
  {
    return wet[k] ? parameters.pressure(pairs[k].midpoint(), time) : 0.;
  }



  template <int dim>
  void
  JointWater<dim>::add_load(const unsigned int b,
                            Block<dim>        &block,
                            const double       time) const
  {
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  forces;
    for (const auto &[k, sign] : sides_on_block[b])
      {
        const auto &pair = pairs[k];
        // The normal points from a to b: water pushes b along it, a back.
        const Tensor<1, dim> force =
          sign * pressure(k, time) * pair.area * pair.frame[0];
        for (const auto &node : pair.side(sign).nodes)
          for (unsigned int c = 0; c < dim; ++c)
            {
              dofs.push_back(node.dofs[c]);
              forces.push_back(node.weight * force[c]);
            }
      }
    if (!dofs.empty())
      block.add_external_point_forces(dofs, forces);
  }



  template <int dim>
  double
  JointWater<dim>::resultant(const double time) const
  {
    double sum = 0.;
    for (unsigned int k = 0; k < pairs.size(); ++k)
      sum += pressure(k, time) * pairs[k].area;
    return sum;
  }



  template <int dim>
  unsigned int
  JointWater<dim>::n_wet_pairs() const
  {
    return std::count(wet.begin(), wet.end(), true);
  }



  template struct WaterPressureParameters<2>;
  template struct WaterPressureParameters<3>;
  template class JointWater<2>;
  template class JointWater<3>;
} // namespace mbfem

#include <mbfem/base/text_input.h>
#include <mbfem/interface/joint_sets.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <sstream>

namespace mbfem
{
  template <int dim>
  Tensor<1, dim>
  JointSet::normal() const
  {
    const double   to_radians = numbers::PI / 180.;
    const double   d = dip * to_radians, a = dip_direction * to_radians;
    Tensor<1, dim> n;
    n[0]       = std::sin(d) * std::sin(a);
    n[dim - 1] = std::cos(d);
    if (dim == 3)
      n[1] = std::sin(d) * std::cos(a);
    return n / n.norm();
  }



  template <int dim>
  bool
  JointSet::contains(const Tensor<1, dim> &n) const
  {
    const double cosine = std::abs(n * normal<dim>()) / n.norm();
    return cosine >=
           std::cos(tolerance * numbers::PI / 180.) - 1e-12; // round-off
  }



  namespace
  {
    /** Reads one 'key value' item of a joint set into @p set. */
    void
    read_item(const std::string &item, const std::string &text, JointSet &set)
    {
      if (item.rfind("group ", 0) == 0)
        {
          set.group = Utilities::trim(item.substr(6));
          return;
        }
      if (item.rfind("point ", 0) == 0)
        {
          std::istringstream in(item.substr(6));
          double             x = 0.;
          set.point.clear();
          while (in >> x)
            set.point.push_back(x);
          AssertThrow(in.eof() &&
                        (set.point.size() == 2 || set.point.size() == 3),
                      ExcMessage("Contact/Joint sets: '" + item + "' in '" +
                                 text +
                                 "': a point is 2 or 3 numbers separated by "
                                 "spaces."));
          return;
        }
      const auto space = item.find_last_of(' ');
      const auto key =
        (space == std::string::npos ? item :
                                      Utilities::trim(item.substr(0, space)));
      double     value = 0.;
      const bool known = (space != std::string::npos);
      if (known)
        {
          std::istringstream in(item.substr(space + 1));
          AssertThrow(in >> value && in.eof(),
                      ExcMessage("Contact/Joint sets: cannot read the number "
                                 "in '" +
                                 item + "' of '" + text + "'."));
        }
      const auto check = [&](const bool ok, const std::string &why) {
        AssertThrow(known && ok,
                    ExcMessage("Contact/Joint sets: '" + item + "' in '" +
                               text + "': " + why));
      };
      if (key == "dip")
        check((set.dip = value) >= 0. && value <= 90., "dip is 0 to 90.");
      else if (key == "dip direction")
        check((set.dip_direction = value) >= 0. && value <= 360.,
              "dip direction is 0 to 360.");
      else if (key == "tolerance")
        check((set.tolerance = value) >= 0. && value < 90.,
              "tolerance is 0 to 90 degrees.");
      else if (key == "friction")
        check((set.joint.friction_coefficient = value) >= 0.,
              "friction coefficient >= 0.");
      else if (key == "cohesion")
        check((set.joint.cohesion = value) >= 0., "cohesion >= 0.");
      else if (key == "tensile strength")
        check((set.joint.tensile_strength = value) >= 0.,
              "tensile strength >= 0.");
      else if (key == "spacing")
        check((set.spacing = value) > 0., "spacing > 0.");
      else
        check(false,
              "the keys are dip, dip direction, tolerance, friction, "
              "cohesion, tensile strength, spacing, point, group.");
    }
  } // namespace



  std::vector<JointSet>
  parse_joint_sets(const std::string &text, const JointLaw &defaults)
  {
    std::vector<JointSet> sets;
    for (const auto &entry : split_list(text, ';', "Contact/Joint sets"))
      {
        const auto colon = entry.find(':');
        AssertThrow(colon != std::string::npos && colon > 0,
                    ExcMessage("Contact/Joint sets: cannot read '" + entry +
                               "'; write 'name: dip 30, dip direction 90, "
                               "friction 0.6' (sets separated by ';')."));
        JointSet set;
        set.name  = Utilities::trim(entry.substr(0, colon));
        set.joint = defaults;
        for (const auto &item :
             split_list(entry.substr(colon + 1), ',', "Contact/Joint sets"))
          read_item(item, entry, set);
        sets.push_back(set);
      }
    return sets;
  }



  template Tensor<1, 2>
  JointSet::normal<2>() const;
  template Tensor<1, 3>
  JointSet::normal<3>() const;
  template bool
  JointSet::contains<2>(const Tensor<1, 2> &) const;
  template bool
  JointSet::contains<3>(const Tensor<1, 3> &) const;
} // namespace mbfem

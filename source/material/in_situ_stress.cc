#include <mbfem/base/text_input.h>
#include <mbfem/material/in_situ_stress.h>
#include <mbfem/mesh/mesh.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>

namespace mbfem
{
  void
  InSituStress::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("In-situ stress");
    {
      prm.declare_entry(
        "Enabled",
        "false",
        Patterns::Bool(),
        "Start from a geostatic stress (tension positive): sigma_v = -(q + "
        "gamma (z_s - z)), sigma_h = K0 sigma_v, z = y in 2D and z in 3D. "
        "It is an initial stress in every block (in equilibrium with gravity "
        "of the same unit weight, so it causes no displacement), and the "
        "interfaces start in the compression it puts on them. The stress in "
        "the output is sigma_0 plus that of the displacement. An extra "
        "solve at t = 0 (increment 0) shows the geostatic stage.");
      prm.declare_entry("Surface elevation",
                        "0",
                        Patterns::Double(),
                        "z_s: the vertical coordinate of the ground surface "
                        "(or of the top of the overburden q).");
      prm.declare_entry("Surcharge",
                        "0",
                        Patterns::Double(0.),
                        "q: vertical stress (compression, > 0) at z_s, e.g. "
                        "the weight of the rock above a model that does not "
                        "reach the surface.");
      prm.declare_entry("Unit weight",
                        "0",
                        Patterns::Double(0.),
                        "gamma: weight per volume of the overburden. It must "
                        "equal every block's Material unit weight, or the "
                        "stress is not in equilibrium with gravity.");
      prm.declare_entry("Lateral pressure coefficient",
                        "1",
                        Patterns::Double(0.),
                        "K0 = sigma_h / sigma_v.");
      prm.declare_entry(
        "Stress boundary ids",
        "",
        Patterns::List(Patterns::Integer(0)),
        "Comma-separated boundary ids of the far field that the in-situ "
        "stress holds: they carry the traction sigma_0 n throughout. "
        "Boundaries with prescribed displacements need not be listed (the "
        "supports carry sigma_0 n).");
    }
    prm.leave_subsection();
  }



  void
  InSituStress::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("In-situ stress");
    {
      enabled             = prm.get_bool("Enabled");
      surface_elevation   = prm.get_double("Surface elevation");
      surcharge           = prm.get_double("Surcharge");
      unit_weight         = prm.get_double("Unit weight");
      lateral_coefficient = prm.get_double("Lateral pressure coefficient");
      stress_boundaries.clear();
      for (const auto id : parse_id_list(prm.get("Stress boundary ids"),
                                         "In-situ stress/Stress boundary ids"))
        stress_boundaries.insert(id);
    }
    prm.leave_subsection();
  }



  template <int dim>
  SymmetricTensor<2, 3>
  InSituStress::stress_3d(const Point<dim> &point) const
  {
    SymmetricTensor<2, 3> sigma;
    if (!enabled)
      return sigma;
    const double vertical =
      -(surcharge + unit_weight * (surface_elevation - point[dim - 1]));
    for (unsigned int d = 0; d < 3; ++d)
      sigma[d][d] = lateral_coefficient * vertical;
    sigma[dim - 1][dim - 1] = vertical;
    return sigma;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  InSituStress::stress(const Point<dim> &point) const
  {
    const SymmetricTensor<2, 3> s = stress_3d(point);
    SymmetricTensor<2, dim>     sigma;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        sigma[i][j] = s[i][j];
    return sigma;
  }



  void
  Excavation::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Excavation");
    {
      prm.declare_entry(
        "Excavated material ids",
        "",
        Patterns::List(Patterns::Integer(0)),
        "Comma-separated material ids of the cells excavated (the cavern). "
        "They are not blocks; the faces where they met the rock are released "
        "(see below). Needs 'In-situ stress/Enabled'.");
      prm.declare_entry(
        "Released boundary ids",
        "",
        Patterns::List(Patterns::Integer(0)),
        "Further boundary ids released in the same way, for a mesh that "
        "leaves the excavated region out. A released face carries (1 - "
        "lambda) sigma_0 n, lambda = t clipped to [0, 1]: the support of the "
        "excavated rock, removed over the load increments.");
    }
    prm.leave_subsection();
  }



  void
  Excavation::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Excavation");
    {
      excavated_ids.clear();
      released_boundaries.clear();
      for (const auto id : parse_id_list(prm.get("Excavated material ids"),
                                         "Excavation/Excavated material ids"))
        {
          excavated_ids.push_back(id);
          released_boundaries.insert(interface_boundary_id(id));
        }
      for (const auto id : parse_id_list(prm.get("Released boundary ids"),
                                         "Excavation/Released boundary ids"))
        released_boundaries.insert(id);
    }
    prm.leave_subsection();
  }



  double
  Excavation::released(const double t)
  {
    return std::min(1., std::max(0., t));
  }



  template SymmetricTensor<2, 2>
  InSituStress::stress(const Point<2> &) const;
  template SymmetricTensor<2, 3>
  InSituStress::stress(const Point<3> &) const;
  template SymmetricTensor<2, 3>
  InSituStress::stress_3d(const Point<2> &) const;
  template SymmetricTensor<2, 3>
  InSituStress::stress_3d(const Point<3> &) const;
} // namespace mbfem

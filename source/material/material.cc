#include <mbfem/base/text_input.h>
#include <mbfem/material/material.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mbfem
{
  Material::Material(const double youngs_modulus, const double poissons_ratio)
    : youngs_modulus(youngs_modulus)
    , poissons_ratio(poissons_ratio)
  {
    check("Material");
  }



  void
  Material::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Young's modulus",
                        "1e9",
                        Patterns::Double(),
                        "Young's modulus E of the block material, in the "
                        "stress unit of the model (e.g. Pa or N/mm^2). Must "
                        "be positive.");
      prm.declare_entry(
        "Poisson's ratio",
        "0.25",
        Patterns::Double(),
        "Poisson's ratio nu. Must lie in (-1, 0.5): at 0.5 the material is "
        "incompressible and this displacement formulation locks.");
      prm.declare_entry(
        "Unit weight",
        "0",
        Patterns::Double(0.),
        "Weight per unit volume (e.g. 24e3 N/m^3 for rock). Gravity acts in "
        "-y in 2D and -z in 3D, in addition to any body force function.");
      prm.declare_entry(
        "Block materials",
        "",
        Patterns::Anything(),
        "Materials of individual blocks (material ids of the mesh), as "
        "'id: E nu [unit weight]' separated by ';', e.g. '1: 20e9 0.25 "
        "24e3; 2: 30e9 0.2 24e3'. If given, every block must be listed; if "
        "empty, every block takes the values above.");
    }
    prm.leave_subsection();
  }



  void
  Material::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      youngs_modulus = prm.get_double("Young's modulus");
      poissons_ratio = prm.get_double("Poisson's ratio");
      unit_weight    = prm.get_double("Unit weight");
    }
    prm.leave_subsection();
    check("subsection Material");
  }



  std::map<types::material_id, Material>
  Material::parse_block_materials(ParameterHandler &prm)
  {
    std::map<types::material_id, Material> materials;
    prm.enter_subsection("Material");
    const std::string text = prm.get("Block materials");
    prm.leave_subsection();
    for (const auto &entry : split_list(text, ';', "Material/Block materials"))
      {
        const auto parts = Utilities::split_string_list(entry, ':');
        AssertThrow(parts.size() == 2,
                    ExcMessage("Material/Block materials: cannot read '" +
                               entry + "'; write 'id: E nu [unit weight]'."));
        std::istringstream  in(parts[1]);
        std::vector<double> values;
        double              value;
        while (in >> value)
          values.push_back(value);
        AssertThrow((values.size() == 2 || values.size() == 3) && in.eof(),
                    ExcMessage("Material/Block materials: '" + entry +
                               "' needs E, nu and optionally the unit "
                               "weight, as numbers."));
        const int id = Utilities::string_to_int(parts[0]);
        AssertThrow(id >= 0,
                    ExcMessage("Material/Block materials: '" + parts[0] +
                               "' is not a material id (0 or more)."));
        // A block given twice would take one of its values silently.
        AssertThrow(materials.count(id) == 0,
                    ExcMessage("Material/Block materials: block " +
                               std::to_string(id) +
                               " is listed twice; give each block once."));
        Material material;
        material.youngs_modulus = values[0];
        material.poissons_ratio = values[1];
        material.unit_weight    = (values.size() == 3 ? values[2] : 0.);
        material.check("Material/Block materials, block " + std::to_string(id));
        materials[id] = material;
      }
    return materials;
  }



  void
  Material::check(const std::string &where) const
  {
    AssertThrow(std::isfinite(youngs_modulus) &&
                  std::isfinite(poissons_ratio) && std::isfinite(unit_weight),
                ExcMessage(where + ": Young's modulus, Poisson's ratio and "
                                   "the unit weight must be finite numbers."));
    AssertThrow(youngs_modulus > 0.,
                ExcMessage(where + ": Young's modulus must be positive, got " +
                           std::to_string(youngs_modulus) + "."));
    // In SI units (Pa) the stiffest solid (diamond) has 1.2e12, and kPa or
    // MPa give smaller numbers: a larger value is a slip (a string of digits,
    // a unit off by a factor of 1000), not a material.
    std::ostringstream value;
    value << youngs_modulus;
    AssertThrow(youngs_modulus <= 1e15,
                ExcMessage(where + ": Young's modulus " + value.str() +
                           " is stiffer than any solid in SI units (diamond: "
                           "1.2e12 Pa); mbfem takes E up to 1e15. Check the "
                           "value and its units."));
    AssertThrow(poissons_ratio > -1. && poissons_ratio < 0.5,
                ExcMessage(
                  where + ": Poisson's ratio must lie in (-1, 0.5), got " +
                  std::to_string(poissons_ratio) +
                  ". At nu = 0.5 the material is incompressible and the "
                  "displacement formulation cannot represent it."));
  }



  double
  Material::lambda() const
  {
    return youngs_modulus * poissons_ratio /
           ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
  }



  double
  Material::mu() const
  {
    return youngs_modulus / (2. * (1. + poissons_ratio));
  }



  template <int dim>
  SymmetricTensor<2, dim>
  Material::stress(const SymmetricTensor<2, dim> &strain) const
  {
    return lambda() * trace(strain) * unit_symmetric_tensor<dim>() +
           2. * mu() * strain;
  }



  template <int dim>
  SymmetricTensor<2, 3>
  Material::stress_3d(const SymmetricTensor<2, dim> &strain) const
  {
    const SymmetricTensor<2, dim> s = stress(strain);
    SymmetricTensor<2, 3>         full;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        full[i][j] = s[i][j];
    if (dim == 2)
      full[2][2] = lambda() * trace(strain); // plane strain: eps_zz = 0
    return full;
  }



  std::array<double, 3>
  principal_stresses(const SymmetricTensor<2, 3> &stress)
  {
    // deal.II returns the eigenvalues in descending order.
    return eigenvalues(stress);
  }



  double
  von_mises_stress(const SymmetricTensor<2, 3> &stress)
  {
    const SymmetricTensor<2, 3> s = deviator(stress);
    return std::sqrt(1.5 * scalar_product(s, s));
  }



  template SymmetricTensor<2, 2>
  Material::stress(const SymmetricTensor<2, 2> &) const;
  template SymmetricTensor<2, 3>
  Material::stress(const SymmetricTensor<2, 3> &) const;
  template SymmetricTensor<2, 3>
  Material::stress_3d(const SymmetricTensor<2, 2> &) const;
  template SymmetricTensor<2, 3>
  Material::stress_3d(const SymmetricTensor<2, 3> &) const;
} // namespace mbfem

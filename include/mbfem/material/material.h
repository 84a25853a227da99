#ifndef mbfem_material_material_h
#define mbfem_material_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>

#include <array>
#include <map>
#include <string>

namespace mbfem
{
  using namespace dealii;

  /**
   * Isotropic linear elastic material of a block. In 2D the blocks are in
   * plane strain (the state of a long dam section or a cavern cross-section),
   * so the out-of-plane stress sigma_zz = lambda tr(eps) is not zero and is
   * kept when principal stresses and the von Mises stress are reported.
   */
  class Material
  {
  public:
    Material() = default;

    /** Checks the values: E > 0 and -1 < nu < 0.5. */
    Material(const double youngs_modulus, const double poissons_ratio);

    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads subsection "Material"; rejects nu >= 0.5 with a message. */
    void
    parse_parameters(ParameterHandler &prm);

    double
    lambda() const;

    double
    mu() const;

    /** In-plane (2D) or full (3D) stress from the small strain. */
    template <int dim>
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &strain) const;

    /**
     * The full 3x3 stress: in 2D the in-plane stress plus the plane-strain
     * sigma_zz; in 3D the stress itself.
     */
    template <int dim>
    SymmetricTensor<2, 3>
    stress_3d(const SymmetricTensor<2, dim> &strain) const;

    double youngs_modulus = 1.;
    double poissons_ratio = 0.;

    /** Weight per unit volume; gravity acts in -y (2D) or -z (3D). */
    double unit_weight = 0.;

    /**
     * "Material/Block materials": material id -> material, for meshes whose
     * blocks differ; empty when every block takes the default.
     */
    static std::map<types::material_id, Material>
    parse_block_materials(ParameterHandler &prm);

  private:
    void
    check(const std::string &where) const;
  };

  /** Principal stresses sigma_1 >= sigma_2 >= sigma_3, tension positive. */
  std::array<double, 3>
  principal_stresses(const SymmetricTensor<2, 3> &stress);

  /** sqrt(3 J2) of the full stress. */
  double
  von_mises_stress(const SymmetricTensor<2, 3> &stress);
} // namespace mbfem

#endif

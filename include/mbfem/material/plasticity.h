#ifndef mbfem_material_plasticity_h
#define mbfem_material_plasticity_h

#include <mbfem/material/material.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

namespace mbfem
{
  using namespace dealii;

  /**
   * Subsection "Plasticity": elastic-perfectly plastic Mohr-Coulomb rock in
   * every block, solved by the constant-stiffness initial-stress method:
   * each block keeps its elastic stiffness (so its factorisation and its
   * contact flexibility stay valid), the plastic strain enters the load as
   * int B^T D eps_p, and every load increment is repeated (with its
   * contact iteration) until the plastic strain stops changing.
   */
  struct PlasticityParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    bool         enabled         = false;
    double       cohesion        = 0.;
    double       friction_angle  = 30.; // degrees
    double       dilatancy_angle = 0.;  // degrees
    double       tolerance       = 1e-6;
    unsigned int max_iterations  = 1000;
    /** Aitken's relaxation of the fixed-point iteration (else plain). */
    bool aitken = true;
    /**
     * Newton's method with the consistent tangent instead of the
     * initial-stress iteration: every iteration reassembles and
     * refactorises each block with its tangent stiffness and recomputes the
     * contact flexibilities.
     */
    bool newton = false;
  };



  /**
   * Mohr-Coulomb yield, f = k sigma_1 - sigma_3 - sigma_c <= 0 with
   * sigma_1 >= sigma_2 >= sigma_3 (tension positive), k = (1 + sin phi) /
   * (1 - sin phi), sigma_c = 2 c cos phi / (1 - sin phi), and the plastic
   * potential of the dilatancy angle psi. The return mapping works in
   * principal stresses (isotropic elasticity keeps the principal axes): to
   * the plane, to one of the two edges (sigma_1 = sigma_2 or sigma_2 =
   * sigma_3), or to the apex, whichever the trial stress lies behind
   * (Clausen, Damkilde and Andersen, Computers & Structures 2006).
   */
  class MohrCoulomb
  {
  public:
    MohrCoulomb(const PlasticityParameters &parameters,
                const Material             &material);

    /** f of @p stress; > 0 outside the yield surface. */
    double
    yield_function(const SymmetricTensor<2, 3> &stress) const;

    /**
     * Returns @p trial to the yield surface: @p stress the admissible
     * stress, @p plastic_strain the plastic strain increment D^{-1}
     * (trial - stress). Returns false (and stress = trial) if the trial is
     * elastic.
     */
    bool
    return_map(const SymmetricTensor<2, 3> &trial,
               SymmetricTensor<2, 3>       &stress,
               SymmetricTensor<2, 3>       &plastic_strain) const;

    /**
     * The consistent tangent d sigma / d eps of return_map() at @p trial,
     * for strains in the first dim directions (plane strain keeps eps_zz =
     * 0): C : d eps is the change of the returned stress. By central
     * differences of the return mapping (Perez-Foguet, Rodriguez-Ferran and
     * Huerta, IJNME 2000): the mapping switches between plane, edges and
     * apex, and one differentiated code path for each would be three
     * places to get wrong. Not symmetric for non-associated flow.
     */
    template <int dim>
    SymmetricTensor<4, dim>
    tangent(const SymmetricTensor<2, 3> &trial) const;

    /** D restricted to the first dim directions (plane strain in 2D). */
    template <int dim>
    SymmetricTensor<4, dim>
    elastic_tangent() const;

    /** D eps for a 3x3 strain. */
    SymmetricTensor<2, 3>
    elastic_stress(const SymmetricTensor<2, 3> &strain) const;

    /** D^{-1} sigma for a 3x3 stress. */
    SymmetricTensor<2, 3>
    elastic_strain(const SymmetricTensor<2, 3> &stress) const;

  private:
    double lambda, mu, youngs_modulus, poissons_ratio;
    double k, m, sigma_c;
  };
} // namespace mbfem

#endif

#ifndef mbfem_material_in_situ_stress_h
#define mbfem_material_in_situ_stress_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>

#include <set>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * Subsection "In-situ stress": the geostatic stress the rock is in before
   * anything is excavated (tension positive):
   *
   *   sigma_v = -(q + gamma (z_s - z)),   sigma_h = K0 sigma_v,
   *
   * z the vertical coordinate (y in 2D, z in 3D), z_s the surface
   * elevation, q a surcharge (the overburden above the model), gamma the
   * unit weight, K0 the lateral pressure coefficient. Both horizontal
   * stresses (in 2D: sigma_xx and the out-of-plane sigma_zz) are K0 sigma_v,
   * and there is no shear.
   *
   * It enters each block as an initial stress: the load gets -int B^T
   * sigma_0 and the output adds sigma_0 to the stress of the displacement.
   * With gravity of the same unit weight it is in equilibrium, so the
   * geostatic stage has zero displacement, and the interfaces carry the
   * compression sigma_0 puts on them from the first increment.
   */
  struct InSituStress
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    template <int dim>
    SymmetricTensor<2, dim>
    stress(const Point<dim> &point) const;

    /** With the out-of-plane component in 2D. */
    template <int dim>
    SymmetricTensor<2, 3>
    stress_3d(const Point<dim> &point) const;

    bool   enabled             = false;
    double surface_elevation   = 0.;
    double surcharge           = 0.;
    double unit_weight         = 0.;
    double lateral_coefficient = 1.;
    /**
     * Far-field boundaries held by the in-situ stress: they carry the
     * traction sigma_0 n throughout (the rock beyond the model).
     */
    std::set<types::boundary_id> stress_boundaries;
  };



  /**
   * Subsection "Excavation": cells removed from the mesh and the release of
   * the support they gave. The faces where the rest of the rock met them
   * (and any "Released boundary ids") carry (1 - lambda) sigma_0 n, lambda
   * = t clipped to [0, 1]: at t = 0 the rock is as before excavation, at
   * t = 1 the excavated rock's support is gone.
   */
  struct Excavation
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Fraction of the support released at pseudo-time @p t. */
    static double
    released(const double t);

    std::vector<types::material_id> excavated_ids;
    std::set<types::boundary_id>    released_boundaries;
  };
} // namespace mbfem

#endif

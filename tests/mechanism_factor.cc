// Limit equilibrium along the statics certificate's mechanism
// (StaticAdmissibility::Result::mechanism_factor), on rigid blocks whose
// limits are known in closed form; the couplings are written down directly
// as in tests/static_admissibility.cc.
// - A block sliding on an incline (2D): the mechanism is the down-dip
//   slide, and its limit equilibrium is the statics limit: both factors
//   are mu / tan(theta) exactly (to the bisection's 1e-7).
// - A tall block toppling (2D): the mechanism rotates it about its
//   down-dip corner, the other corner opens, and no strength holds it
//   there: the factor is below the search's bound of 0.001.
// - Hoek and Bray's symmetric wedge (3D), two planes at an included angle
//   xi, the line of intersection plunging psi: their factor of safety,
//   with the shear on both planes along the line, is
//     F = tan(phi) / (tan(psi) sin(xi / 2)),
//   which the mechanism factor must give to 1e-6 (the kinematics fix the
//   slide along the line, so no faceting enters). Statics alone also
//   allows shear across the line, which wedges the block between the
//   planes: its strength factor lies above, as for the 3D wedge of
//   parameters/wedge_3d.prm (1.3737 against 1.3249).

#include <mbfem/contact/static_admissibility.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <cstdio>

#include "rigid_blocks.h"

using namespace dealii;
using mbfem::JointLaw;
using mbfem::StaticAdmissibility;
using rigid_blocks::incline_2d;

namespace
{
  /**
   * A rigid wedge of unit weight on two planes through a line plunging
   * @p psi towards +y, at an included angle @p xi, symmetric about the
   * vertical plane through the line; four pairs on each plane.
   */
  StaticAdmissibility<3>::Result
  wedge_3d(const double psi, const double xi, const JointLaw joint)
  {
    const Tensor<1, 3> along({0., std::cos(psi), -std::sin(psi)});
    const Tensor<1, 3> up({0., std::sin(psi), std::cos(psi)});
    const Tensor<1, 3> x({1., 0., 0.});
    const double       s = std::sin(xi / 2.), c = std::cos(xi / 2.);
    // Each plane's direction up from the line, and its normal into the
    // wedge.
    const Tensor<1, 3> rise[2]   = {s * x + c * up, -s * x + c * up};
    const Tensor<1, 3> normal[2] = {-c * x + s * up, c * x + s * up};
    const Tensor<1, 3> centre    = 0.5 * c * up;
    const double       size      = 2.;
    FullMatrix<double> coupling(24, 6);
    std::vector<StaticAdmissibility<3>::Candidate> candidates(8);
    for (unsigned int k = 0; k < 8; ++k)
      {
        const unsigned int plane = k / 4;
        const Tensor<1, 3> point = (k % 2 == 0 ? -1. : 1.) * along +
                                   (k / 2 % 2 == 0 ? 0.1 : 1.) * rise[plane];
        const Tensor<1, 3> frame[3] = {normal[plane],
                                       along,
                                       cross_product_3d(normal[plane], along)};
        rigid_blocks::couple_pair_3d(coupling, k, point - centre, size, frame);
        candidates[k].joint = joint;
        candidates[k].area  = 0.25;
      }
    const std::vector<double> resultant = {0., 0., -1., 0., 0., 0.};
    return StaticAdmissibility<3>(candidates,
                                  mbfem::CouplingRows(coupling),
                                  resultant)
      .solve();
  }

  const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }
} // namespace



int
main()
{
  const double degree = numbers::PI / 180.;

  for (const double slope : {6.57, 24.2})
    for (const double fraction : {0.99, 1.01})
      {
        JointLaw joint;
        joint.friction_coefficient = std::tan(slope * degree) / fraction;
        const auto r = incline_2d(slope * degree, 2.26, 1.69, joint, 1.);
        std::printf("2D slide, theta = %5.2f deg, at %.2f of the limit: "
                    "mechanism factor %.5f, closed form %.5f, equal to the "
                    "strength factor to 1e-6: %s\n",
                    slope,
                    fraction,
                    r.mechanism_factor,
                    1. / fraction,
                    yes(std::abs(r.mechanism_factor - r.strength_factor) <
                        1e-6));
      }

  {
    JointLaw joint;
    joint.friction_coefficient = 2.;
    const auto r               = incline_2d(20. * degree, 1., 3., joint, 1.);
    std::printf("2D topple, theta = 20 deg: mechanism factor below 0.001 "
                "(no strength holds a block rotating about its corner): %s\n",
                yes(r.mechanism_factor_bounded && r.mechanism_factor < 1.));
  }

  for (const double xi : {60., 90., 120.})
    for (const double fraction : {0.99, 1.01})
      {
        const double psi = 30. * degree;
        // mu such that Hoek and Bray's F is 1 / fraction.
        const double hoek_bray_mu = std::tan(psi) * std::sin(xi * degree / 2.);
        JointLaw     joint;
        joint.friction_coefficient = hoek_bray_mu / fraction;
        const auto r               = wedge_3d(psi, xi * degree, joint);
        std::printf(
          "3D wedge, xi = %3.0f deg, psi = 30 deg, at %.2f of Hoek and "
          "Bray's limit: mechanism factor %.5f (closed form %.5f, within "
          "1e-6: %s), one free motion: %s, strength factor above it: %s "
          "(%.4f)\n",
          xi,
          fraction,
          r.mechanism_factor,
          1. / fraction,
          yes(std::abs(r.mechanism_factor * fraction - 1.) < 1e-6),
          yes(r.limit_mechanism_freedom == 1),
          yes(r.strength_factor > r.mechanism_factor * (1. + 1e-4)),
          r.strength_factor);
      }
  return 0;
}

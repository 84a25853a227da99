// The statics certificate's linear program (StaticAdmissibility) on rigid
// blocks whose limits are known in closed form, without finite elements:
// the coupling P_hat of a rigid block's three (2D) or six (3D) modes to
// pairs at its base corners is written down directly.
// - A block sliding on an incline at theta: the limit is mu = tan(theta),
//   so the strength factor is mu / tan(theta) exactly (2D), and within
//   the faceting's 1 / cos(pi / 64) = 1.0012 in 3D, where the cone is a
//   polygon. At 0.99 of the limit (mu = tan(theta) / 0.99) admissible
//   forces exist; at 1.01 none do and the mechanism is the down-dip
//   translation (to within a degree in 2D, the exact mechanism having no
//   rotation; within the facets' half spacing of 2.8 degrees in 3D).
// - A tall block toppling on a rough incline: b / h = 1/3 topples at
//   tan(theta) = 1/3 whatever the friction; the mechanism is a rotation
//   about the down-dip corner.
// - Cohesion alone: |W sin(theta)| <= c A gives the factor c A / (W sin).

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
  const char *
  verdict_name(const StaticAdmissibility<2>::Verdict v)
  {
    return v == StaticAdmissibility<2>::Verdict::admissible ? "admissible" :
           v == StaticAdmissibility<2>::Verdict::none       ? "none" :
                                                              "undecided";
  }

  const char *
  verdict_name(const StaticAdmissibility<3>::Verdict v)
  {
    return v == StaticAdmissibility<3>::Verdict::admissible ? "admissible" :
           v == StaticAdmissibility<3>::Verdict::none       ? "none" :
                                                              "undecided";
  }

  /** 3D: a 1 x 1 x 1 block on a plane dipping theta towards -x. */
  StaticAdmissibility<3>::Result
  incline_3d(const double theta, const JointLaw joint)
  {
    const Tensor<1, 3> t1({std::cos(theta), 0., std::sin(theta)});
    const Tensor<1, 3> t2({0., 1., 0.});
    const Tensor<1, 3> n({-std::sin(theta), 0., std::cos(theta)});
    // Tangents turned by 20 degrees in the plane, so that the slip
    // direction is not normal to a facet of the polygonal cone.
    const double       turn   = 20. * numbers::PI / 180.;
    const Tensor<1, 3> s1     = std::cos(turn) * t1 + std::sin(turn) * t2;
    const Tensor<1, 3> s2     = -std::sin(turn) * t1 + std::cos(turn) * t2;
    const Tensor<1, 3> centre = 0.5 * t1 + 0.5 * t2 + 0.5 * n;
    FullMatrix<double> coupling(12, 6);
    std::vector<StaticAdmissibility<3>::Candidate> candidates(4);
    for (unsigned int k = 0; k < 4; ++k)
      {
        const Tensor<1, 3> x        = (k % 2) * t1 + (k / 2) * t2 - centre;
        const Tensor<1, 3> frame[3] = {n, s1, s2};
        rigid_blocks::couple_pair_3d(coupling, k, x, std::sqrt(3.), frame);
        candidates[k].joint = joint;
        candidates[k].area  = 0.25;
      }
    const std::vector<double> resultant = {0., 0., -1., 0., 0., 0.};
    return StaticAdmissibility<3>(candidates,
                                  mbfem::CouplingRows(coupling),
                                  resultant)
      .solve();
  }

  /** Angle (degrees) between the mechanism's translation and @p d. */
  template <int dim>
  double
  angle_to(const std::vector<double> &mechanism, const Tensor<1, dim> &d)
  {
    Tensor<1, dim> v;
    for (unsigned int i = 0; i < dim; ++i)
      v[i] = mechanism[i];
    const double cosine = v * d / (v.norm() * d.norm());
    return std::acos(std::min(1., std::max(-1., cosine))) * 180. / numbers::PI;
  }
} // namespace



int
main()
{
  const double degree = numbers::PI / 180.;

  // Sliding, 2D, for several slopes; c = 0.
  for (const double slope : {6.57, 24.2, 35.})
    for (const double fraction : {0.99, 1.01})
      {
        const double theta = slope * degree;
        JointLaw     joint;
        joint.friction_coefficient = std::tan(theta) / fraction;
        const auto result          = incline_2d(theta, 2.26, 1.69, joint, 95.5);
        std::printf("2D slide, theta = %5.2f deg, load at %.2f of the limit: "
                    "%s, strength factor %.5f (closed form %.5f)",
                    slope,
                    fraction,
                    verdict_name(result.verdict),
                    result.strength_factor,
                    1. / fraction);
        if (!result.mechanism.empty())
          {
            const Tensor<1, 2> down_dip({-std::cos(theta), -std::sin(theta)});
            const double       angle = angle_to<2>(result.mechanism, down_dip);
            std::printf(", mechanism down-dip within 1 deg: %s, rotation "
                        "below 1e-6: %s",
                        angle < 1. ? "yes" : "no",
                        std::abs(result.mechanism[2]) < 1e-6 ? "yes" : "no");
          }
        std::printf("\n");
      }

  // Toppling, 2D: b / h = 1/3, mu = 2 (no sliding before 63 deg).
  for (const double slope : {17., 20.})
    {
      JointLaw joint;
      joint.friction_coefficient = 2.;
      const auto result = incline_2d(slope * degree, 1., 3., joint, 1.);
      std::printf("2D topple, theta = %5.2f deg (limit %.2f): %s",
                  slope,
                  std::atan(1. / 3.) / degree,
                  verdict_name(result.verdict));
      // Rotation about the down-dip corner (0, 0), counter-clockwise: the
      // centre moves as omega x (centre - corner), omega = mode / size.
      if (!result.mechanism.empty())
        {
          const double       theta = slope * degree;
          const double       omega = result.mechanism[2] / std::sqrt(10.);
          const Tensor<1, 2> centre =
            Tensor<1, 2>({std::cos(theta) * 0.5 - std::sin(theta) * 1.5,
                          std::sin(theta) * 0.5 + std::cos(theta) * 1.5});
          const Tensor<1, 2> expected({-omega * centre[1], omega * centre[0]});
          const Tensor<1, 2> found({result.mechanism[0], result.mechanism[1]});
          std::printf(", mechanism: counter-clockwise rotation about the "
                      "down-dip corner (to 1e-6): %s",
                      omega > 0. && (found - expected).norm() < 1e-6 ? "yes" :
                                                                       "no");
        }
      std::printf("\n");
    }

  // Cohesion alone, 2D: c A >= W sin(theta) at the limit.
  {
    JointLaw joint;
    joint.cohesion  = 10.;
    const auto   r  = incline_2d(30. * degree, 2., 1., joint, 30.);
    const double cf = 10. * 2. / (30. * std::sin(30. * degree));
    std::printf("2D cohesion, theta = 30 deg: %s, strength factor %.5f "
                "(closed form %.5f)\n",
                verdict_name(r.verdict),
                r.strength_factor,
                cf);
  }

  // Sliding, 3D, with polygonal cones of 64 sides.
  for (const double fraction : {0.99, 1.01})
    {
      const double theta = 30. * degree;
      JointLaw     joint;
      joint.friction_coefficient = std::tan(theta) / fraction;
      const auto   result        = incline_3d(theta, joint);
      const double ratio         = result.strength_factor * fraction;
      std::printf("3D slide, theta = 30 deg, load at %.2f of the limit: %s, "
                  "strength factor / closed form in [1, 1/cos(pi/64)]: %s",
                  fraction,
                  verdict_name(result.verdict),
                  ratio >= 1. - 1e-6 &&
                      ratio <= 1. / std::cos(numbers::PI / 64) + 1e-6 ?
                    "yes" :
                    "no");
      if (!result.mechanism.empty())
        {
          const Tensor<1, 3> down_dip({-std::cos(theta), 0., -std::sin(theta)});
          // The polygon's facets are 360/64 degrees apart, and the
          // mechanism slides normal to one of them: within half of that.
          std::printf(", mechanism down-dip within 2.9 deg (the facets' "
                      "half spacing): %s",
                      angle_to<3>(result.mechanism, down_dip) < 2.9 ? "yes" :
                                                                      "no");
        }
      std::printf("\n");
    }
  return 0;
}

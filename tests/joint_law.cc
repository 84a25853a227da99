// JointLaw, the one place of Table 1's Mohr-Coulomb law that the state
// methods ask: for a joint mu = 0.6, c = 100 kPa, sigma_t = 50 kPa and a
// pair of area 0.5 m2 the strength |r_T| <= c A + mu max(r_N, 0) and the
// cut-off r_N >= -sigma_t A, checked at forces on either side of each
// limit by 10 N against a tolerance of 1 N (so each case is decided by the
// law, not the tolerance), with cohesion and tension gone once broken and
// friction gone for tensile slip; the semismooth Newton method's disc
// (scaled units, cohesion only where held closed) and its stick test;
// strength reduction dividing all three strengths; and the statics
// certificate's polygonal cones: a force on the circle |r_T| = c A + mu r_N
// is inside the circumscribed polygon (largest row excess 0 where it
// touches a facet, below 0 between) and outside the inscribed one except
// at its vertices, and the cone shifted by the cut-off carries
// c A + mu (r_N + sigma_t A) (it passes through (-sigma_t A, c A)). Excesses
// print in kN to 3 decimals: a facet misplaced by 1 N shows.

#include <mbfem/interface/joint_law.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
  const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }

  /** The largest normal r_N + tangent . r_T - bound over @p facets. */
  double
  excess(const std::vector<mbfem::JointLaw::ConeFacet> &facets,
         const double                                   r_n,
         const double                                   t1,
         const double                                   t2)
  {
    double worst = -1e300;
    for (const auto &f : facets)
      worst = std::fmax(worst,
                        f.normal * r_n + f.tangent[0] * t1 + f.tangent[1] * t2 -
                          f.bound);
    return worst;
  }
} // namespace

int
main()
{
  mbfem::JointLaw law;
  law.friction_coefficient = 0.6;
  law.cohesion             = 100e3;
  law.tensile_strength     = 50e3;
  const double A = 0.5, tol = 1.;

  // Strength at r_N = 200 kN: 50 kN + 120 kN = 170 kN.
  std::printf("strength at 200 kN: %.1f kN; broken %.1f kN; tensile slip "
              "%.1f kN\n",
              law.shear_strength(200e3, A, false) / 1e3,
              law.shear_strength(200e3, A, true) / 1e3,
              law.shear_strength(200e3, A, false, true) / 1e3);
  std::printf("slips at |r_T| = 169.99 kN: %s; at 170.01 kN: %s; broken at "
              "120.01 kN: %s\n",
              yes(law.slips(200e3, 169.99e3, A, false, tol)),
              yes(law.slips(200e3, 170.01e3, A, false, tol)),
              yes(law.slips(200e3, 120.01e3, A, true, tol)));
  std::printf("friction margin at |r_T| = 150 kN: %.1f kN\n",
              law.friction_margin(200e3, 150e3, A, false) / 1e3);

  // Cut-off: sigma_t A = 25 kN.
  std::printf("breaks at r_N = -24.99 kN: %s; at -25.01 kN: %s; broken at "
              "-0.011 kN: %s; tension margin at -20 kN: %.1f kN\n",
              yes(law.breaks(-24.99e3, A, false, tol)),
              yes(law.breaks(-25.01e3, A, false, tol)),
              yes(law.breaks(-11., A, true, tol)),
              law.tension_margin(-20e3, A, false) / 1e3);

  // The disc, forces scaled by 1e-6: cohesion 0.05 where held closed.
  const double scale = 1e-6;
  std::printf("disc radius at xi = 0.2: held closed %.3f, unilateral %.3f; "
              "at xi = -0.2: %.3f, %.3f\n",
              law.disc_radius(0.2, A, true, scale),
              law.disc_radius(0.2, A, false, scale),
              law.disc_radius(-0.2, A, true, scale),
              law.disc_radius(-0.2, A, false, scale));
  std::printf("in the disc of 0.17: |z| = 0.169 %s, 0.171 %s; of 0: |z| = "
              "0 %s\n",
              yes(mbfem::JointLaw::in_disc(0.169, 0.17)),
              yes(mbfem::JointLaw::in_disc(0.171, 0.17)),
              yes(mbfem::JointLaw::in_disc(0., 0.)));

  // Strength reduction by F = 2: 25 kN + 60 kN at 200 kN, cut-off 12.5 kN.
  const mbfem::JointLaw reduced = law.reduced(2.);
  std::printf("reduced by 2: strength at 200 kN %.1f kN, tension limit "
              "%.1f kN; without reducing tension %.1f kN\n",
              reduced.shear_strength(200e3, A, false) / 1e3,
              reduced.tensile_limit(A, false) / 1e3,
              law.reduced(2., false).tensile_limit(A, false) / 1e3);

  // Polygonal cones at r_N = 200 kN, where the circle's radius is 170 kN;
  // in 3D 8 sides, facet normals at 0, 45, ... degrees, vertices between.
  const double pi = mbfem::JointLaw::pi, R = 170e3;
  const auto   outer = law.polygonal_cone(8, A, false, false, 1.);
  const auto inner = law.polygonal_cone(8, A, false, false, std::cos(pi / 8.));
  for (const double degrees : {0., 22.5, 30.})
    {
      const double a = degrees * pi / 180.;
      std::printf("circle at %4.1f deg: excess over the circumscribed "
                  "polygon %.3f kN, the inscribed %.3f kN\n",
                  degrees,
                  excess(outer, 200e3, R * std::cos(a), R * std::sin(a)) / 1e3,
                  excess(inner, 200e3, R * std::cos(a), R * std::sin(a)) / 1e3);
    }
  // 2D: two facets, +-t.
  const auto line = law.polygonal_cone(2, A, false, false, 1.);
  std::printf("2D: excess at r_T = +170 kN %.3f kN, -170 kN %.3f kN, "
              "-171 kN %.3f kN\n",
              excess(line, 200e3, R, 0.) / 1e3,
              excess(line, 200e3, -R, 0.) / 1e3,
              excess(line, 200e3, -171e3, 0.) / 1e3);
  // Shifted by the cut-off: at r_N = -25 kN the cone carries c A = 50 kN;
  // broken, the cone of friction alone from r_N = 0.
  const auto cutoff = law.polygonal_cone(2, A, false, true, 1.);
  const auto broken = law.polygonal_cone(2, A, true, true, 1.);
  std::printf("shifted by the cut-off: excess at (-25 kN, 50 kN) %.3f kN; "
              "broken at (0, 0) %.3f kN, (200 kN, 120 kN) %.3f kN\n",
              excess(cutoff, -25e3, 50e3, 0.) / 1e3,
              excess(broken, 0., 0., 0.) / 1e3,
              excess(broken, 200e3, 120e3, 0.) / 1e3);
  // The Newton method's tension margin, forces scaled by 1e-6.
  std::printf("tension margin at -20 kN, scaled by 1e-6: %.4f\n",
              law.tension_margin(-20e3 * scale, A, false, scale));
}

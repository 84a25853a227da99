#ifndef mbfem_interface_joint_law_h
#define mbfem_interface_joint_law_h

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace mbfem
{
  /**
   * The Mohr-Coulomb law of a joint (the paper's Table 1): friction
   * coefficient mu, cohesion c and tensile strength sigma_t, as stresses.
   * A pair of tributary area A sticks while |r_T| < c A + mu max(r_N, 0)
   * and carries tension up to sigma_t A; once it breaks (tension beyond
   * that, or opening) it keeps c = sigma_t = 0. This is the one place that
   * says so: the fast iteration's checks, the load path's margins, the
   * Newton method's friction disc, the certificate's polygonal cones and
   * its strength reduction all ask it (doc/contact_solver.md).
   */
  struct JointLaw
  {
    /** pi (this header does without deal.II's numbers::PI, the same value). */
    static constexpr double pi = 3.14159265358979323846;

    double friction_coefficient = 0.;
    double cohesion             = 0.;
    double tensile_strength     = 0.;

    /**
     * |r_T| a pair of area @p area carries at normal force @p r_n (> 0
     * compression); without cohesion once @p broken, and without friction
     * where @p tensile (slip with r_N < 0).
     */
    double
    shear_strength(const double r_n,
                   const double area,
                   const bool   broken,
                   const bool   tensile = false) const
    {
      return (broken ? 0. : cohesion) * area +
             (tensile ? 0. : friction_coefficient) * std::max(r_n, 0.);
    }

    /** Largest tension (> 0) a pair of area @p area carries. */
    double
    tensile_limit(const double area, const bool broken) const
    {
      return (broken ? 0. : tensile_strength) * area;
    }

    /**
     * How far a pair at normal force @p r_n is inside the tension cut-off
     * (> 0 inside), as a force: the load path's margin, the check's, and
     * the Newton method's in its units, where a force is @p scale times
     * larger.
     */
    double
    tension_margin(const double r_n,
                   const double area,
                   const bool   broken,
                   const double scale = 1.) const
    {
      return r_n + scale * tensile_limit(area, broken);
    }

    /**
     * How far a tangential force of magnitude @p r_t is inside the friction
     * cone at normal force @p r_n (> 0 inside), as a force.
     */
    double
    friction_margin(const double r_n,
                    const double r_t,
                    const double area,
                    const bool   broken,
                    const bool   tensile = false) const
    {
      return shear_strength(r_n, area, broken, tensile) - r_t;
    }

    /**
     * Table 1's check of a closed pair against the tension cut-off: beyond
     * it by more than @p tolerance (a force), the pair breaks open.
     */
    bool
    breaks(const double r_n,
           const double area,
           const bool   broken,
           const double tolerance) const
    {
      return tension_margin(r_n, area, broken) < -tolerance;
    }

    /**
     * Table 1's check of a stuck pair: |r_T| = @p r_t beyond the friction
     * cone by more than @p tolerance (a force), the pair slips.
     */
    bool
    slips(const double r_n,
          const double r_t,
          const double area,
          const bool   broken,
          const double tolerance) const
    {
      return friction_margin(r_n, r_t, area, broken) < -tolerance;
    }

    /** The line |r_T| = intercept + slope r_N of slip_line(). */
    struct SlipLine
    {
      double slope     = 0.;
      double intercept = 0.;
    };

    /**
     * The line |r_T| = c A + mu r_N along which a slipping pair's forces
     * move, for the linear rows of the state iteration, the mechanism
     * test, the certificate's dual cone and Lemke's tableau: no cohesion
     * once @p broken, no friction where the pair slips in tension
     * (@p tensile). A curved law gives its tangent here (and states so):
     * those rows are linear in r_N.
     */
    SlipLine
    slip_line(const double area,
              const bool   broken,
              const bool   tensile = false) const
    {
      return {tensile ? 0. : friction_coefficient,
              shear_strength(0., area, broken)};
    }

    /**
     * The friction disc of the semismooth Newton method (Alart and
     * Curnier's form), in its units, where a force is @p scale times
     * larger: radius c A scale + mu max(xi, 0) at augmented normal force
     * @p xi, the cohesion only where @p cohesive (a pair held closed
     * until it breaks; a unilateral pair's disc must vanish as it opens).
     */
    double
    disc_radius(const double xi,
                const double area,
                const bool   cohesive,
                const double scale) const
    {
      return scale * (cohesive ? shear_strength(0., area, false) : 0.) +
             friction_coefficient * std::max(xi, 0.);
    }

    /**
     * d disc_radius() / d xi: the Newton Jacobian's term of a slipping
     * pair's normal force (mu where xi > 0, else 0).
     */
    double
    disc_slope(const double xi) const
    {
      return xi > 0. ? friction_coefficient : 0.;
    }

    /**
     * The semismooth projection's case: z = r_T - v (the tangential force
     * less the slip increment) inside the disc of @p radius means the pair
     * sticks, outside it slips along z.
     */
    static bool
    in_disc(const double z_norm, const double radius)
    {
      return radius > 0. && z_norm <= radius;
    }

    /**
     * The law of strength reduction at factor @p factor: tan(phi) / F and
     * c / F, and sigma_t / F if @p reduce_tension (as the statics
     * certificate divides all three).
     */
    JointLaw
    reduced(const double factor, const bool reduce_tension = true) const
    {
      JointLaw law = *this;
      law.friction_coefficient /= factor;
      law.cohesion /= factor;
      if (reduce_tension)
        law.tensile_strength /= factor;
      return law;
    }

    /**
     * A facet of the friction cone as a row of a linear program:
     * normal r_N + tangent . r_T <= bound, r_T in the pair's tangents
     * (the second zero in 2D).
     */
    struct ConeFacet
    {
      double                normal = 0.;
      std::array<double, 2> tangent{{0., 0.}};
      double                bound = 0.;
    };

    /**
     * The facet e . r_T <= kappa (c A + mu r_N) of the cone of a pair of
     * area @p area, for the unit tangent @p e. With @p shifted_by_cutoff
     * the cone is moved by the cut-off sigma_t A along r_N,
     * kappa (c A + mu (r_N + sigma_t A)): it then passes through
     * (-sigma_t A, c A) and contains every force the law admits, tension
     * included (its apex at r_N = -(c A / mu + sigma_t A)).
     */
    ConeFacet
    cone_facet(const std::array<double, 2> &e,
               const double                 area,
               const bool                   broken,
               const bool                   shifted_by_cutoff,
               const double                 kappa = 1.) const
    {
      const double strength =
        shear_strength(0., area, broken) +
        (shifted_by_cutoff ?
           friction_coefficient * tensile_limit(area, broken) :
           0.);
      return {-kappa * friction_coefficient, e, kappa * strength};
    }

    /**
     * The cone as a polygon of @p n_sides facets for the statics
     * certificate's linear programs: @p n_sides = 2 is the 2D cone
     * (e = +-t, kappa = 1: exact); from 3 on (3D) the unit tangents at
     * angles 2 pi j / n_sides, where kappa = 1 circumscribes the circle
     * |r_T| = c A + mu r_N and cos(pi / n_sides) inscribes it.
     */
    std::vector<ConeFacet>
    polygonal_cone(const unsigned int n_sides,
                   const double       area,
                   const bool         broken,
                   const bool         shifted_by_cutoff,
                   const double       kappa) const
    {
      std::vector<ConeFacet> facets;
      for (unsigned int j = 0; j < n_sides; ++j)
        {
          const double                angle = 2. * pi * j / n_sides;
          const std::array<double, 2> e =
            (n_sides == 2 ?
               std::array<double, 2>{{j == 0 ? 1. : -1., 0.}} :
               std::array<double, 2>{{std::cos(angle), std::sin(angle)}});
          facets.push_back(
            cone_facet(e, area, broken, shifted_by_cutoff, kappa));
        }
      return facets;
    }

    /** Whether a pair of this joint breaks when it opens or fails. */
    bool
    has_strength() const
    {
      return cohesion > 0. || tensile_strength > 0.;
    }
  };
} // namespace mbfem

#endif

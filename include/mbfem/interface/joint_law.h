#ifndef mbfem_interface_joint_law_h
#define mbfem_interface_joint_law_h

#include <algorithm>

namespace mbfem
{
  /**
   * The Mohr-Coulomb law of a joint (the paper's Table 1): friction
   * coefficient mu, cohesion c and tensile strength sigma_t, as stresses.
   * A pair of tributary area A sticks while |r_T| < c A + mu max(r_N, 0)
   * and carries tension up to sigma_t A; once it breaks (tension beyond
   * that, or opening) it keeps c = sigma_t = 0. This is the one place that
   * says so: strength reduction and joint water pressure belong here too.
   */
  struct JointLaw
  {
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

    /** Whether a pair of this joint breaks when it opens or fails. */
    bool
    has_strength() const
    {
      return cohesion > 0. || tensile_strength > 0.;
    }
  };
} // namespace mbfem

#endif

#ifndef mbfem_contact_static_admissibility_h
#define mbfem_contact_static_admissibility_h

#include <mbfem/contact/coupling_rows.h>
#include <mbfem/interface/joint_law.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The statics certificate behind "no equilibrium" (design.md, section 4;
   * issue 20): do contact forces exist at the candidate pairs that lie in
   * every pair's Mohr-Coulomb cone and balance the loads of all floating
   * blocks together? A linear program over the pairs' forces rho (in their
   * frames: normal, then tangents), whatever the blocks' stiffness:
   *
   *   P_hat^T rho = -F_e,                (every floating mode)
   *   r_n >= -sigma_t A,                 (every pair)
   *   |r_t| <= c A + mu r_n.
   *
   * In 3D the circular cone is a polygon of n_facets sides, circumscribed
   * to prove that no forces exist (its cone contains the true one) and
   * inscribed to show that some do (contained in it). With a tensile
   * strength the circumscribed cone is |r_t| <= c A + mu (r_n + sigma_t A),
   * the inscribed one the line above, so that the two still bracket the
   * joint law (whose strength cA + mu max(r_n, 0) is not convex).
   *
   * It is solved as a phase-1 LP: minimise the sum of slacks on the
   * equilibrium rows. A positive optimum proves that no admissible forces
   * exist; the duals of the equilibrium rows are then a virtual velocity of
   * the floating modes along which the loads do more work than the joints
   * can dissipate: the mechanism. Forces are divided by the largest load
   * resultant so that every entry is of unit order (models run in N and
   * Pa, kN and kPa, or N and mm).
   *
   * The margin is the strength factor: the largest F such that forces
   * exist with mu/F, c/F and sigma_t/F (bisection on F, each step an LP).
   * F < 1 means none exist; for a rigid block sliding on one plane it is
   * the limit-equilibrium factor of safety, and it bounds any elastic
   * factor of safety from above.
   *
   * The LP solver is COIN-OR Clp (doc/decisions.md says why).
   */
  template <int dim>
  class StaticAdmissibility
  {
  public:
    /** What the LP needs of a candidate pair. */
    struct Candidate
    {
      JointLaw joint;
      double   area = 0.;
      /** Broken pairs keep neither cohesion nor tensile strength. */
      bool broken = false;
      /** Tied pairs carry any force (ContactPair::tied). */
      bool tied = false;
      /** Directions held by supports carry no contact force. */
      std::array<bool, dim> held{};
    };

    enum class Verdict
    {
      /** Forces exist even in the inscribed cones. */
      admissible,
      /** No forces exist even in the circumscribed cones. */
      none,
      /** 3D: between the inscribed and circumscribed cones. */
      undecided
    };

    struct Result
    {
      Verdict verdict = Verdict::admissible;
      /**
       * Phase-1 optimum in the circumscribed cones, relative to the sum of
       * |F_e|: 0 if admissible.
       */
      double infeasibility = 0.;
      /** Largest strength factor with admissible forces (circumscribed). */
      double strength_factor = 0.;
      /** The factor reached the search's bound (a lower bound then). */
      bool strength_factor_bounded = false;
      /**
       * The mechanism from the LP's duals, per floating mode (P_hat's
       * columns), largest entry 1, oriented so that the loads do positive
       * work; empty if admissible. It is the mechanism of associated flow:
       * its sliding pairs open at the friction angle (a block on an
       * incline at theta "slides" at theta - phi to the horizontal).
       */
      std::vector<double> associated_mechanism;
      /**
       * The same without the dilatancy, as the blocks would move on
       * joints that do not dilate: associated_mechanism projected so that
       * its sliding pairs keep their normal distance and its pairs at rest
       * stay at rest (pairs that open stay free). A block slides along
       * its plane, a wedge along the line of intersection, a column
       * topples about its toe. This is the one the messages name.
       */
      std::vector<double> mechanism;
      /**
       * The mechanism of mechanism_factor: @p mechanism if no admissible
       * forces exist, else the one of the statics limit (the same LP at
       * 1.0001 x the strength factor); empty if the strength factor is
       * unbounded, or if the mechanism would drive a pair into its
       * neighbour (the projection leaves opening pairs free).
       */
      std::vector<double> limit_mechanism;
      /**
       * How many independent motions keep limit_mechanism's sliding pairs
       * sliding and its pairs at rest at rest: 1 if the kinematics alone
       * fix its direction (a wedge on two planes), 0 if it is not
       * projected (the associated one).
       */
      unsigned int limit_mechanism_freedom = 0;
      /**
       * Limit equilibrium along limit_mechanism, as Hoek and Bray's wedge
       * or Goodman and Bray's toppling analyses do it: the largest F such
       * that forces exist with every sliding pair's shear against its slip
       * and at most (c A + mu (N + sigma_t A)) / F, N >= -sigma_t A / F (so
       * N >= 0 without tensile strength), the pairs that open carrying
       * nothing, and those at rest anything in their (circumscribed)
       * cone. Motion along the mechanism needs such forces, so below 1
       * the blocks cannot move this way in equilibrium. At most the
       * strength factor in 2D and where the kinematics fix the direction
       * (in 3D otherwise the shear may turn by pi / n_facets from the
       * slip, which can lift it slightly above). 0 if there is no
       * mechanism.
       */
      double mechanism_factor = 0.;
      /** The factor reached the search's bound. */
      bool mechanism_factor_bounded = false;
      /** Admissible forces (per pair and direction), if any exist. */
      std::vector<double> forces;
      unsigned int        n_candidates = 0;
      unsigned int        n_solves     = 0;
      double              seconds      = 0.;
      /** The verdict in words, with the mechanism named per block. */
      std::string description;
    };

    /**
     * @p coupling has a row per pair and direction (k * dim + i, in the
     * pair's frame) and a column per floating mode; @p external_resultant
     * is F_e, per mode. Rows of pairs that touch no floating block are
     * ignored.
     */
    StaticAdmissibility(std::vector<Candidate>     candidates,
                        const CouplingRows        &coupling,
                        const std::vector<double> &external_resultant,
                        const unsigned int         n_facets = 64);

    /**
     * The verdict, the mechanism if none, the strength factor and, if
     * @p with_mechanism_factor, the mechanism factor.
     */
    Result
    solve(const bool with_mechanism_factor = true) const;

    /**
     * The phase-1 optimum, relative to the sum of |F_e|, with every joint's
     * strength divided by @p strength_factor, in circumscribed (outer) or
     * inscribed cones; the mechanism (duals) and forces if asked for.
     */
    double
    infeasibility(const double         strength_factor,
                  const bool           circumscribed,
                  std::vector<double> *mechanism = nullptr,
                  std::vector<double> *forces    = nullptr) const;

    /** A phase-1 optimum below this (relative) is feasible. */
    static constexpr double feasibility_tolerance = 1e-8;

    /**
     * The phase-1 optimum, relative to the sum of |F_e|, of limit
     * equilibrium along @p mechanism (Result::mechanism_factor) with every
     * joint's strength divided by @p strength_factor; @p freedom as
     * Result::limit_mechanism_freedom (in 3D, unless it is 1, the shear may
     * turn by pi / n_facets from the slip, the LP's error in direction).
     */
    double
    mechanism_infeasibility(const double               strength_factor,
                            const std::vector<double> &mechanism,
                            const unsigned int         freedom) const;

  private:
    /**
     * The sliding mechanism from the associated one (see Result) of the
     * LP at @p strength_factor, and how many independent motions it was
     * chosen from (@p freedom).
     */
    std::vector<double>
    sliding_mechanism(const std::vector<double> &associated,
                      const double               strength_factor,
                      unsigned int              &freedom) const;

    /**
     * Largest factor at which @p admissible (monotone: true up to the
     * factor, false beyond) holds, by bisection.
     */
    static double
    search_factor(const std::function<bool(double)> &admissible, bool &bounded);

    /** Result::mechanism (at the statics limit if admissible). */
    void
    add_mechanism_factor(Result &result) const;

    /**
     * The joint law of @p pair with its strength divided by
     * @p strength_factor (JointLaw::reduced()), and its area in the LP's
     * force units.
     */
    std::pair<JointLaw, double>
    law_of(const Candidate &pair, const double strength_factor) const;

    /** The relative velocity P_hat v of every pair, in its frame. */
    std::vector<double>
    pair_velocities(const std::vector<double> &mechanism) const;

    const std::vector<Candidate> candidates;
    const CouplingRows           coupling;
    const std::vector<double>    external_resultant;
    const unsigned int           n_facets;
    /** Forces are divided by this (the largest |F_e|). */
    double force_scale = 1.;
    /** Pairs that touch a floating block. */
    std::vector<unsigned int> active;
  };
} // namespace mbfem

#endif

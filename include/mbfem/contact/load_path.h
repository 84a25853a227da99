#ifndef mbfem_contact_load_path_h
#define mbfem_contact_load_path_h

#include <mbfem/contact/contact_state.h>
#include <mbfem/contact/fast_iteration.h>
#include <mbfem/contact/interface_system.h>
#include <mbfem/contact/mechanism_test.h>
#include <mbfem/contact/rigid_coupling.h>
#include <mbfem/contact/state_check.h>
#include <mbfem/interface/contact_interface.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The load path of the state iteration (doc/state_iteration.md,
   * doc/decisions.md): the increment's load scaled by s from the last
   * converged state (s = 0) to the full increment (s = 1). With the states
   * fixed the solution is affine in s; the path moves to the first s where
   * a pair's condition fails, switches that pair (every transition of the
   * joint law, open -> slip included), and goes on: a parametric principal
   * pivoting method, with the states as the pivots. It ends at s = 1 with
   * the states of the solution (which the owner then solves and checks as
   * the fast iteration does), or at a mechanism with the fraction it
   * reached.
   *
   * Everything is referenced, not copied; the loads are the owner's, which
   * the path sets to each fraction s (IncrementLoads::set_fraction()) and
   * leaves at s = 1.
   */
  template <int dim>
  class LoadPath
  {
  public:
    using Trial = StateTrial<dim>;

    /** How the path ended. */
    struct Outcome : StateMethodOutcome
    {
      // converged stays false: the states at s = 1 are still to be solved
      // and checked (LoadPathStateMethod::finish()). no_equilibrium: a
      // mechanism no switch mends; iterations: the switches.
      bool reached_end = false; // s = 1, with states
      /**
       * The states where the path ended: at s = 1 where reached_end, else
       * where it stopped. Their broken flags are the joints the path broke
       * for good (ContactSolver::certify_path_breaking()).
       */
      Trial states;
      /** The fraction of the increment's load the path held up to. */
      double s = 0.;
    };

    /**
     * The path from the @p committed states and relative displacements,
     * @p loads running from @p start_loads (s = 0) to @p full_loads (s =
     * 1), each trial solved by @p solve.
     */
    LoadPath(const std::vector<ContactPair<dim>>      &pairs,
             const std::vector<std::array<bool, dim>> &held,
             const RigidCoupling<dim>                 &coupling,
             const StateCheck<dim>                    &checks,
             const MechanismTest<dim>                 &mechanisms,
             const Trial                              &committed,
             const std::vector<Tensor<1, dim>>        &committed_displacement,
             const IncrementLoads                     &start_loads,
             const IncrementLoads                     &full_loads,
             IncrementLoads                           &loads,
             const typename FastIteration<dim>::Solve &solve);

    /** The path over the increment; @p head starts its messages. */
    Outcome
    run(const std::string &head);

    /**
     * The part of the path's messages that says how far it got: up to
     * load fraction @p s, after @p switches state switches.
     */
    static std::string
    how_far(const double s, const unsigned int switches);

  private:
    /** The solution of one path segment and where it ends. */
    struct Segment;
    /** The smallest margin of a pair's state at a point of a segment. */
    struct Margin;
    /** The first event on a segment: pair, kind and where. */
    struct Event;

    /** Solves @p trial at s_a and at 1; false if singular. */
    bool
    solve_segment(Trial &trial, const double s_a, Segment &segment);

    /**
     * 3D: Newton on the slip directions of @p trial at the present load
     * fraction (states fixed); returns false if singular.
     */
    bool
    correct_directions(Trial &trial, Segment &segment);

    /**
     * The smallest margin of pair @p k's state in @p trial at t on
     * @p segment (scaled: negative means failed), and which condition:
     * what first_event() samples and bisects.
     */
    Margin
    state_margin(const Trial       &trial,
                 const Segment     &segment,
                 const unsigned int k,
                 const double       t) const;

    /**
     * Whether pair @p k's margin can fail on @p segment: false where it
     * holds at the points between which it is concave (most pairs of a
     * segment), so first_event() samples only the others.
     */
    bool
    may_fail(const Trial       &trial,
             const Segment     &segment,
             const unsigned int k) const;

    Event
    first_event(const Trial &trial, const Segment &segment) const;

    /** The state of the pair of @p event once it has happened. */
    void
    switch_state(Trial         &trial,
                 const Segment &segment,
                 const Event   &event) const;

    /**
     * At a singular segment: the mechanism's motion, if any, mended by
     * unload_against() or close_along(); returns how many pairs switched
     * (0: the path ends there).
     */
    unsigned int
    mend_mechanism(Trial &trial, std::vector<double> &gap) const;

    /**
     * At a mechanism: the slipping pairs whose slip the mechanism's motion
     * would reverse stick instead (they are not at their limit along it).
     * Returns how many switched; 0 means the mechanism is the limit.
     */
    unsigned int
    unload_against(Trial &trial, const Vector<double> &motion) const;

    /**
     * At a mechanism that unloading cannot mend: the blocks move along it,
     * a finite motion at the same load, until the first open pair closes
     * (a column tipping onto its neighbour across a gap), which then slips
     * on in the direction it moved (or sticks, if it did not move
     * tangentially). Only along a motion the loads do work on, and only
     * for a pair it closes at a move of at most 100 times the gap. @p gap
     * is every pair's normal gap at the present s, updated for the motion.
     * Returns whether a pair closed.
     */
    bool
    close_along(Trial                &trial,
                const Vector<double> &motion,
                std::vector<double>  &gap) const;

    /**
     * The end where the states of @p pair and its neighbours cycle at one
     * load, wander there too long, or the path has switched too often.
     */
    Outcome
    cycle_end(const Trial       &trial,
              const std::string &head,
              const unsigned int pair,
              const double       s,
              const unsigned int switches) const;

    /**
     * The end at a singular segment that no switch mends: no equilibrium
     * naming the mechanism, or a singular system.
     */
    Outcome
    singular_end(const Trial       &trial,
                 const std::string &head,
                 const double       s,
                 const unsigned int switches) const;

    const std::vector<ContactPair<dim>>      &pairs;
    const std::vector<std::array<bool, dim>> &held;
    const RigidCoupling<dim>                 &coupling;
    const StateCheck<dim>                    &checks;
    const MechanismTest<dim>                 &mechanisms;
    const Trial                              &committed;
    const std::vector<Tensor<1, dim>>        &committed_displacement;
    const IncrementLoads                     &start_loads, &full_loads;
    IncrementLoads                           &loads;
    /** A copy: the caller's function may be a temporary. */
    const typename FastIteration<dim>::Solve solve;
  };
} // namespace mbfem

#endif

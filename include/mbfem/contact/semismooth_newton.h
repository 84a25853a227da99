#ifndef mbfem_contact_semismooth_newton_h
#define mbfem_contact_semismooth_newton_h

#include <mbfem/contact/condensed_system.h>
#include <mbfem/contact/contact_state.h>
#include <mbfem/contact/interface_system.h>
#include <mbfem/contact/rigid_coupling.h>
#include <mbfem/contact/state_method.h>
#include <mbfem/interface/contact_interface.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The semismooth Newton method of the state iteration
   * (doc/state_iteration.md): one load increment of the condensed system
   * written as one nonsmooth system in (rho, alpha), the joint law by Alart
   * and Curnier's projections, solved by Newton's method on its generalised
   * Jacobian (sparse, NewtonJacobian) with a backtracking line search and
   * Levenberg and Marquardt's step where that fails. Where it stalls, it
   * starts again with the floating blocks held by weak springs whose
   * anchors follow them (a proximal point iteration on the rigid motions,
   * solve_proximal()). Joints with strength break one at a time, the one
   * furthest beyond its tensile limit first.
   *
   * It does not decide the increment: its answer gives states, which
   * ContactSolver's fast iteration then solves and checks with the same
   * tolerances as every other method.
   */
  template <int dim>
  class SemismoothNewton
  {
  public:
    /**
     * The increment under @p loads from the committed states and relative
     * displacements, with the limits of @p parameters, on @p system (whose
     * floating modes @p coupling describes). Everything is referenced, not
     * copied: it must outlive this object.
     */
    SemismoothNewton(const StateMethodParameters              &parameters,
                     const std::vector<ContactPair<dim>>      &pairs,
                     const CondensedSystem<dim>               &system,
                     const RigidCoupling<dim>                 &coupling,
                     const std::vector<std::array<bool, dim>> &held,
                     const IncrementLoads                     &loads,
                     const StateTrial<dim>                    &committed,
                     const std::vector<Tensor<1, dim>> &committed_displacement);

    ~SemismoothNewton();

    /**
     * Newton's method from (rho, alpha) = @p start (or from zero if
     * @p start is empty); adds its steps to @p iterations. True if it
     * converged, with the joints it broke on the way.
     */
    bool
    solve(const Vector<double> &start, unsigned int &iterations);

    /**
     * Why solve() failed: the iteration limit, no descent, or a singular
     * Jacobian, and then why the springs failed.
     */
    std::string
    failure() const;

    /** The states (and slip directions) of solve()'s answer. */
    StateTrial<dim>
    answer_states() const;

  private:
    /** The unknowns u, the relative displacements, residual and Jacobian. */
    struct System;

    /** Pair @p k is closed by its strength until it breaks. */
    bool
    is_bilateral(const unsigned int k, const std::vector<bool> &broken) const;

    /** The rows of pair @p k: held directions, normal, then tangential. */
    void
    pair_residual(const unsigned int k, System &system) const;

    /** The friction disc's rows of pair @p k, radius from @p xi. */
    void
    tangential_residual(const unsigned int k,
                        const double       xi,
                        const bool         xi_has_gap,
                        System            &system) const;

    /** The residual (and Jacobian, if asked) at system.u; 1/2 |F|^2. */
    double
    evaluate(System &system) const;

    /**
     * Damped Newton on one system; false if it stalls. With
     * @p stopped_singular, also at its first singular Jacobian (the first
     * try, where the springs follow), which it then sets true.
     */
    bool
    solve_system(System       &system,
                 unsigned int &iterations,
                 bool         *stopped_singular = nullptr) const;

    /**
     * One system (one set of broken joints): solve_system() without
     * springs, stopping at a singular Jacobian where floating blocks
     * exist; where that fails, solve_proximal(); where that fails too
     * after a singular Jacobian, solve_system() again from the same start
     * with Levenberg-Marquardt's steps past it.
     */
    bool
    solve_system_or_springs(System &system, unsigned int &iterations) const;

    /**
     * Where solve_system() stalled or met a singular Jacobian: from
     * @p start again, every floating
     * block held by a spring to an anchor that moves to the block after
     * each solve, until the springs carry nothing; then once more without
     * springs. The Jacobian stays regular while a block has no closed
     * pair, and each solve is a well-posed contact problem.
     */
    bool
    solve_proximal(System               &system,
                   const Vector<double> &start,
                   unsigned int         &iterations) const;

    /**
     * solve_system()'s step: Newton's direction from the Jacobian, cut
     * to @p trust, with backtracking (only down to internal::min_step
     * where it was cut below internal::singular_cut); false if no length
     * decreases 1/2 |F|^2, with @p singular where the Jacobian is
     * singular or its step was cut that much (singular but for rounding).
     */
    bool
    line_search(System      &system,
                const double merit,
                const double trust,
                bool        &singular) const;

    /** solve_system()'s fallback step: Levenberg-Marquardt. */
    bool
    levenberg_marquardt_step(System      &system,
                             const double merit,
                             double      &damping) const;

    /**
     * The system's A from the blocks' flexibilities and the rigid-mode
     * coupling, sparse: a pair's row holds the pairs of its two blocks
     * only.
     */
    void
    set_matrix(System &system, const bool springs = false) const;

    /** The states (and slip directions) of @p system's answer. */
    StateTrial<dim>
    states(const System &system) const;

    /** The largest force and displacement of @p system, in u's units. */
    std::pair<double, double>
    scales(const System &system) const;

    /** The friction disc's radius (times scale) of pair @p k at @p xi. */
    double
    radius(const unsigned int k, const double xi, const System &system) const;

    /** The unbroken pair furthest beyond its tensile limit, if any. */
    unsigned int
    worst_tension(const System &system) const;

    const unsigned int                        max_iterations;
    const double                              tolerance;
    const double                              proximal_stiffness;
    const unsigned int                        proximal_steps;
    const std::vector<ContactPair<dim>>      &pairs;
    const CondensedSystem<dim>               &condensed;
    const RigidCoupling<dim>                 &coupling;
    const std::vector<std::array<bool, dim>> &held;
    const IncrementLoads                     &loads;
    const StateTrial<dim>                    &committed;
    const std::vector<Tensor<1, dim>>        &committed_displacement;
    const unsigned int                        n_pairs;

    /** solve()'s system and answer. */
    std::unique_ptr<System> answer;
  };
} // namespace mbfem

#endif

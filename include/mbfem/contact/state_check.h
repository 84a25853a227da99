#ifndef mbfem_contact_state_check_h
#define mbfem_contact_state_check_h

#include <mbfem/contact/condensed_system.h>
#include <mbfem/contact/contact_state.h>
#include <mbfem/contact/interface_system.h>
#include <mbfem/contact/rigid_coupling.h>
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
   * The check of Table 1's conditions on a solved trial: for every pair,
   * whether the forces and relative displacements that its assumed state
   * gave satisfy that state's inequalities (a stuck pair within its
   * Mohr-Coulomb strength, a slipping pair moving along its friction, an
   * open pair not penetrating), and if not, the state it goes to and by
   * how much it failed. Every method of the state iteration reads states
   * through it, with state_tolerance relative to the trial's largest force
   * and displacement, so that they decide alike.
   *
   * Everything is referenced, not copied: the owner (ContactSolver) keeps
   * the pairs, the held directions, the committed displacements and the
   * loads, which change between increments.
   */
  template <int dim>
  class StateCheck
  {
  public:
    using Trial = StateTrial<dim>;

    /**
     * @p condensed is nullptr for the monolithic formulation (no
     * flexibility on demand, so no closing limit).
     */
    StateCheck(const std::vector<ContactPair<dim>>      &pairs,
               const std::vector<std::array<bool, dim>> &held,
               const std::vector<Tensor<1, dim>>        &committed_displacement,
               const IncrementLoads                     &loads,
               const RigidCoupling<dim>                 &coupling,
               const CondensedSystem<dim>               *condensed);

    /**
     * The next trial from @p trial and its solve (forces @p solution,
     * relative displacements @p displacement, both in the pairs' frames):
     * each pair's state after its check, its violation (scaled, 0 where it
     * holds) in @p violation, and in 3D the largest change of a slip
     * direction in @p direction_change.
     */
    Trial
    check(const Trial          &trial,
          const Vector<double> &solution,
          const Vector<double> &displacement,
          std::vector<double>  &violation,
          double               &direction_change) const;

    /**
     * The fast iteration's start where the flexibility is on demand: the
     * fresh stuck pairs of @p trial (no gap, no force in
     * @p committed_solution, no strength, between immobile blocks) open,
     * so that their columns are computed only if the load presses them.
     */
    Trial
    open_on_demand(const Trial          &trial,
                   const Vector<double> &committed_solution) const;

    /** Whether both nodes of pair @p k are held in every direction. */
    bool
    all_held(const unsigned int k) const;

    /** Whether no floating mode moves pair @p k (P_hat's rows are zero). */
    bool
    immobile(const unsigned int k) const;

    /**
     * The states of @p trial as one character per pair (in 2D with the
     * slip's sign; upper case where broken): what the fast iteration
     * compares to find a cycle.
     */
    std::string
    signature(const Trial &trial) const;

  private:
    /**
     * The scales of the tolerances and violations, from what both
     * formulations know (not Delta_F, which only the condensed one
     * computes), so that they decide alike.
     */
    struct Scales
    {
      double force                  = 1e-300;
      double displacement           = 1e-300;
      double force_tolerance        = 0.;
      double displacement_tolerance = 0.;
    };

    Scales
    scales(const Vector<double> &solution,
           const Vector<double> &displacement) const;

    /**
     * The steps of check(), for pair @p k of @p trial by its state: the
     * new state into @p next and its violation into @p violation. A stuck
     * pair slips or breaks open...
     */
    void
    check_stick(const unsigned int    k,
                const Trial          &trial,
                const Vector<double> &solution,
                const Scales         &scales,
                Trial                &next,
                double               &violation) const;

    /**
     * ... a slipping pair sticks, breaks open, changes its direction (3D)
     * or its tensile slip...
     */
    void
    check_slip(const unsigned int    k,
               const Trial          &trial,
               const Vector<double> &solution,
               const Vector<double> &displacement,
               const Scales         &scales,
               Trial                &next,
               double               &violation,
               double               &direction_change) const;

    /** ... an open pair closes... */
    void
    check_open(const unsigned int    k,
               const Vector<double> &displacement,
               const Scales         &scales,
               Trial                &next,
               double               &violation) const;

    /** ... and a pair in tension beyond its limit opens (and breaks). */
    void
    break_open(const unsigned int k,
               const Trial       &trial,
               const double       r_n,
               const double       tension_limit,
               const Scales      &scales,
               Trial             &next,
               double            &violation) const;

    /**
     * Where the flexibility is on demand (CondensedSystem::on_demand()),
     * reopens in @p next the pairs between immobile blocks that close from
     * @p trial with less than internal::closing_fraction (0.9) of the
     * deepest penetration (@p violation).
     */
    void
    limit_closing(const Trial               &trial,
                  const std::vector<double> &violation,
                  Trial                     &next) const;

    const std::vector<ContactPair<dim>>      &pairs;
    const std::vector<std::array<bool, dim>> &held;
    const std::vector<Tensor<1, dim>>        &committed_displacement;
    const IncrementLoads                     &loads;
    const RigidCoupling<dim>                 &coupling;
    const CondensedSystem<dim>               *condensed;
  };
} // namespace mbfem

#endif

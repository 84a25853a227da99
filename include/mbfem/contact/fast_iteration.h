#ifndef mbfem_contact_fast_iteration_h
#define mbfem_contact_fast_iteration_h

#include <mbfem/contact/contact_state.h>
#include <mbfem/contact/mechanism_test.h>
#include <mbfem/contact/state_check.h>
#include <mbfem/contact/state_method.h>
#include <mbfem/interface/contact_interface.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The fast iteration of the state iteration (doc/state_iteration.md), the
   * paper's own: assume every pair's state, solve the interface system,
   * check each pair against its state (StateCheck), switch the pairs that
   * fail, until none does. Where the states repeat, or a trial leaves a
   * block unheld after a good one, it goes on switching only the pair that
   * failed worst. It concludes in a few solves on nearly every increment;
   * where it cycles, the next method of 'Contact/State method' takes over.
   *
   * It knows the interface system only through the solve it is given, so
   * it runs alike on the condensed and the monolithic formulation, and
   * from any states (the committed ones, or those another method found).
   */
  template <int dim>
  class FastIteration
  {
  public:
    using Trial = StateTrial<dim>;

    /**
     * The solve of a trial's states: the forces (rho, then the floating
     * amplitudes) and the relative displacements in the pairs' frames;
     * false if the system is singular.
     */
    using Solve = std::function<
      bool(const Trial &, Vector<double> &solution, Vector<double> &d)>;

    /** How the iteration ended, and its answer where it converged. */
    struct Outcome : StateMethodOutcome
    {
      // no_equilibrium: a singular trial, not a cycle; iterations: solves.
      /** The converged states (slip directions updated by the check). */
      Trial          states;
      Vector<double> solution, displacement;
      /** The slip directions the last solve used. */
      std::vector<Tensor<1, dim>> solved_slip_direction;
    };

    /**
     * At most @p max_iterations solves ('Contact/Maximum iterations');
     * everything is referenced, not copied. With @p stall_iterations > 0
     * it also gives up where, switching every failing pair (before a
     * cycle makes it switch one at a time), the number of pairs that
     * switch has not fallen to a new low in as many solves: it wanders
     * then, each solve a full one, while another method follows
     * ('Contact/Fast iteration stall'). A solve where only the 3D slip
     * directions move counts as progress.
     */
    FastIteration(const StateCheck<dim>               &checks,
                  const MechanismTest<dim>            &mechanisms,
                  const std::vector<ContactPair<dim>> &pairs,
                  const unsigned int                   max_iterations,
                  const unsigned int                   stall_iterations = 0);

    /**
     * The iteration from @p trial; @p head starts its messages ("Load
     * increment 3").
     */
    Outcome
    run(Trial trial, const Solve &solve, const std::string &head) const;

  private:
    /** What run() remembers from solve to solve. */
    struct Progress;

    /**
     * After a singular trial: back to the last trial that solved, with
     * only its worst pair switched, and damped from then on. False where
     * that was done already or no trial solved.
     */
    bool
    damp_after_singular(Progress &progress, Trial &trial) const;

    /**
     * The states after @p trial: its check's @p next, one pair of it only
     * where damped or where @p next was met before (which damps), and the
     * message where the damped states cycle or the undamped iteration
     * stalls (empty otherwise).
     */
    std::string
    choose_next(Progress                  &progress,
                const Trial               &trial,
                Trial                     &next,
                const std::vector<double> &violation,
                const unsigned int         iteration,
                const std::string         &head) const;

    /**
     * @p from with only the pair of the largest @p violation switched to
     * its state in @p to: the damped step.
     */
    static Trial
    single_change(const Trial               &from,
                  const Trial               &to,
                  const std::vector<double> &violation);

    /**
     * How many pairs @p next switches from @p trial, as the states'
     * signature tells them apart (StateCheck::signature()).
     */
    unsigned int
    n_switching(const Trial &trial, const Trial &next) const;

    /** The message when the undamped iteration stalls. */
    std::string
    describe_stall(const std::string &head,
                   const unsigned int iteration,
                   const unsigned int switching) const;

    /** The message when the states cycle even damped. */
    std::string
    describe_cycle(const std::string &head,
                   const unsigned int iteration,
                   const Trial       &trial,
                   const Trial       &next) const;

    const StateCheck<dim>               &checks;
    const MechanismTest<dim>            &mechanisms;
    const std::vector<ContactPair<dim>> &pairs;
    const unsigned int                   max_iterations;
    const unsigned int                   stall_iterations;
  };
} // namespace mbfem

#endif

#ifndef mbfem_analysis_model_h
#define mbfem_analysis_model_h

#include <mbfem/block/block.h>
#include <mbfem/contact/contact_solver.h>
#include <mbfem/interface/joint_water.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <memory>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  template <int dim>
  struct Parameters;

  /**
   * What every part of a run works on (as ASPECT's SimulatorAccess gives
   * its plugins the simulator's state): the parameters, the screen, the
   * blocks, the contact solver and the water of the present stage, the
   * monolithic reference, and the run's clocks. MultiBodyProblem owns it;
   * StageSequence, LoadSteps, RunReport and StrengthReductionRun each hold a
   * reference and do their part on it.
   */
  template <int dim>
  struct Model
  {
    Model(Parameters<dim> &parameters, ConditionalOStream &pcout);

    Parameters<dim>                         &parameters;
    ConditionalOStream                      &pcout;
    TimerOutput                              timer;
    std::vector<std::unique_ptr<Block<dim>>> blocks;

    /**
     * The contact solver of the present stage (nullptr: no interfaces),
     * and its water in the joints (nullptr: dry). StageSequence switches
     * them.
     */
    ContactSolver<dim> *contact = nullptr;
    JointWater<dim>    *water   = nullptr;
    /** Formulation "both": the monolithic solve beside the condensed one. */
    std::unique_ptr<ContactSolver<dim>> reference;

    /** A trial of strength reduction: nothing printed or written. */
    bool trial_run = false;

    /**
     * Wall time of the work of each formulation alone (not the mesh, the
     * load vectors or the output, which both share): condensed = block
     * factorisation, flexibilities, load responses, contact iterations,
     * field recovery; monolithic = its assembly and contact iterations
     * (one sparse LU each) and field recovery.
     */
    double condensed_seconds  = 0.;
    double monolithic_seconds = 0.;
    /**
     * The contact time of the last pass, of all passes and steps of this
     * increment, and of the last monolithic reference solve.
     */
    double last_contact_seconds      = 0.;
    double increment_contact_seconds = 0.;
    double last_reference_seconds    = 0.;

    /** Steps in which Newton gave way to the initial-stress method. */
    unsigned int newton_suspensions = 0;
  };
} // namespace mbfem

#endif

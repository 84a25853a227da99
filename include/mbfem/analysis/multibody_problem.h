#ifndef mbfem_analysis_multibody_problem_h
#define mbfem_analysis_multibody_problem_h

#include <mbfem/analysis/load_steps.h>
#include <mbfem/analysis/model.h>
#include <mbfem/analysis/run_report.h>
#include <mbfem/analysis/stage_sequence.h>
#include <mbfem/mesh/rock_mass.h>

#include <deal.II/base/conditional_ostream.h>

#include <memory>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  template <int dim>
  struct Parameters;

  /**
   * The multi-body finite element method from mesh to results: the mesh is
   * split into blocks (one per material id), each block is factorised once,
   * contact pairs are found on the declared interfaces, the blocks' contact
   * flexibilities are computed by unit loads, and the load history is
   * followed increment by increment (external response of every block,
   * contact-state iteration, field recovery, output). A mesh with one held
   * block and no interface is the plain elastic problem.
   *
   * The work is shared by the parts of a run, each a class on the Model:
   * StageSequence (the configurations of the stages), LoadSteps (one
   * increment: step halving, plastic passes, the contact solve),
   * RunReport (the screen and the files) and StrengthReductionRun (the
   * factor of safety). This class builds the model and walks the load
   * history, as step-18's run() and do_timestep().
   */
  template <int dim>
  class MultiBodyProblem
  {
  public:
    MultiBodyProblem(Parameters<dim> &parameters, ConditionalOStream &pcout);

    void
    run();

    /** The blocks with their final fields (after run()). */
    const std::vector<std::unique_ptr<Block<dim>>> &
    get_blocks() const;

    /** The contact solver, or nullptr without interfaces. */
    const ContactSolver<dim> *
    get_contact() const;

  private:
    /**
     * Mesh/Source = rock mass: the blocks' gmsh file built from the domain
     * and the joint sets with a spacing (build_rock_mass()), written to the
     * output folder, where make_blocks() then reads it.
     */
    void
    build_rock_mass_mesh();

    /** The screen's line of what build_rock_mass_mesh() built. */
    void
    print_rock_mass(const RockMassSummary          &summary,
                    const std::vector<JointPlanes> &sets,
                    const std::string              &file) const;

    void
    make_blocks();

    /**
     * Under mpirun, the rank that factorises and solves each block,
     * balanced by the blocks' cost() (Parallel::assign_owners()).
     */
    void
    assign_block_owners();

    /**
     * Whether the blocks are factorised: not if the monolithic formulation
     * alone runs, whose one system holds them all.
     */
    bool
    factorises_blocks() const;

    /** Each block's DoFs, constraints and stiffness (not yet factorised). */
    void
    setup_blocks();

    /**
     * Factorises each block's stiffness on its owner, if
     * factorises_blocks(): with MUMPS where the block's flexibility will be
     * on demand among @p pairs (its columns are entries of that
     * factorisation's inverse), so that the block does not hold Amesos's
     * as well; hence after the pairs are found.
     */
    void
    factorize_blocks(const std::vector<ContactPair<dim>> &pairs);

    /** Every block with free rigid-body modes has a pair that can hold it. */
    void
    check_blocks_held(const std::vector<ContactPair<dim>> &pairs) const;

    /**
     * The contact pairs and the formulation(s) that solve for their forces:
     * the condensed one (flexibilities), the monolithic one, or both.
     */
    void
    make_contact();

    /** Every increment of the load history, from the start. */
    void
    run_load_history();

    /**
     * One load increment, as step-18's do_timestep(): solve (with step
     * halving), check, print, compare, write, commit.
     */
    void
    do_increment(const unsigned int k);

    Model<dim> model;
    /** The gmsh file's joints in physical groups (make_blocks()). */
    JointFaces<dim>    joint_faces;
    StageSequence<dim> stages;
    RunReport<dim>     report;
    LoadSteps<dim>     steps;
  };
} // namespace mbfem

#endif

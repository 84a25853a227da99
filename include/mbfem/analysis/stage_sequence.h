#ifndef mbfem_analysis_stage_sequence_h
#define mbfem_analysis_stage_sequence_h

#include <mbfem/analysis/model.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mbfem
{
  /**
   * The stages of the load history as configurations of the model: the
   * blocks present and the contact pairs from one stage on, each with its
   * own condensed contact solver and water, and the hand-over from one to
   * the next (issue 28; doc/dam_safety.md, "Stages that add blocks"). A
   * model without stages that change it has one configuration. It sets the
   * model's contact solver and water to the present stage's.
   */
  template <int dim>
  class StageSequence
  {
  public:
    explicit StageSequence(Model<dim> &model);

    /**
     * Models whose stages add or remove blocks or switch interfaces on:
     * the refusals (the monolithic reference, plasticity, an in-situ
     * stress, unknown blocks or interfaces, an added block moved by its
     * supports before its stage, a block removed by the first stage or no
     * later than it is added), and each added or removed block's stage
     * (Block::set_added(), Block::set_removed()).
     */
    void
    check_staged_model();

    /**
     * The configurations of the stages from the pairs of the whole model
     * (a single one without stages that change the model), each with its
     * condensed solver set up.
     */
    void
    make_configurations(const std::vector<ContactPair<dim>> &pairs,
                        const std::function<std::unique_ptr<ContactSolver<dim>>(
                          std::vector<ContactPair<dim>>)>   &make_solver);

    /**
     * The monolithic formulation alone: its solver, of all @p n_pairs
     * pairs, as the one configuration.
     */
    void
    adopt(std::unique_ptr<ContactSolver<dim>> solver,
          const unsigned int                  n_pairs);

    /** Each configuration's water in the joints, where 'Water pressure' has
     * some. */
    void
    make_water();

    /**
     * Increment @p k begins a stage with another configuration: its
     * solver takes over (ContactSolver::continue_from()) and a line says
     * what the stage adds.
     */
    void
    switch_configuration(const unsigned int k);

    /**
     * Back to the first configuration with its states before the first
     * increment, the joints' strengths divided by @p factor.
     */
    void
    restart_contact(const double factor);

    /** ContactSolver::change_nominal_joints() on every configuration. */
    void
    change_nominal_joints(
      const std::function<void(const ContactPair<dim> &, JointLaw &)> &change);

    /** ContactSolver::set_early_verdict() on every configuration's solver. */
    void
    set_early_verdict(const bool early);

    /** What is left at @p time of the forces released on block @p b. */
    void
    add_released_forces(const unsigned int b, const double time);

    /**
     * The present configuration's pairs as indices into the pairs of the
     * whole model (empty where the model does not change in stages).
     */
    std::vector<unsigned int>
    present_pairs() const;

    /**
     * Flexibility columns computed on demand so far over all
     * configurations, and how many their blocks on demand have.
     */
    std::pair<std::size_t, std::size_t>
    columns_on_demand() const;

  private:
    /**
     * The blocks present and the pairs (indices into the pairs of the
     * whole model) from stage first_stage on, until the next
     * configuration's, with their contact solver and water.
     */
    struct Configuration
    {
      unsigned int                        first_stage = 0;
      std::vector<bool>                   present;
      std::vector<unsigned int>           pairs;
      std::unique_ptr<ContactSolver<dim>> solver;
      std::unique_ptr<JointWater<dim>>    water;
    };

    /**
     * The forces that the pairs of a removed block exerted on a block that
     * stays (its DoFs and forces), released linearly from full at start
     * to 0 at end, the removing stage's times.
     */
    struct ReleasedForces
    {
      unsigned int                         block = 0;
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  forces;
      double                               start = 0., end = 1.;
    };

    /**
     * switch_configuration(): the forces of the pairs of @p earlier that
     * end at stage @p s because it removes one of their blocks, as
     * released forces on the blocks that stay.
     */
    void
    release_removed_pairs(const Configuration &earlier,
                          const Configuration &next,
                          const unsigned int   s);

    /**
     * make_configurations(): every floating block of @p configuration
     * reaches a supported block through its pairs.
     */
    void
    check_configuration_held(const std::vector<ContactPair<dim>> &pairs,
                             const Configuration &configuration) const;

    /**
     * make_configurations(): the blocks of an interface that the stage of
     * @p configuration switches on are there.
     */
    void
    check_switched_on(const std::vector<ContactPair<dim>> &pairs,
                      const Configuration                 &configuration) const;

    /**
     * switch_configuration(): a line where the pairs of an interface
     * switched on now begin with the blocks overlapping.
     */
    void
    warn_of_overlap(const Configuration             &earlier,
                    const Configuration             &next,
                    const std::vector<unsigned int> &earlier_pair) const;

    Model<dim>                 &model;
    std::vector<Configuration>  configurations;
    unsigned int                active_configuration = 0;
    std::vector<ReleasedForces> released;
    /** The gap of every pair of the model as the mesh gives it. */
    std::vector<double> mesh_gaps;
  };
} // namespace mbfem

#endif

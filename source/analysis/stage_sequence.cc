// Stages that add blocks or switch interfaces on (issue 28, part 3): the
// model's configurations, one contact solver each, and the hand-over from
// one to the next (doc/dam_safety.md, "Stages that add blocks").

#include <mbfem/analysis/parameters.h>
#include <mbfem/analysis/stage_sequence.h>

#include <deal.II/base/types.h>

#include <algorithm>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <string>

namespace mbfem
{
  namespace
  {
    std::string
    quoted(const std::string &name)
    {
      return "'" + name + "'";
    }
  } // namespace



  template <int dim>
  StageSequence<dim>::StageSequence(Model<dim> &model)
    : model(model)
  {}



  namespace
  {
    /** What a model that changes in stages cannot be combined with. */
    template <int dim>
    void
    check_stages_allowed(const Parameters<dim> &parameters)
    {
      const std::string what =
        "'Load history/Added blocks' and 'Interfaces switched on'";
      AssertThrow(!parameters.contact.declares_interfaces() ||
                    !parameters.contact_solver.runs_monolithic(),
                  ExcMessage(what + " work with the condensed formulation "
                                    "only: set 'Contact/Formulation = "
                                    "condensed'."));
      AssertThrow(!parameters.plasticity.enabled,
                  ExcMessage(what + " work with elastic blocks only "
                                    "('Plasticity/Enabled = false')."));
      AssertThrow(!parameters.in_situ_stress.enabled,
                  ExcMessage(what + " cannot be combined with an in-situ "
                                    "stress (whose equilibrium holds for all "
                                    "blocks from the start)."));
    }

    /**
     * Every added or removed block is a block of the mesh, and a block is
     * removed after the stage that adds it (the first stage's entries are
     * refused by LoadHistory: nothing came before them).
     */
    template <int dim>
    void
    check_stage_blocks(const LoadHistory                              &history,
                       const std::vector<std::unique_ptr<Block<dim>>> &blocks)
    {
      const auto is_block = [&](const unsigned int id) {
        return std::any_of(blocks.begin(), blocks.end(), [id](const auto &b) {
          return b->get_id() == id;
        });
      };
      for (const auto &stage : history.stages)
        for (const bool adds : {true, false})
          for (const unsigned int id :
               (adds ? stage.added_blocks : stage.removed_blocks))
            AssertThrow(is_block(id),
                        ExcMessage(std::string("Load history/") +
                                   (adds ? "Added" : "Removed") +
                                   " blocks: stage " + quoted(stage.name) +
                                   (adds ? " adds" : " removes") + " block " +
                                   std::to_string(id) +
                                   ", but no block of the mesh has material "
                                   "id " +
                                   std::to_string(id) + "."));
      for (unsigned int s = 0; s < history.stages.size(); ++s)
        for (const unsigned int id : history.stages[s].removed_blocks)
          {
            const unsigned int added = history.stage_adding_block(id);
            AssertThrow(added == numbers::invalid_unsigned_int || added < s,
                        ExcMessage("Load history/Removed blocks: stage " +
                                   quoted(history.stages[s].name) +
                                   " removes block " + std::to_string(id) +
                                   ", which is added only by stage " +
                                   quoted(history
                                            .stages[std::min<unsigned int>(
                                              added, history.stages.size() - 1)]
                                            .name) +
                                   ": a block is removed after the stage that "
                                   "adds it."));
          }
    }

    /**
     * Every interface switched on is a declared one, numbered as declared
     * ('all' puts the interfaces it finds before them).
     */
    void
    check_stage_interfaces(const LoadHistory       &history,
                           const ContactParameters &contact)
    {
      const auto &interfaces = contact.interfaces;
      AssertThrow(!contact.all_shared_faces ||
                    std::all_of(history.stages.begin(),
                                history.stages.end(),
                                [](const auto &stage) {
                                  return stage.interfaces_on.empty();
                                }),
                  ExcMessage("Load history/Interfaces switched on numbers the "
                             "entries of 'Contact/Interfaces', which 'all' "
                             "renumbers with the interfaces it finds; declare "
                             "the interfaces one by one."));
      const auto n_declared =
        std::count_if(interfaces.begin(), interfaces.end(), [](const auto &i) {
          return !i.found;
        });
      for (const auto &stage : history.stages)
        for (const unsigned int number : stage.interfaces_on)
          AssertThrow(number >= 1 && number <= interfaces.size() &&
                        !interfaces[number - 1].found,
                      ExcMessage(
                        "Load history/Interfaces switched on: stage " +
                        quoted(stage.name) + " switches on interface " +
                        std::to_string(number) +
                        ", but 'Contact/Interfaces' declares " +
                        std::to_string(n_declared) + " (numbered from 1)."));
    }

    /**
     * Block @p block, which stage @p s adds, does not move before the
     * stage begins at @p start: no platen touches it, and its prescribed
     * displacements are zero until then.
     */
    template <int dim>
    void
    check_added_block_supports(const Block<dim>        &block,
                               const unsigned int       s,
                               const double             start,
                               const LoadHistory       &history,
                               BoundaryConditions<dim> &conditions)
    {
      const std::string added_by = block.name() + ", which stage " +
                                   quoted(history.stages[s].name) + " adds, ";
      Vector<double> value(dim);
      for (const auto &face : block.get_triangulation().active_face_iterators())
        {
          if (!face->at_boundary())
            continue;
          const auto id = face->boundary_id();
          AssertThrow(conditions.rigid_platens.count(id) == 0,
                      ExcMessage(added_by +
                                 "touches the rigid platen of boundary id " +
                                 std::to_string(id) +
                                 ": a platen would move it before it is "
                                 "there."));
          const auto support = conditions.dirichlet.find(id);
          if (support == conditions.dirichlet.end())
            continue;
          for (unsigned int k = 0;
               k <= history.n_increments && history.time(k) <= start;
               ++k)
            {
              conditions.set_time(history.time(k));
              for (const unsigned int v : face->vertex_indices())
                {
                  conditions.prescribed_displacement->vector_value(
                    face->vertex(v), value);
                  for (unsigned int c = 0; c < dim; ++c)
                    AssertThrow(
                      !support->second[c] || value[c] == 0.,
                      ExcMessage(
                        added_by + "has a prescribed displacement of " +
                        std::to_string(value[c]) +
                        " at t = " + std::to_string(history.time(k)) +
                        " on boundary id " + std::to_string(id) +
                        ", before it is there: 'Boundary conditions/"
                        "Prescribed displacement' must be zero on an added "
                        "block until its stage begins."));
                }
            }
        }
    }
  } // namespace



  template <int dim>
  void
  StageSequence<dim>::check_staged_model()
  {
    const LoadHistory &history = model.parameters.load_history;
    if (!history.changes_model())
      return;
    check_stages_allowed(model.parameters);
    check_stage_blocks(history, model.blocks);
    check_stage_interfaces(history, model.parameters.contact);

    // Mark when each block comes and goes; an added block does not move
    // before its stage.
    auto &conditions = model.parameters.boundary_conditions;
    for (auto &block : model.blocks)
      {
        const unsigned int removing =
          history.stage_removing_block(block->get_id());
        if (removing != numbers::invalid_unsigned_int)
          block->set_removed(history.stage_times(removing).first);
        const unsigned int s = history.stage_adding_block(block->get_id());
        if (s == numbers::invalid_unsigned_int)
          continue;
        const auto [start, end] = history.stage_times(s);
        block->set_added(start, end);
        check_added_block_supports(*block, s, start, history, conditions);
      }
    conditions.set_time(0.);
  }



  template <int dim>
  void
  StageSequence<dim>::make_configurations(
    const std::vector<ContactPair<dim>> &pairs,
    const std::function<std::unique_ptr<ContactSolver<dim>>(
      std::vector<ContactPair<dim>>)>   &make_solver)
  {
    const LoadHistory &history = model.parameters.load_history;
    const unsigned int n_stages =
      std::max<std::size_t>(history.stages.size(), 1);
    for (const auto &pair : pairs)
      mesh_gaps.push_back(pair.initial_gap);
    for (unsigned int s = 0; s < n_stages; ++s)
      {
        Configuration configuration;
        configuration.first_stage = s;
        for (const auto &block : model.blocks)
          {
            const unsigned int added =
              history.stage_adding_block(block->get_id());
            const unsigned int removed =
              history.stage_removing_block(block->get_id());
            configuration.present.push_back(
              (added == numbers::invalid_unsigned_int || added <= s) &&
              (removed == numbers::invalid_unsigned_int || s < removed));
          }
        for (unsigned int k = 0; k < pairs.size(); ++k)
          {
            const unsigned int on =
              history.stage_switching_on(pairs[k].interface + 1);
            if (configuration.present[pairs[k].a.block] &&
                configuration.present[pairs[k].b.block] &&
                (on == numbers::invalid_unsigned_int || on <= s))
              configuration.pairs.push_back(k);
          }
        if (!configurations.empty() &&
            configuration.present == configurations.back().present &&
            configuration.pairs == configurations.back().pairs)
          continue;

        check_configuration_held(pairs, configuration);
        check_switched_on(pairs, configuration);

        std::vector<ContactPair<dim>> subset;
        for (const unsigned int k : configuration.pairs)
          subset.push_back(pairs[k]);
        configuration.solver = make_solver(std::move(subset));
        configuration.solver->setup(model.blocks, configuration.present);
        configurations.push_back(std::move(configuration));
      }
    active_configuration = 0;
    model.contact        = configurations[0].solver.get();
  }



  template <int dim>
  void
  StageSequence<dim>::switch_configuration(const unsigned int k)
  {
    const LoadHistory &history = model.parameters.load_history;
    if (!history.starts_stage(k) || !history.changes_model() ||
        configurations.empty()) // no interfaces: loads alone change
      return;
    const unsigned int s = history.stage(k);
    unsigned int       c = active_configuration;
    while (c + 1 < configurations.size() &&
           configurations[c + 1].first_stage <= s)
      ++c;
    if (c == active_configuration)
      return;

    const Configuration &earlier = configurations[active_configuration];
    Configuration       &next    = configurations[c];
    // Pair k of the next solver is pair earlier_pair[k] of the earlier one.
    std::vector<unsigned int> earlier_pair;
    for (const unsigned int global : next.pairs)
      {
        const auto j =
          std::find(earlier.pairs.begin(), earlier.pairs.end(), global);
        earlier_pair.push_back(
          j == earlier.pairs.end() ?
            numbers::invalid_unsigned_int :
            static_cast<unsigned int>(j - earlier.pairs.begin()));
      }
    if (!model.trial_run)
      warn_of_overlap(earlier, next, earlier_pair);
    next.solver->continue_from(*earlier.solver, earlier_pair, model.blocks);
    release_removed_pairs(earlier, next, s);
    if (!model.trial_run)
      {
        std::string added, removed;
        for (unsigned int b = 0; b < model.blocks.size(); ++b)
          if (next.present[b] != earlier.present[b])
            {
              std::string &list = next.present[b] ? added : removed;
              list += (list.empty() ? "" : ", ") + model.blocks[b]->name();
            }
        std::string what = added.empty() ? "" : "adds " + added + ", ";
        if (!removed.empty())
          what += "removes " + removed +
                  " (the forces of its pairs on the blocks that stay are "
                  "released over the stage), ";
        const auto n_new = std::count(earlier_pair.begin(),
                                      earlier_pair.end(),
                                      numbers::invalid_unsigned_int);
        if (n_new > 0)
          what += "brings " + std::to_string(n_new) +
                  " new pair(s), closed where they are; ";
        model.pcout << "  the stage " << what << next.pairs.size()
                    << " pairs from here on\n";
      }
    active_configuration = c;
    model.contact        = next.solver.get();
    model.water          = next.water.get();
  }



  template <int dim>
  void
  StageSequence<dim>::release_removed_pairs(const Configuration &earlier,
                                            const Configuration &next,
                                            const unsigned int   s)
  {
    const auto [start, end] = model.parameters.load_history.stage_times(s);
    const ContactSolver<dim> &solver = *earlier.solver;
    for (unsigned int j = 0; j < earlier.pairs.size(); ++j)
      {
        const ContactPair<dim> &pair = solver.pairs()[j];
        if (next.present[pair.a.block] && next.present[pair.b.block])
          continue; // the pair stays (or its interface was on already)
        const Tensor<1, dim> r = solver.force(j);
        // Water in the joint pushes each face away from the other.
        const double p_w =
          earlier.water ? earlier.water->pressure(j, start) : 0.;
        for (const int sign : {-1, 1})
          {
            const auto &side = pair.side(sign);
            if (!next.present[side.block])
              continue;
            const Tensor<1, dim> f =
              sign * (r + p_w * pair.area * pair.frame[0]);
            ReleasedForces forces;
            forces.block = side.block;
            forces.start = start;
            forces.end   = end;
            for (const auto &node : side.nodes)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  forces.dofs.push_back(node.dofs[c]);
                  forces.forces.push_back(node.weight * f[c]);
                }
            released.push_back(std::move(forces));
          }
      }
  }



  template <int dim>
  void
  StageSequence<dim>::add_released_forces(const unsigned int b,
                                          const double       time)
  {
    for (const auto &forces : released)
      {
        if (forces.block != b)
          continue;
        const double left =
          1. - std::clamp((time - forces.start) / (forces.end - forces.start),
                          0.,
                          1.);
        if (left == 0.)
          continue;
        std::vector<double> values = forces.forces;
        for (double &value : values)
          value *= left;
        model.blocks[forces.block]->add_external_point_forces(forces.dofs,
                                                              values);
      }
  }



  namespace
  {
    /**
     * check_configuration_held()'s refusal of block @p block in stage
     * @p stage, whose group of @p n_members blocks (@p names) keeps the
     * rigid motions @p free (about @p centre).
     */
    template <int dim>
    std::string
    unheld_message(const std::string                 &block,
                   const std::string                 &stage,
                   const std::vector<Vector<double>> &free,
                   const Point<dim>                  &centre,
                   const unsigned int                 n_members,
                   const std::string                 &names)
    {
      std::ostringstream text;
      text << block << " is not held in stage " << stage
           << ": it has free rigid-body modes, and no chain of pairs there "
              "links it to a supported block";
      if (n_members == 1)
        text << "; its own supports leave ";
      else
        text << "; nor do the supports of the group its pairs link it into ("
             << names << ") hold it together: as one body the group keeps ";
      text << free.size() << " rigid motion(s) free,";
      bool rotates = false;
      for (const auto &motion : free)
        {
          text << " [" << Block<dim>::describe_rigid_body_mode(motion) << "]";
          for (unsigned int a = dim; a < motion.size(); ++a)
            rotates |= (motion(a) != 0.);
        }
      if (rotates)
        text << " (rotations about (" << std::setprecision(6) << centre << "))";
      text << ". A block is held by its pairs only from the stage that adds "
              "it or switches their interface on, until the stage that "
              "removes it or its neighbour.";
      return text.str();
    }
  } // namespace



  template <int dim>
  void
  StageSequence<dim>::check_configuration_held(
    const std::vector<ContactPair<dim>> &pairs,
    const Configuration                 &configuration) const
  {
    // The blocks there linked by its pairs form groups (a stage that removes
    // a block removes its pairs, one that adds it or switches an interface
    // on brings them). A group is held when its supports together leave it
    // no rigid motion as one body: a supported block in it, or rollers on
    // different blocks that hold different directions (issue 66).
    const unsigned int        n = model.blocks.size();
    std::vector<unsigned int> group(n);
    std::iota(group.begin(), group.end(), 0u);
    const auto root = [&](unsigned int b) {
      while (group[b] != b)
        b = group[b] = group[group[b]];
      return b;
    };
    for (const unsigned int k : configuration.pairs)
      group[root(pairs[k].a.block)] = root(pairs[k].b.block);

    const LoadHistory &history = model.parameters.load_history;
    const std::string  stage =
      history.stages.empty() ?
         std::string("(the only one)") :
         quoted(history.stages[configuration.first_stage].name);
    std::vector<bool> checked(n, false);
    for (unsigned int b = 0; b < n; ++b)
      {
        if (!configuration.present[b] || checked[root(b)])
          continue;
        checked[root(b)] = true;
        std::vector<const FloatingModes<dim> *> members;
        std::string                             names;
        for (unsigned int c = 0; c < n; ++c)
          if (configuration.present[c] && root(c) == root(b))
            {
              members.push_back(&model.blocks[c]->get_floating_modes());
              names += (names.empty() ? "" : ", ") + model.blocks[c]->name();
            }
        Point<dim> centre;
        double     size = 0.;
        const auto free =
          FloatingModes<dim>::free_group_motions(members, centre, size);
        AssertThrow(free.empty(),
                    ExcMessage(unheld_message(model.blocks[b]->name(),
                                              stage,
                                              free,
                                              centre,
                                              members.size(),
                                              names)));
      }
  }



  template <int dim>
  void
  StageSequence<dim>::check_switched_on(
    const std::vector<ContactPair<dim>> &pairs,
    const Configuration                 &configuration) const
  {
    // An interface switched on while a block of it is not there yet would
    // silently begin with that block instead.
    const LoadHistory &history = model.parameters.load_history;
    const unsigned int s       = configuration.first_stage;
    for (const auto &pair : pairs)
      {
        if (history.stage_switching_on(pair.interface + 1) != s)
          continue;
        for (const auto *side : {&pair.a, &pair.b})
          AssertThrow(configuration.present[side->block],
                      ExcMessage("Load history/Interfaces switched on: stage " +
                                 quoted(history.stages[s].name) +
                                 " switches on interface " +
                                 std::to_string(pair.interface + 1) + ", but " +
                                 model.blocks[side->block]->name() +
                                 " is not there in that stage."));
      }
  }



  template <int dim>
  void
  StageSequence<dim>::warn_of_overlap(
    const Configuration             &earlier,
    const Configuration             &next,
    const std::vector<unsigned int> &earlier_pair) const
  {
    // A switched-on interface between blocks that were both there: they
    // did not touch, so they may have moved into each other.
    double overlap = 0.;
    for (unsigned int k = 0; k < next.pairs.size(); ++k)
      {
        const ContactPair<dim> &pair = next.solver->pairs()[k];
        if (earlier_pair[k] != numbers::invalid_unsigned_int ||
            !earlier.present[pair.a.block] || !earlier.present[pair.b.block])
          continue;
        const double gap =
          mesh_gaps[next.pairs[k]] +
          pair.frame[0] * pair.relative_displacement(model.blocks);
        overlap = std::max(overlap, -gap);
      }
    if (overlap > 0.)
      model.pcout
        << "  warning: while their interface was off, the blocks of a "
           "pair switched on now moved into each other, by up to "
        << overlap
        << " (they do not touch before; its pairs close where they "
           "are)\n";
  }



  template <int dim>
  void
  StageSequence<dim>::restart_contact(const double factor)
  {
    released.clear();
    active_configuration = 0;
    model.contact        = configurations[0].solver.get();
    model.water          = configurations[0].water.get();
    model.contact->restart(
      factor, model.parameters.strength_reduction.reduce_tensile_strength);
  }



  template <int dim>
  void
  StageSequence<dim>::change_nominal_joints(
    const std::function<void(const ContactPair<dim> &, JointLaw &)> &change)
  {
    for (auto &configuration : configurations)
      configuration.solver->change_nominal_joints(change);
  }



  template <int dim>
  void
  StageSequence<dim>::make_water()
  {
    if (!model.parameters.water_pressure.enabled())
      return;
    for (auto &configuration : configurations)
      configuration.water =
        std::make_unique<JointWater<dim>>(model.parameters.water_pressure,
                                          model.parameters.contact,
                                          configuration.solver->pairs(),
                                          model.blocks.size());
    model.water = configurations[0].water.get();
    // The stage with the most pairs (the model finished, unless some
    // stage removes blocks).
    const Configuration &most =
      *std::max_element(configurations.begin(),
                        configurations.end(),
                        [](const Configuration &a, const Configuration &b) {
                          return a.pairs.size() < b.pairs.size();
                        });
    model.pcout << "  water pressure on " << most.water->n_wet_pairs() << " of "
                << most.pairs.size() << " pairs (both faces of the joint)\n";
  }



  template <int dim>
  void
  StageSequence<dim>::adopt(std::unique_ptr<ContactSolver<dim>> solver,
                            const unsigned int                  n_pairs)
  {
    configurations.resize(1);
    configurations[0].present.assign(model.blocks.size(), true);
    for (unsigned int k = 0; k < n_pairs; ++k)
      configurations[0].pairs.push_back(k);
    configurations[0].solver = std::move(solver);
    model.contact            = configurations[0].solver.get();
  }



  template <int dim>
  void
  StageSequence<dim>::set_early_verdict(const bool early)
  {
    for (auto &configuration : configurations)
      configuration.solver->set_early_verdict(early);
  }



  template <int dim>
  std::vector<unsigned int>
  StageSequence<dim>::present_pairs() const
  {
    if (!model.parameters.load_history.changes_model())
      return {};
    return configurations[active_configuration].pairs;
  }



  template <int dim>
  std::pair<std::size_t, std::size_t>
  StageSequence<dim>::columns_on_demand() const
  {
    std::size_t computed = 0, all = 0;
    for (const auto &configuration : configurations)
      if (configuration.solver != nullptr)
        {
          computed += configuration.solver->columns_on_demand().first;
          all += configuration.solver->columns_on_demand().second;
        }
    return {computed, all};
  }



  template class StageSequence<2>;
  template class StageSequence<3>;
} // namespace mbfem

// A stage that adds blocks or switches interfaces on (Load history/Added
// blocks, Interfaces switched on) continues on a ContactSolver built over
// the pairs there from then on: it takes over the committed state of the
// solver before it, and starts its new pairs cast in place
// (doc/dam_safety.md, "Stages that add blocks").

#include <mbfem/contact/contact_solver.h>

#include <deal.II/base/types.h>

namespace mbfem
{



  template <int dim>
  void
  ContactSolver<dim>::continue_from(
    const ContactSolver                            &earlier,
    const std::vector<unsigned int>                &earlier_pair,
    const std::vector<std::unique_ptr<Block<dim>>> &blocks)
  {
    AssertThrow(condensed && earlier.condensed, ExcInternalError());
    AssertDimension(earlier_pair.size(), n_pairs);
    restart(earlier.strength_factor, earlier.reduce_tension);

    const bool has_forces = earlier.committed_solution.size() > 0;
    start_displacement.assign(n_pairs, Tensor<1, dim>());
    if (has_forces)
      committed_solution.reinit(n_pairs * dim + coupling.n_modes());
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const unsigned int j = earlier_pair[k];
        if (j != numbers::invalid_unsigned_int)
          {
            AssertIndexRange(j, earlier.n_pairs);
            committed.state[k]          = earlier.committed.state[j];
            committed.broken[k]         = earlier.committed.broken[j];
            committed.tensile_slip[k]   = earlier.committed.tensile_slip[j];
            committed.slip_direction[k] = earlier.committed.slip_direction[j];
            committed.direction_stiffness[k] =
              earlier.committed.direction_stiffness[j];
            committed_displacement[k]    = earlier.committed_displacement[j];
            contact_pairs[k].initial_gap = earlier.contact_pairs[j].initial_gap;
            if (!earlier.start_displacement.empty())
              start_displacement[k] = earlier.start_displacement[j];
            for (unsigned int d = 0; has_forces && d < dim; ++d)
              committed_solution(k * dim + d) =
                earlier.committed_solution(j * dim + d);
            continue;
          }
        // Cast in place: the relative displacement the sides have now is
        // this pair's reference; its gap is zero and it holds no force.
        const ContactPair<dim> &pair = contact_pairs[k];
        const Tensor<1, dim>    v    = pair.relative_displacement(blocks);
        for (unsigned int d = 0; d < dim; ++d)
          committed_displacement[k][d] = pair.frame[d] * v;
        start_displacement[k]        = committed_displacement[k];
        contact_pairs[k].initial_gap = -committed_displacement[k][0];
        committed.state[k]           = ContactState::stick;
      }
    // The floating amplitudes of the blocks both have; a block added now
    // has not moved.
    for (unsigned int b = 0; has_forces && b < coupling.n_blocks(); ++b)
      if (earlier.coupling.n_modes(b) == coupling.n_modes(b))
        for (unsigned int a = 0; a < coupling.n_modes(b); ++a)
          committed_solution(n_pairs * dim + coupling.offset(b) + a) =
            earlier.committed_solution(earlier.n_pairs * dim +
                                       earlier.coupling.offset(b) + a);
    current              = committed;
    current_displacement = committed_displacement;
    current_solution     = committed_solution;
  }



  template void
  ContactSolver<2>::continue_from(
    const ContactSolver<2> &,
    const std::vector<unsigned int> &,
    const std::vector<std::unique_ptr<Block<2>>> &);
  template void
  ContactSolver<3>::continue_from(
    const ContactSolver<3> &,
    const std::vector<unsigned int> &,
    const std::vector<std::unique_ptr<Block<3>>> &);
} // namespace mbfem

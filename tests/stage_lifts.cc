// A column built in lifts ('Load history/Added blocks'): three blocks
// 1 m x 1 m stacked on a fixed base, nu = 0, unit weight g, modulus E, each
// lift added by its own stage and cast onto the deformed top of the one
// below. With nu = 0 the column is one-dimensional, so the closed form is
// exact in FE_Q(2): a point at height y of the lift starting at y0 has
// settled, since that lift was cast, by the shortening of the column below
// y under the weight added afterwards,
//
//   u(y) = -(g / E) [(H - y0) y0 + H (y - y0) - (y^2 - y0^2) / 2],
//
// against -(g / E) (H y - y^2 / 2) when the whole column is loaded at once
// (the same formula with y0 = 0). The top settles 2.5 g H^2/(9 E) built in
// lifts, against 4.5 g H^2 / (9 E) at once. Both runs are checked at every
// node to 1e-9 of the largest settlement: the fields lie in the finite
// element space, so only round-off is left (measured when written: 1.6e-15).

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "run_model.h"

using namespace dealii;

const std::string column = column_of_three_blocks;

const std::string in_lifts = R"(
subsection Load history
  set Stages       = lift 1: 1, 1; lift 2: 2, 1; lift 3: 3, 2
  set Added blocks = lift 2: 2; lift 3: 3
end
)";

constexpr double H = 3., g = 24e3, E = 20e9;

/** The settlement of height y in the lift from y0 (y0 = 0: all at once). */
double
settlement(const double y, const double y0)
{
  return -(g / E) * ((H - y0) * y0 + H * (y - y0) - (y * y - y0 * y0) / 2.);
}

/** Largest nodal difference from the closed form, and the top settlement. */
std::pair<double, double>
check(const mbfem::MultiBodyProblem<2> &problem, const bool lifts)
{
  double difference = 0., top = 0.;
  for (const auto &block : problem.get_blocks())
    {
      const double y0     = lifts ? block->get_id() - 1. : 0.;
      const auto   points = block->support_points();
      std::vector<types::global_dof_index> dofs(
        block->get_fe().n_dofs_per_cell());
      for (const auto &cell : block->get_dof_handler().active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const unsigned int c =
                block->get_fe().system_to_component_index(i).first;
              const double y     = points[dofs[i]][1];
              const double u     = block->get_solution()(dofs[i]);
              const double exact = (c == 1 ? settlement(y, y0) : 0.);
              difference         = std::max(difference, std::abs(u - exact));
              if (c == 1 && std::abs(y - H) < 1e-12)
                top = u;
            }
        }
    }
  return {difference, top};
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  mbfem::Parameters<2> at_once_parameters, lifts_parameters;
  const auto           at_once = run_model(column, at_once_parameters);
  const auto           lifts   = run_model(column + in_lifts, lifts_parameters);

  const double scale = 4.5 * g * H * H / (9. * E);
  for (const bool in_lifts : {false, true})
    {
      const auto [difference, top] =
        check(in_lifts ? *lifts : *at_once, in_lifts);
      std::printf("%s: top settles %.4f g H^2 / (9 E) (closed form %.1f); "
                  "every node within 1e-9 of the closed form: %s\n",
                  in_lifts ? "built in lifts" : "loaded at once",
                  -top / (g * H * H / (9. * E)),
                  in_lifts ? 2.5 : 4.5,
                  difference < 1e-9 * scale ? "yes" : "NO");
    }

  const auto *contact = lifts->get_contact();
  std::printf("built in lifts: %u pairs at the end, stick/slip/open "
              "%u/%u/%u, largest gap %.1e of the settlement\n",
              static_cast<unsigned int>(contact->pairs().size()),
              contact->count(mbfem::ContactState::stick),
              contact->count(mbfem::ContactState::slip),
              contact->count(mbfem::ContactState::open),
              [&] {
                double gap = 0.;
                for (unsigned int k = 0; k < contact->pairs().size(); ++k)
                  gap = std::max(gap, std::abs(contact->gap(k)));
                return gap < 1e-9 * scale ? 0. : gap / scale;
              }());
}

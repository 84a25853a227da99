// A block removed by a stage ('Load history/Removed blocks'): the column
// of stage_lifts (three blocks 1 m x 1 m on a fixed base, nu = 0, FE_Q(2))
// loaded by its weight at once, then the top block removed in a stage of
// two increments, the forces of its pairs on the block below released
// from full to 0. The joints stay stuck and the blocks elastic, so the
// removal undoes the top block's weight exactly: the two blocks left end
// as a column of height 2 loaded by its own weight,
//
//   u(y) = -(g / E) (2 y - y^2 / 2),
//
// checked at every node to 1e-9 of the largest settlement (exact in
// FE_Q(2); measured when written: 6.9e-15). Half-way, after the first
// increment of the removal (t = 1.5), half of the top block's weight is
// still on the base joint: its normal force is g (1 + 1/2) per unit
// width, read from the pair CSV of that increment.

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "run_model.h"

using namespace dealii;

const std::string column = column_of_three_blocks;

const std::string removal = R"(
subsection Load history
  set Stages         = weight: 1, 1; removal: 2, 2
  set Removed blocks = removal: 3
end
subsection Output
  set Base name = removal
end
)";

constexpr double g = 24e3, E = 20e9;

/**
 * The settlement of height y of the two lower blocks with a fraction
 * @p top of the top block's weight on them.
 */
double
settlement(const double y, const double top)
{
  return -(g / E) * (2. * y - y * y / 2. + top * y);
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  mbfem::Parameters<2> parameters;
  const auto           problem    = run_model(column + removal, parameters);
  double               difference = 0., scale = 0.;
  for (const auto &block : problem->get_blocks())
    {
      if (block->get_id() == 3)
        continue;
      const auto                           points = block->support_points();
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
              const double exact = (c == 1 ? settlement(y, 0.) : 0.);
              difference =
                std::max(difference,
                         std::abs(block->get_solution()(dofs[i]) - exact));
              scale = std::max(scale, std::abs(exact));
            }
        }
    }
  const auto *contact = problem->get_contact();
  std::printf("after the removal: %u pairs, stick/slip/open %u/%u/%u; every "
              "node of the two blocks left within 1e-9 of the closed form: "
              "%s\n",
              static_cast<unsigned int>(contact->pairs().size()),
              contact->count(mbfem::ContactState::stick),
              contact->count(mbfem::ContactState::slip),
              contact->count(mbfem::ContactState::open),
              difference < 1e-9 * scale ? "yes" : "NO");

  // Half-way: the normal force on the base joint (interface 1) at t = 1.5.
  std::ifstream csv("results/removal-pairs-0002.csv");
  std::string   line;
  double        normal = 0.;
  std::getline(csv, line); // "# increment 2, t = 1.5"
  std::getline(csv, line); // the header
  while (std::getline(csv, line))
    {
      std::vector<std::string> field;
      std::stringstream        row(line);
      for (std::string value; std::getline(row, value, ',');)
        field.push_back(value);
      if (field.at(1) == "1")
        normal += std::stod(field.at(4)); // normal_force
    }
  std::printf("half-way (t = 1.5): base joint carries %.6f of g (1 + 1/2)\n",
              normal / (g * 1.5));
}

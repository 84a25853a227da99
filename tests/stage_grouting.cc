// An interface switched on by a stage ('Load history/Interfaces switched
// on'): two blocks 1 m x 2 m side by side on a fixed base, nu = 0.2, a
// contraction joint between them grouted after they have settled under
// their own weight. Stage 'self weight': the blocks stand apart (the joint
// does not exist: they do not touch); stage 'grouting': the joint is
// switched on, its pairs closed and unloaded where the blocks are; stage
// 'push': a pressure of 100 kPa on the outer face of block 1. The joint is
// bonded (c and sigma_t far above the stresses), so after grouting the
// problem is linear and superposition holds exactly:
//
//   staged = (the two blocks apart, under their weight)
//          + (the two blocks joined from the start, under the push alone),
//
// at every node, and the joint's forces are those of the second run alone.
// Checked to 1e-9 of the largest value (round-off; measured when written:
// 1.7e-15 for the displacements, 1.2e-14 for the forces).

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "run_model.h"

using namespace dealii;

const std::string model = R"(
set Dimension = 2
set Test mode = true
subsection Mesh
  set Generator arguments = 4,4 : 0,0 : 2,2 : true
  set Block id function   = 1 + (x > 1)
end
subsection Finite element
  set Polynomial degree = 2
end
subsection Material
  set Young's modulus = 20e9
  set Poisson's ratio = 0.2
end
subsection Boundary conditions
  set Prescribed displacement boundary ids = 2: xy
  set Traction boundary ids                = 0
end
subsection Output
  set Write VTU = false
  set Directory = results
end
)";

const std::string joint = R"(
subsection Contact
  set Interfaces           = blocks 1:2
  set Friction coefficient = 1
  set Cohesion             = 1e9
  set Tensile strength     = 1e9
end
)";

const std::string staged = R"(
subsection Material
  set Unit weight = 24e3
end
subsection Boundary conditions
  subsection Traction
    set Function expression = 1e5 * max(t - 2, 0); 0
  end
end
subsection Load history
  set Stages                 = self weight: 1, 2; grouting: 2, 1; push: 3, 2
  set Interfaces switched on = grouting: 1
end
)";

const std::string push_alone = R"(
subsection Material
  set Unit weight = 0
end
subsection Boundary conditions
  subsection Traction
    set Function expression = 1e5 * t; 0
  end
end
)";

const std::string weight_alone = R"(
subsection Material
  set Unit weight = 24e3
end
subsection Boundary conditions
  subsection Traction
    set Function expression = 0; 0
  end
end
)";

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  mbfem::Parameters<2> p_staged, p_push, p_weight;
  const auto           a = run_model(model + joint + staged, p_staged);
  const auto           b = run_model(model + joint + push_alone, p_push);
  const auto           c = run_model(model + weight_alone, p_weight);

  double u_difference = 0., u_max = 0.;
  for (unsigned int i = 0; i < a->get_blocks().size(); ++i)
    {
      const auto &u_a = a->get_blocks()[i]->get_solution();
      const auto &u_b = b->get_blocks()[i]->get_solution();
      const auto &u_c = c->get_blocks()[i]->get_solution();
      for (unsigned int j = 0; j < u_a.size(); ++j)
        {
          u_difference =
            std::max(u_difference, std::abs(u_a(j) - u_b(j) - u_c(j)));
          u_max = std::max(u_max, std::abs(u_a(j)));
        }
    }
  const auto *joint_a      = a->get_contact();
  const auto *joint_b      = b->get_contact();
  double      r_difference = 0., r_max = 0.;
  for (unsigned int k = 0; k < joint_a->pairs().size(); ++k)
    {
      r_difference =
        std::max(r_difference, (joint_a->force(k) - joint_b->force(k)).norm());
      r_max = std::max(r_max, joint_b->force(k).norm());
    }

  std::printf("staged: %u pairs, stick/slip/open %u/%u/%u\n",
              static_cast<unsigned int>(joint_a->pairs().size()),
              joint_a->count(mbfem::ContactState::stick),
              joint_a->count(mbfem::ContactState::slip),
              joint_a->count(mbfem::ContactState::open));
  std::printf("displacement at every node = apart under the weight + joined "
              "under the push, to 1e-9: %s\n",
              u_difference < 1e-9 * u_max ? "yes" : "NO");
  std::printf("joint forces = those of the push alone, to 1e-9: %s\n",
              r_difference < 1e-9 * r_max ? "yes" : "NO");
}

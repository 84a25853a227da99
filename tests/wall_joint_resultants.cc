// Walls of blocks on a clamped base block under gravity (unit weight 1)
// and a lateral traction q = 0.05 on the left face of the wall, with
// 'Contact/Interfaces = all': in 2D and 3D, aligned (X-junctions; in 3D
// edges of four blocks and corners of eight) and in running bond
// (T-junctions). Every horizontal joint must carry exactly what is above
// it: the weight W = (volume above) and the lateral load H = q (area of
// the left face above), whatever the states and wherever the points shared
// by three or more blocks are, since the pairs there (doc/jointed_rock.md)
// put all the force they transfer on the blocks. The resultant of the
// pairs on each joint (pairs at the joint's height with a vertical normal,
// force on the upper block) is compared with (-H, W) to 1e-9 relative,
// in both contact formulations.

#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/parameters.h>

#include <deal.II/base/mpi.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace dealii;

template <int dim>
std::unique_ptr<mbfem::MultiBodyProblem<dim>>
run(const std::string &text, mbfem::Parameters<dim> &parameters)
{
  ParameterHandler prm;
  mbfem::Parameters<dim>::declare_parameters(prm);
  prm.parse_input_from_string(text);
  parameters.parse_parameters(prm, SOURCE_DIR "/../parameters");
  static ConditionalOStream quiet(std::cout, false);
  auto                      problem =
    std::make_unique<mbfem::MultiBodyProblem<dim>>(parameters, quiet);
  problem->run();
  return problem;
}

// The wall's parameter file from parameters/, with the formulation set.
std::string
input(const std::string &name, const std::string &formulation)
{
  std::ifstream     in(SOURCE_DIR "/../parameters/" + name + ".prm");
  std::stringstream text;
  text << in.rdbuf();
  return text.str() +
         "\nset Test mode = true\nsubsection Contact\n  set "
         "Formulation = " +
         formulation +
         "\nend\nsubsection Output\n  set Write VTU = false\n"
         "  set Directory = results\nend\n";
}

// Joints every 0.5 from z = 0.5 (2D: y) up to the top of the wall, which
// is @p width wide and @p depth deep (1 in 2D).
template <int dim>
void
check(const std::string &name,
      const std::string &formulation,
      const double       width,
      const double       depth,
      const double       top)
{
  mbfem::Parameters<dim> parameters;
  const auto   problem  = run<dim>(input(name, formulation), parameters);
  const auto  *contact  = problem->get_contact();
  double       worst    = 0.;
  unsigned int n_joints = 0;
  for (double level = 0.5; level < top - 1e-9; level += 0.5, ++n_joints)
    {
      Tensor<1, dim> resultant, expected;
      expected[dim - 1] = width * depth * (top - level);
      expected[0]       = -0.05 * depth * (top - level);
      for (unsigned int k = 0; k < contact->pairs().size(); ++k)
        {
          const auto &pair = contact->pairs()[k];
          if (std::abs(pair.midpoint()[dim - 1] - level) < 1e-9 &&
              std::abs(std::abs(pair.frame[0][dim - 1]) - 1.) < 1e-9)
            resultant += contact->force(k);
        }
      worst = std::max(worst, (resultant - expected).norm() / expected.norm());
    }
  std::cout << name << ", " << formulation << ": "
            << problem->get_blocks().size() << " blocks, "
            << contact->pairs().size() << " pairs, stick/slip/open "
            << contact->count(mbfem::ContactState::stick) << "/"
            << contact->count(mbfem::ContactState::slip) << "/"
            << contact->count(mbfem::ContactState::open) << "; " << n_joints
            << " horizontal joints carry the weight and lateral load above "
               "them to 1e-9: "
            << (worst < 1e-9 ? "yes" : "NO") << std::endl;
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string formulation : {"condensed", "monolithic"})
    {
      check<2>("wall_aligned_2d", formulation, 4., 1., 2.5);
      check<2>("wall_running_bond_2d", formulation, 4., 1., 2.5);
      check<3>("wall_aligned_3d", formulation, 2., 2., 1.5);
      check<3>("wall_running_bond_3d", formulation, 3., 1., 2.);
    }
}

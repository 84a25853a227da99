// The statics certificate on a whole model that is in equilibrium: a
// 2 x 1 block on a 2 x 1 base, under a weight tilted by 24.2 degrees (an
// incline without a rotated mesh: body force 25e3 (-sin, -cos)), friction
// mu = tan(24.2 deg) / 0.95, i.e. at 0.95 of the rigid-block limit. The
// increment converges (the run is silent here), and ContactSolver::certify()
// on its data must say "admissible" with the strength factor 1/0.95 =
// 1.052632 (the rigid-block limit of a block sliding on one plane; the
// bisection stops at 1e-7 of it, so five decimals are stable).

#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/parameters.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <cstdio>
#include <fstream>
#include <iostream>

int
main(int argc, char *argv[])
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  {
    std::ofstream prm("certificate_admissible.prm");
    prm << "set Dimension = 2\n"
           "set Test mode = true\n"
           "subsection Mesh\n"
           "  set Generator name      = subdivided_hyper_rectangle\n"
           "  set Generator arguments = 4,4 : 0,0 : 2,2 : true\n"
           "  set Block id function   = (y > 1)\n"
           "end\n"
           "subsection Finite element\n"
           "  set Polynomial degree = 2\n"
           "end\n"
           "subsection Material\n"
           "  set Young's modulus = 2e7\n"
           "  set Poisson's ratio = 0.2\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  set Prescribed displacement boundary ids = 2: xy\n"
           "  subsection Body force\n"
           "    set Function constants  = g=25e3, theta=0.42236968\n"
           "    set Function expression = -g*sin(theta); -g*cos(theta)\n"
           "  end\n"
           "end\n"
           "subsection Contact\n"
           "  set Interfaces           = blocks 0:1\n"
           "  set Friction coefficient = 0.473071\n"
           "end\n"
           "subsection Output\n"
           "  set Write VTU = false\n"
           "  set Directory = certificate_admissible_results\n"
           "end\n";
  }
  mbfem::Parameters<2> parameters;
  mbfem::read_parameters("certificate_admissible.prm", parameters);
  ConditionalOStream         silent(std::cout, false);
  mbfem::MultiBodyProblem<2> problem(parameters, silent);
  problem.run();

  const auto result = problem.get_contact()->certify();
  std::printf("candidate pairs: %u\n", result.n_candidates);
  std::printf("verdict: %s\n",
              result.verdict ==
                  mbfem::StaticAdmissibility<2>::Verdict::admissible ?
                "admissible" :
                "not admissible");
  std::printf("strength factor: %.5f (rigid block: 1/0.95 = %.5f)\n",
              result.strength_factor,
              1. / 0.95);
  std::printf("admissible forces balance the block: %s\n",
              result.forces.empty() ? "no" : "yes");
  return 0;
}

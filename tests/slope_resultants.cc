// The rock slope of parameters/jointed_slope.prm at H = 6 m, W = 4 m
// (meshes/jointed_slope_small.msh: 21 blocks cut by the two joint sets, on
// the fixed base block that also backs the slope), condensed formulation:
// the blocks' area is W H + H^2 / (2 tan psi), the base carries their
// weight, every block is in equilibrium (jointed_checks.h), to 1e-9. (The
// monolithic formulation, which has the fast state iteration only, cycles
// at increment 3: open <-> stick at one pair on the back wall; the load
// path of the condensed one concludes it. doc/state_iteration.md.)
// `slope_resultants FILE.prm` checks FILE instead.

#include "jointed_checks.h"

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Under mpirun (NAME.mpirun=2.output) rank 0 prints, as mbfem does.
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.rdbuf(nullptr);
  if (argc > 1)
    return run_file(argc, argv);
  const std::string parameters = SOURCE_DIR "/../parameters";
  const double      H = 6., W = 4., psi = 50. * M_PI / 180.;
  check<2>({"jointed slope, H = 6, W = 4",
            read(parameters + "/jointed_slope.prm") +
              "\nsubsection Mesh\n  set Mesh file = " SOURCE_DIR
              "/../meshes/jointed_slope_small.msh\nend\n",
            parameters,
            25e3,
            0.},
           W * H + H * H / (2. * std::tan(psi)));
}

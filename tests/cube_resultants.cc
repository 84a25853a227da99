// The cube of parameters/cube_5x5x5.prm at 3 x 3 x 3 blocks on its base
// block: under gravity alone (one increment, t = 1) each of the three
// levels of horizontal joints carries the weight above it; with the push
// (t = 2, traction 0.1 in +x on the side x = 0) each carries the weight and
// the push above it, the base the whole of both (-0.9 in x, 27 in z); every
// block is in equilibrium (jointed_checks.h), to 1e-9.
// `cube_resultants FILE.prm [PUSH]` checks FILE instead.

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
  const std::string cube =
    read(parameters + "/cube_5x5x5.prm") +
    "\nsubsection Mesh\n  set Generator arguments = 3,3,4 : 0,0,0 : 3,3,4 : "
    "true\n  set Block id function = (z > 1) * (1 + floor(x) + 3*floor(y) + "
    "9*floor(z - 1))\nend\n";
  check<3>({"cube 3 x 3 x 3, gravity",
            cube + "subsection Load history\n  set End time = 1\n  set "
                   "Number of increments = 1\nend\n",
            parameters,
            1.,
            0.,
            true},
           27.);
  check<3>(
    {"cube 3 x 3 x 3, gravity and push", cube, parameters, 1., 0.1, true}, 27.);
}

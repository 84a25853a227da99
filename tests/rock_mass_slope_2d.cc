// Issue 61: the rock slope of parameters/jointed_slope_sets.prm (the slope
// of jointed_slope.prm described by its two joint sets, Mesh/Source = rock
// mass) at H = 6 m, W = 4 m, against the hand-written .geo's blocks of the
// same slope (meshes/jointed_slope_small.msh), both through one load
// history (gravity in 5 increments):
//  - the same number of blocks and of pairs (every joint segment two cells
//    in both meshes), each block of the generated slope with the area of
//    one of the .geo's to 1e-9 (sorted areas compared; the base excluded,
//    it is meshed differently but has the same outline);
//  - the generated blocks' area W H + H^2 / (2 tan psi), the base carrying
//    their weight, every block in equilibrium, to 1e-9 (jointed_checks.h).
// The states differ between the two: the cells of the base differ.

#include <mbfem/mesh/mesh.h>

#include <algorithm>

#include "jointed_checks.h"

namespace
{
  /**
   * The areas of the blocks (material ids) of @p file but block 1, read as
   * mbfem reads it (the rock mass's joints are physical groups of interior
   * curves, which deal.II's GridIn alone refuses).
   */
  std::vector<double>
  block_areas(const std::string &file)
  {
    Triangulation<2>      mesh;
    mbfem::MeshParameters parameters;
    parameters.source    = "gmsh";
    parameters.mesh_file = file;
    mbfem::create_mesh(parameters, mesh);
    std::map<types::material_id, double> area;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->material_id() != 1)
        area[cell->material_id()] += cell->measure();
    std::vector<double> result;
    for (const auto &[id, a] : area)
      result.push_back(a);
    std::sort(result.begin(), result.end());
    return result;
  }
} // namespace



int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                parameters = SOURCE_DIR "/../parameters";
  const double                     H = 6., W = 4., psi = 50. * M_PI / 180.;
  const std::string                small =
    "\nsubsection Mesh\n  subsection Rock mass\n    set Slope height = 6\n"
    "    set Crest width = 4\n  end\nend\n"
    "subsection Output\n  set Directory = results\n"
    "  set Base name = rock_mass_slope_2d\n  set Write VTU = false\nend\n";
  check<2>({"slope by its joint sets, H = 6, W = 4",
            read(parameters + "/jointed_slope_sets.prm") + small,
            parameters,
            25e3,
            0.},
           W * H + H * H / (2. * std::tan(psi)));
  check<2>({"slope of meshes/jointed_slope_small.msh",
            read(parameters + "/jointed_slope.prm") +
              "\nsubsection Mesh\n  set Mesh file = " SOURCE_DIR
              "/../meshes/jointed_slope_small.msh\nend\n"
              "subsection Output\n  set Directory = results\n"
              "  set Base name = rock_mass_slope_2d_geo\n"
              "  set Write VTU = false\nend\n",
            parameters,
            25e3,
            0.});

  const auto generated =
               block_areas("results/rock_mass_slope_2d-rock-mass.msh"),
             geo = block_areas(SOURCE_DIR "/../meshes/jointed_slope_small.msh");
  bool same      = generated.size() == geo.size();
  for (unsigned int b = 0; same && b < geo.size(); ++b)
    same = std::abs(generated[b] - geo[b]) < 1e-9 * geo.back();
  std::cout << generated.size() << " and " << geo.size()
            << " blocks on the base, the smallest " << generated.front()
            << " and " << geo.front()
            << "; every block's area the same to 1e-9: "
            << (same ? "yes" : "NO") << std::endl;
}

// Issue 61: parameters/rock_mass_box.prm, a 3 x 3 x 3 box cut by three
// orthogonal persistent joint sets spaced 1 (Mesh/Source = rock mass),
// under its own weight on a fixed base with rollers on the sides. Checks:
//  - 27 blocks (3 x 3 x 3 cuts), their volumes summing to the box's 27
//    within 1e-10 (the fragments cover the box, no sliver is lost);
//  - every pair belongs to the set whose planes it lies in: its normal is
//    the set's (to 1e-9) and its friction the set's (0.6 bedding, 0.7
//    east, 0.8 north; the default 0.5 for none), the pairs counted by set;
//  - each of the two levels of bedding joints (z = 1, 2) carries the weight
//    of the blocks above it, 9 and 18 blocks of 25e3 per unit volume, to
//    1e-9 (the side rollers carry no vertical force: nothing else can);
//  - every block above the base layer is in vertical equilibrium to 1e-9
//    (the side rollers push horizontally only), and in full those that
//    touch no side (the middle column of the 3 x 3 x 3 box).
// Weights are (unit weight) x (volume of the block's mesh), exact for
// straight-sided cells; the forces come from the state iteration.
// `rock_mass_box FILE.prm` checks FILE instead, an n x n x n box of unit
// blocks with the same sets (parameters/rock_mass_1000.prm: n = 10).

#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

using namespace dealii;

namespace
{
  const char *
  yes(const bool ok)
  {
    return ok ? "yes" : "NO";
  }

  std::string
  read(const std::string &path)
  {
    std::ifstream     in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /** The weight and the centre of every block. */
  struct Blocks
  {
    std::vector<double>   weight;
    std::vector<Point<3>> centre;
    double                volume = 0.;
  };

  Blocks
  measure(const std::vector<std::unique_ptr<mbfem::Block<3>>> &blocks,
          const double                                         gamma)
  {
    Blocks result;
    for (const auto &block : blocks)
      {
        const auto  &mesh   = block->get_triangulation();
        const double volume = GridTools::volume(mesh);
        result.weight.push_back(gamma * volume);
        result.volume += volume;
        Point<3> c;
        for (const auto &v : mesh.get_vertices())
          c += v / double(mesh.n_vertices());
        result.centre.push_back(c);
      }
    return result;
  }
} // namespace



/** Runs the box of @p text and prints the checks. */
void
check_box(const std::string &text, const std::string &folder)
{
  ParameterHandler prm;
  mbfem::Parameters<3>::declare_parameters(prm);
  prm.parse_input_from_string(text +
                              "\nset Test mode = true\nsubsection Output\n"
                              "  set Write VTU = false\nend\n");
  mbfem::Parameters<3> parameters;
  parameters.parse_parameters(prm, folder);
  ConditionalOStream         quiet(std::cout, false);
  mbfem::MultiBodyProblem<3> problem(parameters, quiet);
  problem.run();

  const auto  &blocks  = problem.get_blocks();
  const auto  *contact = problem.get_contact();
  const auto  &pairs   = contact->pairs();
  const Blocks m       = measure(blocks, 25e3);
  // the box's side, in blocks of 1
  const double       n       = parameters.mesh.rock_mass.size[0];
  const unsigned int n_cubed = std::lround(n * n * n);
  std::cout << blocks.size() << " blocks (" << n_cubed
            << " expected): " << yes(blocks.size() == n_cubed) << "\n"
            << "their volumes sum to the box's " << n_cubed << " within 1e-10: "
            << yes(std::abs(m.volume - n_cubed) < 1e-10 * n_cubed) << "\n";

  // Pairs by set (normal and friction), the bedding levels, each block's
  // sum of forces.
  const std::map<double, unsigned int> axis_of = {{0.6, 2}, {0.7, 0}, {0.8, 1}};
  std::map<double, unsigned int>       count;
  bool                                 tagged = true;
  std::map<long, double>    level; // z in 1e-6 -> upward force carried
  std::vector<Tensor<1, 3>> sum(blocks.size());
  std::vector<double>       scale(m.weight);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    {
      const unsigned int a = pairs[k].a.block, b = pairs[k].b.block;
      const double       mu   = pairs[k].joint.friction_coefficient;
      const auto         axis = axis_of.find(mu);
      tagged                  = tagged && axis != axis_of.end() &&
               std::abs(std::abs(pairs[k].frame[0][axis->second]) - 1.) < 1e-9;
      ++count[mu];
      const Tensor<1, 3> f = contact->force(k); // on side b
      sum[b] += f;
      sum[a] -= f;
      scale[a] = std::max(scale[a], f.norm());
      scale[b] = std::max(scale[b], f.norm());
      if (mu == 0.6)
        level[std::lround(pairs[k].midpoint()[2] * 1e6)] +=
          (m.centre[b][2] > m.centre[a][2] ? 1. : -1.) * f[2];
    }
  std::cout << pairs.size() << " pairs: bedding " << count[0.6] << ", east "
            << count[0.7] << ", north " << count[0.8]
            << "; each with its set's normal and friction: " << yes(tagged)
            << "\n";

  double worst_level = 0.;
  for (const auto &[height, force] : level)
    {
      double above = 0.;
      for (unsigned int b = 0; b < blocks.size(); ++b)
        if (m.centre[b][2] > height * 1e-6)
          above += m.weight[b];
      worst_level = std::max(worst_level, std::abs(force - above) / above);
    }
  std::cout << level.size()
            << " levels of bedding joints carry the weight above them to "
               "1e-9: "
            << yes(level.size() == n - 1 && worst_level < 1e-9) << "\n";

  // Above the base layer: the vertical balance of every block (the side
  // rollers push horizontally only), and all of it for the blocks that
  // touch no side (the middle column of the 3 x 3 x 3 box).
  double worst_vertical = 0., worst_inner = 0.;
  for (unsigned int b = 0; b < blocks.size(); ++b)
    if (m.centre[b][2] > 1.)
      {
        Tensor<1, 3> total = sum[b];
        total[2] -= m.weight[b];
        worst_vertical =
          std::max(worst_vertical, std::abs(total[2]) / scale[b]);
        if (std::abs(m.centre[b][0] - n / 2.) < n / 2. - 1. &&
            std::abs(m.centre[b][1] - n / 2.) < n / 2. - 1.)
          worst_inner = std::max(worst_inner, total.norm() / scale[b]);
      }
  std::cout << "every block above the base layer in vertical equilibrium to "
               "1e-9: "
            << yes(worst_vertical < 1e-9) << "\n"
            << "the upper blocks that touch no side in equilibrium to 1e-9: "
            << yes(worst_inner < 1e-9) << "\n";
}



int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                file = argc > 1 ? std::string(argv[1]) :
                                                     SOURCE_DIR
                             "/../parameters/rock_mass_box.prm";
  const std::string folder = file.substr(0, file.find_last_of('/') + 1);
  check_box(read(file), folder);
  if (argc > 1)
    return 0;
  // The same box meshed 'structured': one FE_Q(2) hexahedron per block.
  std::cout << "Block meshes = structured, FE_Q(2):\n";
  check_box(read(file) +
              "\nsubsection Mesh\n  subsection Rock mass\n    set Block "
              "meshes = structured\n  end\nend\nsubsection Finite "
              "element\n  set Polynomial degree = 2\nend\n",
            folder);
}

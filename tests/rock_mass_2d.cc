// Issue 61 in 2D: a 20 x 10 rectangle cut by two oblique joint sets (dip 60
// towards +x spaced 4, dip 30 towards -x spaced 3; Mesh/Source = rock
// mass), under its own weight on a fixed base with rollers on the sides.
// Checks, whatever the states of the pairs:
//  - the blocks' areas sum to the rectangle's 200 within 1e-10 (the
//    fragments cover it, the corner slivers included);
//  - every pair lies in a plane of its set (its normal the set's to 1e-9;
//    a pair tied on the base has the global axes as its frame) and has
//    its set's friction (0.8, 0.9), none the default;
//  - every block that touches neither the base nor a side is in
//    equilibrium to 1e-9: its weight and the forces of its pairs.

#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <iostream>
#include <map>

using namespace dealii;

namespace
{
  const char *
  yes(const bool ok)
  {
    return ok ? "yes" : "NO";
  }

  const std::string model = R"(
set Dimension = 2
set Test mode = true
subsection Mesh
  set Source = rock mass
  subsection Rock mass
    set Origin    = 0, 0
    set Size      = 20, 10
    set Mesh size = 1
  end
end
subsection Material
  set Young's modulus = 10e9
  set Poisson's ratio = 0.25
  set Unit weight     = 25e3
end
subsection Boundary conditions
  set Prescribed displacement boundary ids = 1: xy, 3: x, 4: x
end
subsection Contact
  set Interfaces = all
  set Joint sets = a: dip 60, dip direction 90, spacing 4, friction 0.8; b: dip 30, dip direction 270, spacing 3, friction 0.9
end
subsection Output
  set Directory = results
  set Base name = rock_mass_2d
  set Write VTU = false
end
)";

  /** Whether block @p b touches the base or a side of the rectangle. */
  bool
  on_boundary(const mbfem::Block<2> &block)
  {
    for (const auto &face : block.get_triangulation().active_face_iterators())
      if (face->at_boundary() && face->boundary_id() >= 1 &&
          face->boundary_id() <= 4)
        return true;
    return false;
  }
} // namespace



int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler                 prm;
  mbfem::Parameters<2>::declare_parameters(prm);
  prm.parse_input_from_string(model);
  mbfem::Parameters<2> parameters;
  parameters.parse_parameters(prm, ".");
  ConditionalOStream         quiet(std::cout, false);
  mbfem::MultiBodyProblem<2> problem(parameters, quiet);
  problem.run();

  const auto         &blocks  = problem.get_blocks();
  const auto         *contact = problem.get_contact();
  const auto         &pairs   = contact->pairs();
  double              area    = 0.;
  std::vector<double> weight;
  for (const auto &block : blocks)
    {
      weight.push_back(25e3 * GridTools::volume(block->get_triangulation()));
      area += GridTools::volume(block->get_triangulation());
    }
  std::cout << blocks.size() << " blocks; their areas sum to 200 within "
            << "1e-10: " << yes(std::abs(area - 200.) < 1e-10 * 200.) << "\n";

  const double                         pi     = numbers::PI;
  const std::map<double, Tensor<1, 2>> normal = {
    {0.8, Tensor<1, 2>({std::sin(pi / 3.), std::cos(pi / 3.)})},
    {0.9, Tensor<1, 2>({-std::sin(pi / 6.), std::cos(pi / 6.)})}};
  std::map<double, unsigned int> count;
  bool                           tagged = true;
  unsigned int                   n_tied = 0;
  std::vector<Tensor<1, 2>>      sum(blocks.size());
  std::vector<double>            scale(weight);
  for (unsigned int k = 0; k < pairs.size(); ++k)
    {
      const double mu = pairs[k].joint.friction_coefficient;
      const auto   n  = normal.find(mu);
      // (A tied pair, both nodes on a support, has the global axes as
      // its frame: its law is checked, not its normal.)
      tagged = tagged && n != normal.end() &&
               (pairs[k].tied ||
                std::abs(std::abs(pairs[k].frame[0] * n->second) - 1.) < 1e-9);
      n_tied += pairs[k].tied;
      ++count[mu];
      const unsigned int a = pairs[k].a.block, b = pairs[k].b.block;
      const Tensor<1, 2> f = contact->force(k);
      sum[b] += f;
      sum[a] -= f;
      scale[a] = std::max(scale[a], f.norm());
      scale[b] = std::max(scale[b], f.norm());
    }
  std::cout << pairs.size() << " pairs: set a " << count[0.8] << ", set b "
            << count[0.9] << " (" << n_tied << " tied on the base)"
            << "; each in a plane of its set, with its law: " << yes(tagged)
            << "\n";

  double       worst = 0.;
  unsigned int inner = 0;
  for (unsigned int b = 0; b < blocks.size(); ++b)
    if (!on_boundary(*blocks[b]))
      {
        Tensor<1, 2> total = sum[b];
        total[1] -= weight[b];
        worst = std::max(worst, total.norm() / scale[b]);
        ++inner;
      }
  std::cout << inner << " blocks touch neither the base nor a side; each in "
            << "equilibrium to 1e-9: " << yes(inner > 0 && worst < 1e-9)
            << "\n";
}

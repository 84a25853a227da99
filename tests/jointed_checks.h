// Checks shared by tests/slope_resultants.cc and tests/cube_resultants.cc
// (the jointed rock models of issue 13, doc/jointed_rock.md). After a run,
// to 1e-9 relative, whatever the states of the pairs:
//  - the blocks' volumes add up to the expected one (the mesh covers the
//    model, and the weight below is the right one);
//  - the pairs on the base (side a the base block, the lowest material id)
//    transmit the weight of all the other blocks and the push: (-P, W) on
//    the blocks above;
//  - every block is in equilibrium: its weight, its push and the forces of
//    all its pairs sum to zero (relative to the largest of them);
//  - where every horizontal joint spans the model (the cube), every level
//    of horizontal joints (pairs with a vertical normal at one height)
//    carries the weight and push of the blocks above it.
// Weights are (unit weight) x volume from the blocks' meshes: the load is
// assembled by a quadrature exact for these straight-sided cells, so the
// equalities hold to round-off. The contact forces come from the state
// iteration, so a lost or doubled force (a pair at a point shared by three
// or more blocks, say) fails the checks.
//
// `run_file` runs a parameter file given on the command line, e.g.
// `slope_resultants parameters/jointed_slope.prm` or `cube_resultants
// parameters/cube_5x5x5.prm 0.1` (the traction in +x on boundary 0 at the
// last increment), and prints the same checks for it.

#ifndef mbfem_tests_jointed_checks_h
#define mbfem_tests_jointed_checks_h

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
  inline std::string
  read(const std::string &path)
  {
    std::ifstream in(path);
    AssertThrow(in.good(), ExcMessage("Cannot read <" + path + ">."));
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  // What the checks need of a model: its unit weight, the traction in +x
  // on boundary 0 of the blocks other than the base at the end of the run.
  struct Model
  {
    std::string name;
    std::string text;
    std::string folder;
    double      unit_weight = 1.;
    double      push        = 0.;
    // Whether every horizontal joint spans the model (a wall, a cube; not
    // the slope, whose back leans on the base and passes weight to it by
    // friction)
    bool levels = false;
  };

  template <int dim>
  struct Loads
  {
    std::vector<Tensor<1, dim>> load;   // weight and push of each block
    std::vector<Point<dim>>     centre; // of each block's vertices
    double                      volume = 0.;
  };

  template <int dim>
  Loads<dim>
  block_loads(const std::vector<std::unique_ptr<mbfem::Block<dim>>> &blocks,
              const Model                                           &model)
  {
    Loads<dim> loads;
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        const auto    &mesh   = blocks[b]->get_triangulation();
        const double   volume = GridTools::volume(mesh);
        Tensor<1, dim> load;
        load[dim - 1] = -model.unit_weight * volume;
        for (const auto &face : mesh.active_face_iterators())
          if (face->at_boundary() && face->boundary_id() == 0 && b > 0)
            load[0] += model.push * face->measure();
        loads.load.push_back(load);
        Point<dim> centre;
        for (const auto &v : mesh.get_vertices())
          centre += v / double(mesh.n_vertices());
        loads.centre.push_back(centre);
        if (b > 0)
          loads.volume += volume;
      }
    return loads;
  }

  inline const char *
  yes(const bool ok)
  {
    return ok ? "yes" : "NO";
  }
} // namespace



// Block 0 is the base (the lowest material id). Prints the checks.
template <int dim>
inline void
check(const Model &model, const double expected_volume = 0.)
{
  ParameterHandler prm;
  mbfem::Parameters<dim>::declare_parameters(prm);
  prm.parse_input_from_string(
    model.text + "\nset Test mode = true\nsubsection Output\n  set Write "
                 "VTU = false\n  set Directory = results\nend\n");
  mbfem::Parameters<dim> parameters;
  parameters.parse_parameters(prm, model.folder);
  static ConditionalOStream    quiet(std::cout, false);
  mbfem::MultiBodyProblem<dim> problem(parameters, quiet);
  problem.run();

  const auto &blocks  = problem.get_blocks();
  const auto *contact = problem.get_contact();
  const auto &pairs   = contact->pairs();
  const auto  loads   = block_loads(blocks, model);

  // Base: force on the blocks above it against all the load they carry.
  Tensor<1, dim> base, carried;
  for (unsigned int b = 1; b < blocks.size(); ++b)
    carried -= loads.load[b];
  // Each block: its load plus the forces of its pairs.
  std::vector<Tensor<1, dim>>    sum(loads.load);
  std::vector<double>            scale(blocks.size());
  std::map<long, Tensor<1, dim>> levels; // height in 1e-6 -> resultant
  for (unsigned int k = 0; k < pairs.size(); ++k)
    {
      const Tensor<1, dim> f = contact->force(k);
      if (pairs[k].a.block == 0)
        base += f;
      sum[pairs[k].b.block] += f;
      sum[pairs[k].a.block] -= f;
      scale[pairs[k].b.block] = std::max(scale[pairs[k].b.block], f.norm());
      scale[pairs[k].a.block] = std::max(scale[pairs[k].a.block], f.norm());
      if (std::abs(std::abs(pairs[k].frame[0][dim - 1]) - 1.) < 1e-9)
        levels[std::lround(pairs[k].midpoint()[dim - 1] * 1e6)] += f;
    }
  double worst_block = 0.;
  for (unsigned int b = 1; b < blocks.size(); ++b)
    worst_block =
      std::max(worst_block,
               sum[b].norm() / std::max(scale[b], loads.load[b].norm()));
  // Each level carries the load of the blocks above it.
  double worst_level = 0.;
  for (const auto &[height, resultant] : levels)
    {
      Tensor<1, dim> above;
      for (unsigned int b = 1; b < blocks.size(); ++b)
        if (loads.centre[b][dim - 1] > height * 1e-6)
          above -= loads.load[b];
      worst_level =
        std::max(worst_level, (resultant - above).norm() / above.norm());
    }

  std::cout << model.name << ", " << mbfem::to_string(contact->formulation())
            << ": " << blocks.size() << " blocks, " << pairs.size()
            << " pairs, stick/slip/open "
            << contact->count(mbfem::ContactState::stick) << "/"
            << contact->count(mbfem::ContactState::slip) << "/"
            << contact->count(mbfem::ContactState::open) << std::endl;
  if (expected_volume > 0.)
    std::cout
      << "  volume of the blocks other than the base as expected to 1e-9: "
      << yes(std::abs(loads.volume - expected_volume) < 1e-9 * expected_volume)
      << std::endl;
  std::cout << "  the base carries the weight"
            << (model.push != 0. ? " and the push" : "")
            << " of the blocks above it to 1e-9: "
            << yes((base - carried).norm() < 1e-9 * carried.norm())
            << "\n  every block in equilibrium to 1e-9: "
            << yes(worst_block < 1e-9) << std::endl;
  if (model.levels)
    std::cout << "  " << levels.size()
              << " level(s) of horizontal joints carry the load above them "
                 "to 1e-9: "
              << yes(worst_level < 1e-9) << std::endl;
}


// Runs the file named by argv[1] (push argv[2], default 0): the full-size
// models, too long for the test suite. 'Dimension = 3' and 'Unit weight'
// are read from the file's own text (not from files it includes).
inline int
run_file(int argc, char *argv[])
{
  Model model{argv[1], read(argv[1]), ".", 1., 0.};
  model.folder = model.name.substr(0, model.name.find_last_of('/') + 1);
  if (argc > 2)
    model.push = std::stod(argv[2]);
  // the unit weight of the file, or 1
  const auto at = model.text.find("Unit weight");
  if (at != std::string::npos)
    model.unit_weight =
      std::stod(model.text.substr(model.text.find('=', at) + 1));
  if (model.text.find("Dimension = 3") != std::string::npos)
    {
      model.levels = true;
      check<3>(model);
    }
  else
    check<2>(model);
  return 0;
}

#endif

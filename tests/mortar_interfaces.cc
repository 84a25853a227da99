// Mortar interfaces (issue 31, include/mbfem/interface/mortar.h):
//  1. The contact patch test with non-matching meshes: the blocks of
//     parameters/mortar_patch_2d.prm and _3d.prm (4 against 5 elements
//     along the common face, different moduli, nu = 0, 1 MPa on top) with
//     the degrees of the two blocks varied. Both blocks are in uniform
//     uniaxial stress, so every pair must carry exactly 1 MPa and no shear;
//     node-to-node pairs would not (their nodes do not face each other).
//     Checked to 1e-8 of the pressure (measured: 2e-11, round-off), with
//     the multipliers on the coarser side (the default) and on the finer.
//  2. The weights reproduce every field that both sides represent: for a
//     polynomial of the lower of the two degrees, sum_k w_k f(x_k) = f(x_j)
//     at every pair, to 1e-10 (exact integration over the overlaps).
//  2b. The same where the multiplier side is covered only in part: a short
//     block on a longer, coarser base (meshes/mortar_partial_2d.geo), whose
//     end faces face the block over part of their length only. The dual
//     basis there is that of the covered part (Popp et al. 2013), so that
//     the weights still reproduce linear fields to 1e-10; built over the
//     whole face it reproduced only constants (measured: 2.2e-2 for a
//     linear field).
//  2c. The patch test of 1. moved by (1000, 1000)
//     (meshes/mortar_patch_2d_far.geo): the 2D projections must settle at
//     the round-off of coordinates far from the origin. With a fixed
//     tolerance on Newton's step they did not, the points they dropped
//     made whole faces look covered in part, and the interface carried up
//     to 2.9 MPa (found by a review).
//  3. On matching meshes a mortar interface is node-to-node contact: the
//     paper's stacked cantilevers (p = 2, 10 increments) with 'blocks 0:1
//     mortar' give the forces of 'blocks 0:1' at every pair to 1e-10 of the
//     largest, and the same states.

#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/parameters.h>

#include <deal.II/base/mpi.h>

#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

using namespace dealii;

namespace
{
  std::string
  read(const std::string &path)
  {
    std::ifstream      in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

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

  const std::string settings = R"(
set Test mode = true
subsection Output
  set Write VTU = false
  set Directory = results
end
)";

  /** A polynomial of degree @p p in every coordinate, mixed terms too. */
  template <int dim>
  double
  polynomial(const Point<dim> &x, const unsigned int p)
  {
    double value = 0.3;
    for (unsigned int d = 0; d < dim; ++d)
      value += (0.7 + d) * x[d] + (p > 1 ? 0.4 * x[d] * x[d] : 0.) +
               (p > 1 ? 0.9 * x[d] * x[(d + 1) % dim] : 0.);
    return value;
  }

  template <int dim>
  void
  patch_test(const unsigned int lower,
             const unsigned int upper,
             const std::string &side = "coarser")
  {
    const std::string file =
      SOURCE_DIR "/../parameters/mortar_patch_" + std::to_string(dim) + "d.prm";
    std::string text = read(file) + settings;
    text += "subsection Finite element\n  set Polynomial degree = 1\n"
            "  set Block degrees = 1: " +
            std::to_string(lower) + "; 2: " + std::to_string(upper) +
            "\nend\nsubsection Contact\n  set Mortar side = " + side +
            "\nend\n";
    mbfem::Parameters<dim> parameters;
    const auto             problem = run<dim>(text, parameters);
    const auto            &contact = *problem->get_contact();
    const auto            &blocks  = problem->get_blocks();

    double pressure = 0., shear = 0., weights = 0.;
    for (unsigned int k = 0; k < contact.pairs().size(); ++k)
      {
        const auto          &pair = contact.pairs()[k];
        const Tensor<1, dim> r    = contact.local_force(k) / pair.area;
        pressure = std::max(pressure, std::abs(r[0] - 1e6) / 1e6);
        for (unsigned int d = 1; d < dim; ++d)
          shear = std::max(shear, std::abs(r[d]) / 1e6);

        const auto   a_points = blocks[pair.a.block]->support_points();
        const auto   b_points = blocks[pair.b.block]->support_points();
        const double p        = std::min(lower, upper);
        double       f = -polynomial(a_points[pair.a.nodes[0].dofs[0]], p);
        for (const auto &node : pair.b.nodes)
          f += node.weight * polynomial(b_points[node.dofs[0]], p);
        weights = std::max(weights, std::abs(f));
      }
    std::cout << dim << "D, p = " << lower << " below and " << upper
              << " above, multipliers on the " << side
              << " side: " << contact.pairs().size()
              << " pairs; pressure 1 MPa at every pair to 1e-8: "
              << (pressure < 1e-8 ? "yes" : "NO")
              << "; shear below 1e-8 of it: " << (shear < 1e-8 ? "yes" : "NO")
              << "; polynomials of degree " << std::min(lower, upper)
              << " reproduced to 1e-10: " << (weights < 1e-10 ? "yes" : "NO")
              << std::endl;
  }

  /**
   * The weights at every pair of a short block on a longer base (2b.):
   * sum_k w_k f(x_k) = f(x_j) for a linear f, the largest misfit returned.
   */
  void
  partial_cover()
  {
    std::string text = read(SOURCE_DIR "/../parameters/mortar_patch_2d.prm") +
                       settings +
                       "subsection Mesh\n  set Mesh file = "
                       "../meshes/mortar_partial_2d.msh\nend\n";
    mbfem::Parameters<2> parameters;
    const auto           problem = run<2>(text, parameters);
    const auto          &contact = *problem->get_contact();
    const auto          &blocks  = problem->get_blocks();
    double               weights = 0., force = 0.;
    for (unsigned int k = 0; k < contact.pairs().size(); ++k)
      {
        const auto &pair     = contact.pairs()[k];
        const auto  a_points = blocks[pair.a.block]->support_points();
        const auto  b_points = blocks[pair.b.block]->support_points();
        double      f = -polynomial(a_points[pair.a.nodes[0].dofs[0]], 1);
        for (const auto &node : pair.b.nodes)
          f += node.weight * polynomial(b_points[node.dofs[0]], 1);
        weights = std::max(weights, std::abs(f));
        force += contact.local_force(k)[0];
      }
    std::cout << "2D, a short block on a longer base: "
              << contact.pairs().size()
              << " pairs; they carry the load 0.8 MN/m to 1e-8: "
              << (std::abs(force / 0.8e6 - 1.) < 1e-8 ? "yes" : "NO")
              << "; linear fields reproduced to 1e-10: "
              << (weights < 1e-10 ? "yes" : "NO") << std::endl;
  }

  /** 2c.: the pressure and shear of the patch test far from the origin. */
  void
  far_patch_test(const unsigned int lower, const unsigned int upper)
  {
    std::string text =
      read(SOURCE_DIR "/../parameters/mortar_patch_2d.prm") + settings +
      "subsection Mesh\n  set Mesh file = ../meshes/mortar_patch_2d_far.msh\n"
      "end\nsubsection Finite element\n  set Polynomial degree = 1\n"
      "  set Block degrees = 1: " +
      std::to_string(lower) + "; 2: " + std::to_string(upper) + "\nend\n";
    mbfem::Parameters<2> parameters;
    const auto           problem  = run<2>(text, parameters);
    const auto          &contact  = *problem->get_contact();
    double               pressure = 0., shear = 0., area = 0.;
    for (unsigned int k = 0; k < contact.pairs().size(); ++k)
      {
        const Tensor<1, 2> r = contact.local_force(k) / contact.pairs()[k].area;
        pressure             = std::max(pressure, std::abs(r[0] - 1e6) / 1e6);
        shear                = std::max(shear, std::abs(r[1]) / 1e6);
        area += contact.pairs()[k].area;
      }
    std::cout << "2D, moved by (1000, 1000), p = " << lower << " below and "
              << upper << " above: " << contact.pairs().size()
              << " pairs, area 1 to 1e-10: "
              << (std::abs(area - 1.) < 1e-10 ? "yes" : "NO")
              << "; pressure 1 MPa at every pair to 1e-8: "
              << (pressure < 1e-8 ? "yes" : "NO")
              << "; shear below 1e-8 of it: " << (shear < 1e-8 ? "yes" : "NO")
              << std::endl;
  }

  void
  matching_is_node_to_node()
  {
    const std::string file =
      SOURCE_DIR "/../parameters/stacked_cantilevers.prm";
    const std::string text = read(file) + settings +
                             "subsection Contact\n  set Formulation = "
                             "condensed\nend\n";
    mbfem::Parameters<3> node_parameters, mortar_parameters;
    const auto           nodes = run<3>(text, node_parameters);
    const auto           mortar =
      run<3>(text + "subsection Contact\n  set Interfaces = blocks 0:1 "
                    "mortar\nend\n",
             mortar_parameters);
    const auto &a = *nodes->get_contact(), &b = *mortar->get_contact();

    // Pairs by the point of their side a (the mortar side is then block 0
    // or 1: the point is where both sides' nodes coincide).
    std::map<std::array<long, 3>, unsigned int> of_point;
    const auto                                  key = [](const Point<3> &x) {
      return std::array<long, 3>{{std::lround(x[0] * 1e6),
                                  std::lround(x[1] * 1e6),
                                  std::lround(x[2] * 1e6)}};
    };
    for (unsigned int k = 0; k < a.pairs().size(); ++k)
      of_point[key(a.pairs()[k].a.point)] = k;
    double       largest = 0., difference = 0.;
    unsigned int matched = 0, states = 0;
    for (unsigned int k = 0; k < b.pairs().size(); ++k)
      {
        const auto found = of_point.find(key(b.pairs()[k].a.point));
        if (found == of_point.end())
          continue;
        ++matched;
        const unsigned int j = found->second;
        // The force on side b: the same block in both, or its opposite.
        const double sign =
          (a.pairs()[j].b.block == b.pairs()[k].b.block ? 1. : -1.);
        difference =
          std::max(difference, (a.force(j) - sign * b.force(k)).norm());
        largest = std::max(largest, a.force(j).norm());
        states += (a.state(j) == b.state(k));
      }
    std::cout << "stacked cantilevers, matching meshes: " << b.pairs().size()
              << " mortar pairs, " << matched
              << " at the points of the node-to-node ones, the same state at "
              << states << "; forces equal to 1e-10 of the largest: "
              << (difference < 1e-10 * largest ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const auto &[lower, upper] : std::vector<std::pair<unsigned, unsigned>>{
         {1, 1}, {1, 2}, {2, 1}, {2, 2}, {1, 3}})
    patch_test<2>(lower, upper);
  patch_test<2>(1, 2, "finer");
  partial_cover();
  far_patch_test(1, 1);
  far_patch_test(1, 2);
  for (const auto &[lower, upper] :
       std::vector<std::pair<unsigned, unsigned>>{{1, 1}, {1, 2}, {2, 2}})
    patch_test<3>(lower, upper);
  patch_test<3>(1, 2, "finer");
  matching_is_node_to_node();
}

// Which rigid-body modes a block's supports leave free: the floating-block
// bookkeeping of the multi-body method (paper eqs. 5-10). Checked on a unit
// square (2D) and a unit cube (3D) with supports whose free modes are known
// by hand. Boundary ids of the colorized hyper_cube: 0/1 at x = 0/1,
// 2/3 at y = 0/1, 4/5 at z = 0/1.

#include <mbfem/block/block.h>
#include <mbfem/block/boundary_conditions.h>
#include <mbfem/mesh/mesh.h>

#include <deal.II/base/mpi.h>

#include <iostream>

using namespace dealii;

template <int dim>
void
check(const std::string &supports)
{
  ParameterHandler prm;
  mbfem::BoundaryConditions<dim>::declare_parameters(prm);
  prm.parse_input_from_string("subsection Boundary conditions\n"
                              "  set Prescribed displacement boundary ids = " +
                              supports + "\nend\n");
  mbfem::BoundaryConditions<dim> bc;
  bc.parse_parameters(prm);

  mbfem::DiscretisationParameters discretisation;
  discretisation.degree         = 2;
  discretisation.mapping_degree = 2;
  mbfem::Block<dim>     block(mbfem::Material(1., 0.3),
                          discretisation,
                          "Amesos_Klu");
  mbfem::MeshParameters mesh;
  mesh.source              = "generator";
  mesh.generator_name      = "hyper_cube";
  mesh.generator_arguments = "0:1:true";
  mesh.initial_refinement  = 1;
  block.create_mesh(mesh);
  block.setup_system(bc);

  const auto free_modes = block.free_rigid_body_modes();
  std::cout << dim << "D, supports '" << supports << "': " << free_modes.size()
            << " free";
  for (const auto &mode : free_modes)
    std::cout << " [" << mbfem::Block<dim>::describe_rigid_body_mode(mode)
              << "]";
  std::cout << std::endl;
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  check<2>("");                 // floating: all 3
  check<2>("0: xy");            // clamped edge: none
  check<2>("2: y");             // rollers on y = 0: translation x
  check<2>("2: y, 0: x");       // rollers on two edges: none
  check<2>("0: x, 1: x");       // two walls in x: translation y
  check<3>("");                 // floating: all 6
  check<3>("4: xyz");           // clamped base: none
  check<3>("4: z");             // on rollers: translations x, y, rotation z
  check<3>("4: z, 0: x, 2: y"); // three symmetry planes: none
}

// A block's contact flexibility from MUMPS (selected entries of K^{-1},
// block/flexibility.h) must equal the one the method defines it by: the
// displacements at the contact DoFs under a unit force at each of them in
// turn, solved one by one with the block's own factorisation. Checked on
// small 3D blocks with floating modes (pinned, so C is that of the pinned
// block), whose contact DoFs include supported and pinned ones, and enough
// of them (>= 500) that Block::flexibility() takes the MUMPS route.
// The same flexibility on demand (ContactFlexibility: columns and diagonal
// forms for load patterns) must match it too.
// Boundary ids of the colorized hyper_cube: 0/1 at x = 0/1, 2/3 at
// y = 0/1, 4/5 at z = 0/1.

#include <mbfem/block/block.h>
#include <mbfem/block/boundary_conditions.h>
#include <mbfem/mesh/mesh.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>

#include <cstdio>
#include <iostream>

using namespace dealii;

template <int dim>
void
check(const std::string &supports, const unsigned int degree)
{
  ParameterHandler prm;
  mbfem::BoundaryConditions<dim>::declare_parameters(prm);
  prm.parse_input_from_string("subsection Boundary conditions\n"
                              "  set Prescribed displacement boundary ids = " +
                              supports + "\nend\n");
  mbfem::BoundaryConditions<dim> bc;
  bc.parse_parameters(prm);

  mbfem::DiscretisationParameters discretisation;
  discretisation.degree         = degree;
  discretisation.mapping_degree = degree;
  mbfem::Block<dim>     block(mbfem::Material(2e9, 0.3),
                          discretisation,
                          "Amesos_Klu");
  mbfem::MeshParameters mesh;
  mesh.source              = "generator";
  mesh.generator_name      = "hyper_cube";
  mesh.generator_arguments = "0:2:true";
  mesh.initial_refinement  = 2;
  block.create_mesh(mesh);
  block.setup_system(bc);
  block.assemble_stiffness();
  block.factorize();

  // The contact DoFs: every DoF on the faces x = 2, y = 0 and z = 2.
  const IndexSet face_x =
    DoFTools::extract_boundary_dofs(block.get_dof_handler(),
                                    ComponentMask(),
                                    std::set<types::boundary_id>{1});
  const IndexSet face_y =
    DoFTools::extract_boundary_dofs(block.get_dof_handler(),
                                    ComponentMask(),
                                    std::set<types::boundary_id>{2});
  const IndexSet face_z =
    DoFTools::extract_boundary_dofs(block.get_dof_handler(),
                                    ComponentMask(),
                                    std::set<types::boundary_id>{5});
  IndexSet contact = face_x;
  contact.add_indices(face_y);
  contact.add_indices(face_z);
  std::vector<types::global_dof_index> dofs;
  for (const auto dof : contact)
    dofs.push_back(dof);

  const FullMatrix<double> flexibility = block.flexibility(dofs);

  // The unit-load route: one solve per contact DoF.
  FullMatrix<double> reference(dofs.size(), dofs.size());
  for (unsigned int j = 0; j < dofs.size(); ++j)
    {
      block.assemble_load(bc, 0.);
      block.add_point_forces({dofs[j]}, {1.});
      block.solve();
      for (unsigned int i = 0; i < dofs.size(); ++i)
        reference(i, j) = block.get_solution()(dofs[i]);
    }

  double largest = 0., difference = 0., asymmetry = 0.;
  for (unsigned int i = 0; i < dofs.size(); ++i)
    for (unsigned int j = 0; j < dofs.size(); ++j)
      {
        largest = std::max(largest, std::abs(reference(i, j)));
        difference =
          std::max(difference, std::abs(flexibility(i, j) - reference(i, j)));
        asymmetry =
          std::max(asymmetry, std::abs(flexibility(i, j) - flexibility(j, i)));
      }
  std::printf("%dD, FE_Q(%u), supports '%s': %zu free mode(s), %zu contact "
              "DoFs; MUMPS against unit loads: relative difference %s 1e-10, "
              "symmetric %s\n",
              dim,
              degree,
              supports.c_str(),
              block.free_rigid_body_modes().size(),
              dofs.size(),
              difference <= 1e-10 * largest ? "below" : "ABOVE",
              asymmetry <= 1e-10 * largest ? "to 1e-10" : "NO");
  if (difference > 1e-10 * largest)
    std::printf("  largest entry %.3e, largest difference %.3e\n",
                largest,
                difference);

  // On demand (ContactFlexibility): columns C s and forms s^T C s for unit
  // loads at every 7th contact DoF and for two-DoF patterns, against the
  // unit-load reference; a load that reaches no free DoF moves nothing.
  const auto                      on_demand = block.on_demand_flexibility(dofs);
  std::vector<mbfem::ContactLoad> loads;
  for (unsigned int j = 0; j < dofs.size(); j += 7)
    loads.push_back({{j, 1.}});
  for (unsigned int j = 0; j + 1 < dofs.size(); j += 11)
    loads.push_back({{j, 0.5}, {j + 1, -2.}});
  const FullMatrix<double>  columns           = on_demand->columns(loads);
  const std::vector<double> forms             = on_demand->forms(loads);
  double                    column_difference = 0., form_difference = 0.;
  unsigned int              still      = 0;
  bool                      still_zero = true;
  for (unsigned int l = 0; l < loads.size(); ++l)
    {
      double form = 0.;
      for (unsigned int i = 0; i < dofs.size(); ++i)
        {
          double value = 0.;
          for (const auto &[j, w] : loads[l])
            value += reference(i, j) * w;
          column_difference =
            std::max(column_difference, std::abs(columns(i, l) - value));
          for (const auto &[j, w] : loads[l])
            if (j == i)
              form += w * value;
        }
      form_difference = std::max(form_difference, std::abs(forms[l] - form));
      if (!on_demand->moves(loads[l]))
        {
          ++still;
          for (unsigned int i = 0; i < dofs.size(); ++i)
            still_zero = still_zero && columns(i, l) == 0.;
          still_zero = still_zero && forms[l] == 0.;
        }
    }
  std::printf("  on demand, %zu load patterns: columns and forms against unit "
              "loads %s 1e-10; %u move nothing, with zero columns and forms: "
              "%s\n",
              loads.size(),
              std::max(column_difference, form_difference) <= 1e-10 * largest ?
                "below" :
                "ABOVE",
              still,
              still_zero ? "yes" : "NO");
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  check<3>("4: z", 2);       // on rollers: translations x, y, rotation z
  check<3>("4: z, 0: x", 2); // rotation z and translation y free
}

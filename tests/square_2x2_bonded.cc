// The cross-point rule is exact while every pair sticks
// (doc/jointed_rock.md): the 2 x 2 square of square_2x2.prm (four blocks
// on a clamped base block, gravity and a lateral traction, every interface
// declared by 'Interfaces = all', so that three blocks meet at one point
// and four at another) with joints far stronger than the stresses (c and
// sigma_t 1e6) must reproduce the uncut body: the displacement at every
// support point and the stress at every cell centre agree to 1e-8
// relative, in the condensed and in the monolithic formulation. (Had the
// loop at a cross-point been cut by dropping a pair, this would hold too;
// what the rule adds is that the dropped interface keeps its law, which
// square_2x2_pull and square_2x2_push exercise.)

#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/numerics/fe_field_function.h>

#include <cstdio>
#include <iostream>

using namespace dealii;

const std::string problem = R"(
set Dimension = 2
set Test mode = true
subsection Mesh
  set Generator name      = subdivided_hyper_rectangle
  set Generator arguments = 4,5 : 0,0 : 2,2.5 : true
end
subsection Finite element
  set Polynomial degree = 2
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.25
  set Unit weight     = 1
end
subsection Boundary conditions
  set Prescribed displacement boundary ids = 2: xy
  set Traction boundary ids                = 0
  subsection Traction
    set Function expression = (y > 0.5) * 0.05; 0
  end
end
subsection Output
  set Write VTU = false
  set Directory = results
end
)";

std::string
cut(const std::string &formulation)
{
  return R"(
subsection Mesh
  set Block id function = (y > 0.5) * (1 + (x > 1) + 2*(y > 1.5))
end
subsection Contact
  set Interfaces           = all
  set Friction coefficient = 0.5
  set Cohesion             = 1e6
  set Tensile strength     = 1e6
  set Formulation          = )" +
         formulation + "\nend\n";
}

std::unique_ptr<mbfem::MultiBodyProblem<2>>
run(const std::string &text, mbfem::Parameters<2> &parameters)
{
  ParameterHandler prm;
  mbfem::Parameters<2>::declare_parameters(prm);
  prm.parse_input_from_string(text);
  parameters.parse_parameters(prm, ".");
  static ConditionalOStream quiet(std::cout, false);
  auto                      problem =
    std::make_unique<mbfem::MultiBodyProblem<2>>(parameters, quiet);
  problem->run();
  return problem;
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  mbfem::Parameters<2> whole_parameters;
  const auto           whole = run(problem, whole_parameters);
  for (const std::string formulation : {"condensed", "monolithic"})
    {
      mbfem::Parameters<2> cut_parameters;
      const auto split = run(problem + cut(formulation), cut_parameters);
      std::cout << formulation << ": ";

      const auto                   &reference = *whole->get_blocks()[0];
      Functions::FEFieldFunction<2> field(reference.get_dof_handler(),
                                          reference.get_solution(),
                                          reference.get_mapping());

      std::cout << "cut body: " << split->get_blocks().size() << " blocks";
      const auto *contact = split->get_contact();
      std::cout << "\n"
                << contact->pairs().size() << " pairs: stick/slip/open "
                << contact->count(mbfem::ContactState::stick) << "/"
                << contact->count(mbfem::ContactState::slip) << "/"
                << contact->count(mbfem::ContactState::open) << std::endl;

      double u_difference = 0., u_max = 0., s_difference = 0., s_max = 0.;
      for (const auto &block : split->get_blocks())
        {
          const auto     points = block->support_points();
          Vector<double> value(2);
          // Displacement at every node of the block.
          std::vector<types::global_dof_index> dofs(
            block->get_fe().n_dofs_per_cell());
          for (const auto &cell :
               block->get_dof_handler().active_cell_iterators())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < dofs.size(); ++i)
                {
                  const unsigned int c =
                    block->get_fe().system_to_component_index(i).first;
                  field.vector_value(points[dofs[i]], value);
                  u_difference =
                    std::max(u_difference,
                             std::abs(block->get_solution()(dofs[i]) -
                                      value(c)));
                  u_max = std::max(u_max, std::abs(value(c)));
                }
              // Stress at the cell centre, from both fields.
              const Point<2>            centre = cell->center();
              std::vector<Tensor<1, 2>> grad_ref(2), grad_cut(2);
              field.vector_gradient(centre, grad_ref);
              Functions::FEFieldFunction<2> own(block->get_dof_handler(),
                                                block->get_solution(),
                                                block->get_mapping());
              own.set_active_cell(cell);
              own.vector_gradient(centre, grad_cut);
              Tensor<2, 2> g_ref, g_cut;
              for (unsigned int d = 0; d < 2; ++d)
                {
                  g_ref[d] = grad_ref[d];
                  g_cut[d] = grad_cut[d];
                }
              const auto s_ref =
                block->get_material().stress<2>(symmetrize(g_ref));
              const auto s_cut =
                block->get_material().stress<2>(symmetrize(g_cut));
              s_difference = std::max(s_difference, (s_ref - s_cut).norm());
              s_max        = std::max(s_max, s_ref.norm());
            }
        }
      const double u_relative = u_difference / u_max;
      const double s_relative = s_difference / s_max;
      std::printf("displacement at the nodes: cut and uncut agree to 1e-8 "
                  "relative: %s\n",
                  u_relative < 1e-8 ? "yes" : "NO");
      std::printf("stress at the cell centres: cut and uncut agree to 1e-8 "
                  "relative: %s\n",
                  s_relative < 1e-8 ? "yes" : "NO");
    }
}

// Bonded split: Timoshenko's cantilever (p = 2, 20 x 4 cells) cut at x = 5
// into two blocks joined by an interface that stays stuck (c and sigma_t
// far above the stresses). The right block has no support of its own: it
// is a floating block held only by the bonded interface. Its rigid-body
// unknowns, the equilibrium equations and the contact flexibility must
// reproduce the uncut body exactly, because node-wise continuity at the cut
// is what the uncut finite element space has: the displacement at every
// support point and the stress at every cell centre agree to 1e-8 relative
// (measured when written: 1.1e-12 for both, round-off).

#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/numerics/fe_field_function.h>

#include <iostream>

using namespace dealii;

const std::string problem = R"(
set Dimension = 2
set Test mode = true
subsection Mesh
  set Generator arguments       = 5,1 : 0,-1 : 10,1 : true
  set Initial global refinement = 2
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.25
end
subsection Boundary conditions
  set Prescribed displacement boundary ids = 0: xy
  subsection Prescribed displacement
    set Function constants  = P=1, L=10, D=2, I=0.6666666666666666, Ep=1066.6666666666667, nup=0.3333333333333333
    set Function expression = -t*P*y/(6*Ep*I)*((6*L-3*x)*x + (2+nup)*(y^2-D^2/4)); t*P/(6*Ep*I)*(3*nup*y^2*(L-x) + (4+5*nup)*D^2*x/4 + (3*L-x)*x^2)
  end
  set Traction boundary ids = 1
  subsection Traction
    set Function constants  = P=1, D=2, I=0.6666666666666666
    set Function expression = 0; t*P/(2*I)*(D^2/4-y^2)
  end
end
subsection Output
  set Write VTU = false
  set Directory = results
end
)";

const std::string cut = R"(
subsection Mesh
  set Block id function = (x > 5)
end
subsection Contact
  set Interfaces           = blocks 0:1
  set Friction coefficient = 0.5
  set Cohesion             = 1e6
  set Tensile strength     = 1e6
end
)";

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
  // Under mpirun (NAME.mpirun=2.output) rank 0 prints, as mbfem does.
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.rdbuf(nullptr);

  mbfem::Parameters<2> whole_parameters, cut_parameters;
  const auto           whole = run(problem, whole_parameters);
  const auto           split = run(problem + cut, cut_parameters);

  const auto                   &reference = *whole->get_blocks()[0];
  Functions::FEFieldFunction<2> field(reference.get_dof_handler(),
                                      reference.get_solution(),
                                      reference.get_mapping());

  std::cout << "cut body: " << split->get_blocks().size() << " blocks";
  for (const auto &block : split->get_blocks())
    std::cout << ", " << block->name() << " with "
              << block->floating_modes().size() << " floating modes";
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
      for (const auto &cell : block->get_dof_handler().active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const unsigned int c =
                block->get_fe().system_to_component_index(i).first;
              field.vector_value(points[dofs[i]], value);
              u_difference =
                std::max(u_difference,
                         std::abs(block->get_solution()(dofs[i]) - value(c)));
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
          const auto s_ref = block->get_material().stress<2>(symmetrize(g_ref));
          const auto s_cut = block->get_material().stress<2>(symmetrize(g_cut));
          s_difference     = std::max(s_difference, (s_ref - s_cut).norm());
          s_max            = std::max(s_max, s_ref.norm());
        }
    }
  const double u_relative = u_difference / u_max;
  const double s_relative = s_difference / s_max;
  std::cout << "displacement at the nodes: cut and uncut agree to 1e-8 "
               "relative: "
            << (u_relative < 1e-8 ? "yes" : "NO") << "\n"
            << "stress at the cell centres: cut and uncut agree to 1e-8 "
               "relative: "
            << (s_relative < 1e-8 ? "yes" : "NO") << std::endl;
}

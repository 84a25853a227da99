// Shared by the unit tests that run a whole model from the text of a
// parameter file (tests/stage_*.cc): each test stays one file to read, and
// the way a model is run is written once.
#ifndef mbfem_tests_run_model_h
#define mbfem_tests_run_model_h

#include <mbfem/analysis/multibody_problem.h>
#include <mbfem/analysis/parameters.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <iostream>
#include <memory>
#include <string>

/** Runs the model of @p text silently, as `mbfem` would from a file. */
template <int dim>
std::unique_ptr<mbfem::MultiBodyProblem<dim>>
run_model(const std::string &text, mbfem::Parameters<dim> &parameters)
{
  dealii::ParameterHandler prm;
  mbfem::Parameters<dim>::declare_parameters(prm);
  prm.parse_input_from_string(text);
  parameters.parse_parameters(prm, ".");
  static dealii::ConditionalOStream quiet(std::cout, false);
  auto                              problem =
    std::make_unique<mbfem::MultiBodyProblem<dim>>(parameters, quiet);
  problem->run();
  return problem;
}

/**
 * The column of stage_lifts and stage_removal: three blocks 1 m x 1 m
 * stacked on a fixed base (material ids 1, 2, 3 from the bottom), FE_Q(2),
 * E = 20 GPa, nu = 0, 24 kN/m^3, joints with mu = 1.
 */
inline const std::string column_of_three_blocks = R"(
set Dimension = 2
set Test mode = true
subsection Mesh
  set Generator arguments = 2,6 : 0,0 : 1,3 : true
  set Block id function   = 1 + (y > 1) + (y > 2)
end
subsection Finite element
  set Polynomial degree = 2
end
subsection Material
  set Young's modulus = 20e9
  set Poisson's ratio = 0
  set Unit weight     = 24e3
end
subsection Boundary conditions
  set Prescribed displacement boundary ids = 2: xy
end
subsection Contact
  set Interfaces           = blocks 1:2; blocks 2:3
  set Friction coefficient = 1
end
subsection Output
  set Write VTU = false
  set Directory = results
end
)";

#endif

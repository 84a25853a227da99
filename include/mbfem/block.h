#ifndef mbfem_block_h
#define mbfem_block_h

#include <mbfem/boundary_conditions.h>
#include <mbfem/direct_solver.h>
#include <mbfem/material.h>

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /** Element order and geometry order, subsection "Finite element". */
  struct DiscretisationParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    unsigned int degree         = 2;
    unsigned int mapping_degree = 2;
  };

  /** L2 errors against a closed-form solution, absolute and relative. */
  struct ErrorNorms
  {
    double displacement          = 0.;
    double displacement_relative = 0.;
    double stress                = 0.;
    double stress_relative       = 0.;
  };

  /**
   * One block of the multi-body method: an independent elastic finite
   * element model with its own Triangulation, DoFHandler and FESystem of
   * FE_Q(p) (any order), a MappingQ of matching order so that curved faces
   * stay curved, and its stiffness factorised once. Nothing in it refers to
   * other blocks: they interact only through forces at contact pairs, which
   * is what lets a block live on its own MPI rank.
   *
   * Prescribed displacements may change with pseudo-time without a new
   * factorisation: the stiffness is assembled with the constrained rows and
   * columns removed, and each load vector carries the lifting -K u_D.
   */
  template <int dim>
  class Block
  {
  public:
    Block(const Material                 &material,
          const DiscretisationParameters &discretisation,
          const std::string              &solver_package);

    /** Distributes DoFs on triangulation (filled by the caller). */
    void
    setup_system(const BoundaryConditions<dim> &boundary_conditions);

    void
    assemble_stiffness();

    void
    factorize();

    /** Load vector and constraint values at pseudo-time @p time. */
    void
    assemble_load(BoundaryConditions<dim> &boundary_conditions,
                  const double             time);

    /** solution = K^{-1} load, with the prescribed values filled in. */
    void
    solve();

    /**
     * L2 norms of u - u_exact and sigma - sigma_exact (the latter a function
     * with dim*dim components, row by row), each also relative to the norm
     * of the exact field.
     */
    ErrorNorms
    compute_errors(const Function<dim> &exact_displacement,
                   const Function<dim> &exact_stress) const;

    /**
     * The rigid-body modes of the block as displacement vectors: the dim
     * translations and the rotations (1 in 2D, 3 in 3D) about the block's
     * centre, with lengths scaled by the block's size so that all modes
     * are of unit order.
     */
    std::vector<Vector<double>>
    rigid_body_modes() const;

    /**
     * The combinations of rigid_body_modes() that the prescribed
     * displacements of @p boundary_conditions leave free, one coefficient
     * vector each; empty for a block that is held. Without supports a block
     * has all of them free (3 in 2D, 6 in 3D): the paper's floating block,
     * whose stiffness is singular.
     */
    std::vector<Vector<double>>
    free_rigid_body_modes(
      const BoundaryConditions<dim> &boundary_conditions) const;

    /** "translation x", "rotation about z", ... for messages. */
    static std::string
    describe_rigid_body_mode(const Vector<double> &coefficients);

    /** Largest displacement magnitude over the support points. */
    double
    max_displacement() const;

    /** Largest von Mises stress over the Gauss points. */
    double
    max_von_mises_stress() const;

    types::global_dof_index
    n_dofs() const;

    Triangulation<dim>  triangulation;
    const Material      material;
    const FESystem<dim> fe;
    const MappingQ<dim> mapping;
    DoFHandler<dim>     dof_handler;

    Vector<double> solution;

  private:
    /**
     * Cell stiffness from @p fe_values (already reinit'ed on the cell);
     * shared by the matrix and the load assembly.
     */
    void
    cell_matrix(const FEValues<dim> &fe_values,
                FullMatrix<double>  &matrix) const;

    /** Hanging-node and Dirichlet constraints, values at the set time. */
    void
    make_constraints(const BoundaryConditions<dim> &boundary_conditions);

    AffineConstraints<double>      constraints;
    TrilinosWrappers::SparseMatrix stiffness;
    DirectSolver                   direct_solver;
    Vector<double>                 load;
  };
} // namespace mbfem

#endif

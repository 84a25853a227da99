#ifndef mbfem_block_flexibility_h
#define mbfem_block_flexibility_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * A block's contact flexibility C = (K^{-1}) restricted to the contact
   * DoFs @p dofs (paper eq. 2), from one MUMPS factorisation of the
   * stiffness and the selected entries of its inverse (ICNTL(30)), instead
   * of one solve per unit load: doc/benchmarks.md has the measurements that
   * chose this route over the Schur complement (ICNTL(19)) and over dense
   * unit loads.
   *
   * @p stiffness is the block's matrix with the constraints eliminated
   * (constrained rows and columns hold only a diagonal entry), and
   * @p constraints the same constraints made homogeneous. A unit force at
   * a constrained DoF goes where the constraints send it (a platen node
   * loads the platen, a fixed node nothing), and the displacement of a
   * constrained DoF is that of its masters: so C = T (K^{-1})_MM T^T, M the
   * masters of @p dofs (each unconstrained DoF its own master) and T the
   * constraints' weights. Symmetric.
   *
   * @p positive_definite chooses LDL^T without pivoting (elastic
   * stiffness) or with it (a tangent that may be indefinite).
   */
  FullMatrix<double>
  contact_flexibility(const TrilinosWrappers::SparseMatrix       &stiffness,
                      const AffineConstraints<double>            &constraints,
                      const std::vector<types::global_dof_index> &dofs,
                      const bool positive_definite = true);
} // namespace mbfem

#endif

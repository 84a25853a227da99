#ifndef mbfem_block_flexibility_h
#define mbfem_block_flexibility_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  class MumpsSolver;

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

  /** A load pattern over a block's contact DoFs: (index into dofs, weight). */
  using ContactLoad = std::vector<std::pair<unsigned int, double>>;

  /**
   * A block's contact flexibility (as contact_flexibility()) on demand:
   * the block's MUMPS factorisation is kept, and only the columns asked for
   * are computed, as selected entries of K^{-1} (ICNTL(30)), so that a
   * block with thousands of contact DoFs of which a few carry force costs
   * (contact DoFs x loaded DoFs), not (contact DoFs)^2. CondensedSystem
   * asks for the columns of the pairs that close.
   */
  class ContactFlexibility
  {
  public:
    /**
     * The flexibility over @p dofs from @p factorisation, the block's own
     * factorisation of its stiffness (Block::on_demand_flexibility()),
     * shared rather than repeated: the block solves with it too. The
     * constraints as for contact_flexibility(). Under MPI only the block's
     * owner holds the factorisation; elsewhere @p factorisation is null,
     * and forms() and columns() may not be called (CondensedSystem
     * broadcasts what they return).
     */
    ContactFlexibility(std::shared_ptr<const MumpsSolver> factorisation,
                       const AffineConstraints<double>   &constraints,
                       const std::vector<types::global_dof_index> &dofs);

    ~ContactFlexibility();

    /** Whether this rank holds the factorisation. */
    bool
    is_local() const;

    /** The contact DoFs, as given. */
    unsigned int
    size() const;

    /**
     * Whether load pattern @p load reaches a free DoF (where the
     * constraints send it): otherwise it moves nothing and s^T C s = 0.
     */
    bool
    moves(const ContactLoad &load) const;

    /** s^T C s for each load pattern s of @p loads (a few entries each). */
    std::vector<double>
    forms(const std::vector<ContactLoad> &loads) const;

    /**
     * C s for each load pattern s of @p loads: the displacements at the
     * contact DoFs (size() x loads.size()).
     */
    FullMatrix<double>
    columns(const std::vector<ContactLoad> &loads) const;

  private:
    /** A load pattern on the masters: (index into master_dofs, weight). */
    std::map<unsigned int, double>
    on_masters(const ContactLoad &load) const;

    /** Each contact DoF as a combination of unconstrained DoFs (masters). */
    std::vector<unsigned int>                                 master_dofs;
    std::vector<std::vector<std::pair<unsigned int, double>>> weights;
    std::shared_ptr<const MumpsSolver>                        solver;
  };
} // namespace mbfem

#endif

#ifndef mbfem_contact_monolithic_system_h
#define mbfem_contact_monolithic_system_h

#include <mbfem/block/block.h>
#include <mbfem/contact/interface_system.h>
#include <mbfem/interface/contact_interface.h>
#include <mbfem/interface/pair_equation.h>
#include <mbfem/linear_algebra/direct_solver.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The reference formulation of the contact problem: every block's
   * displacement and every pair's force in one sparse system,
   *
   *   [ K   -G^T ] [ u   ]   [ f ]
   *   [ E_u  E_r ] [ rho ] = [ e ],
   *
   * K the blocks' stiffnesses under their physical constraints alone (no
   * pins: a floating block is held by the multipliers), G the map from
   * displacements to the pairs' relative displacements d = G u + g in the
   * pairs' frames (through the constraints: a pair node on a platen moves
   * with the platen), and (E_u, E_r) the rows of the current contact states
   * (PairEquation). It is the classical Lagrange-multiplier contact solve
   * the paper checks its second example against: no flexibility, no
   * rigid-body unknowns, one sparse LU (Amesos) per state iteration.
   *
   * The multipliers are scaled by the mean stiffness diagonal so that their
   * rows are of the size of the stiffness rows.
   */
  template <int dim>
  class MonolithicSystem : public InterfaceSystem<dim>
  {
  public:
    MonolithicSystem(const std::vector<ContactPair<dim>> &pairs,
                     const std::string                   &solver_package);

    /**
     * The blocks' unpinned stiffness matrices and the pattern of the whole
     * system. The blocks must have had assemble_load() once, so that their
     * physical constraints exist.
     */
    void
    setup(const std::vector<std::unique_ptr<Block<dim>>> &blocks) override;

    /**
     * Loads and prescribed values of the current increment, after every
     * block's assemble_load(); @p loads gets a zero Delta_F.
     */
    void
    set_load(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
             IncrementLoads                                 &loads) override;

    /**
     * Pair directions that no free degree of freedom moves (both nodes on
     * supports): their force goes to the supports.
     */
    std::vector<std::array<bool, dim>>
    held() const override;

    /**
     * Solves the system with the rows @p equations (pair by pair, dim rows
     * each); the loads are those of set_load(). Returns the pairs' forces
     * and relative displacements in their frames, or false if the
     * factorisation fails or gives no finite solution.
     */
    bool
    solve(const std::vector<PairEquation<dim>> &equations,
          const IncrementLoads                 &loads,
          Vector<double>                       &forces,
          Vector<double>                       &displacement) override;

    /**
     * Block @p b's displacement from the last solve, its constrained
     * values filled in.
     */
    void
    block_solution(const unsigned int b,
                   const Block<dim>  &block,
                   Vector<double>    &solution) const;

    /** Rows of the system. */
    types::global_dof_index
    size() const;

  private:
    /** d = sum of terms (a displacement unknown, a coefficient) + constant. */
    struct Term
    {
      types::global_dof_index column;
      double                  coefficient;
    };

    /**
     * The steps of setup(): the blocks' offsets, their unpinned stiffnesses
     * (with their patterns) and the scale of the multipliers...
     */
    void
    assemble_blocks(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                    std::vector<SparsityPattern>                   &patterns,
                    std::vector<SparseMatrix<double>>              &stiffness);

    /** ... the pattern of the whole system, for matrix... */
    void
    make_pattern(const std::vector<SparsityPattern> &patterns);

    /** ... and its entries that do not change with the states. */
    void
    add_fixed_entries(const std::vector<SparseMatrix<double>> &stiffness);

    /**
     * The relative displacements' constants (they change with the
     * prescribed values) and, @p with_terms, their terms (which follow the
     * constraints' structure and do not).
     */
    void
    make_relative_displacements(
      const std::vector<std::unique_ptr<Block<dim>>> &blocks,
      const bool                                      with_terms);

    std::vector<ContactPair<dim>>        pairs;
    std::vector<types::global_dof_index> offset;
    types::global_dof_index              n_displacements = 0;
    double                               stiffness_scale = 1.;

    std::vector<std::vector<Term>> terms;    // per pair row
    std::vector<double>            constant; // per pair row
    Vector<double>                 load;     // displacement rows

    TrilinosWrappers::SparseMatrix matrix;
    DirectSolver                   solver;
    Vector<double>                 solution;
  };
} // namespace mbfem

#endif

#ifndef mbfem_block_block_h
#define mbfem_block_block_h

#include <mbfem/block/boundary_conditions.h>
#include <mbfem/block/floating_modes.h>
#include <mbfem/linear_algebra/direct_solver.h>
#include <mbfem/material/in_situ_stress.h>
#include <mbfem/material/material.h>
#include <mbfem/material/plasticity.h>

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
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

  /** What one plastic update of a block found. */
  struct PlasticUpdate
  {
    /**
     * Squared L2 norms of the residual r = F(x) - x of the fixed-point map
     * (x the plastic strain in the load, F(x) the one the return mapping
     * gives back) and of F(x).
     */
    double change2 = 0.;
    double norm2   = 0.;
    /** r_prev . (r - r_prev) and |r - r_prev|^2, for Aitken's relaxation. */
    double       aitken_numerator   = 0.;
    double       aitken_denominator = 0.;
    unsigned int n_yielded          = 0;
    unsigned int n_points           = 0;
    /** Area (2D) or volume (3D) of the yielded quadrature points. */
    double yielded_measure = 0.;
    /** Largest sqrt(2/3 eps_p : eps_p). */
    double max_equivalent = 0.;

    PlasticUpdate &
    operator+=(const PlasticUpdate &other);
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
   *
   * A block whose supports leave rigid-body modes free (a floating block,
   * paper eqs. 5-10) is pinned at just enough degrees of freedom to remove
   * them: its flexibility is that of the pinned block, and the free modes
   * are returned by floating_modes() for the rigid-body unknowns and the
   * equilibrium equations of the contact solver. The pins carry no force
   * once the block is in equilibrium.
   */
  template <int dim>
  class Block
  {
  public:
    Block(const Material                 &material,
          const DiscretisationParameters &discretisation,
          const std::string              &solver_package,
          const types::material_id        id = 0);

    /**
     * Distributes DoFs on triangulation (filled by the caller), builds the
     * constraints, finds the free rigid-body modes and pins them.
     */
    void
    setup_system(const BoundaryConditions<dim> &boundary_conditions);

    /**
     * An initial (in-situ) stress and an excavation to release: both enter
     * the load of assemble_load(), the first also the stresses this block
     * reports. Must outlive the block.
     */
    void
    set_initial_state(const InSituStress *in_situ,
                      const Excavation   *excavation);

    /** The in-situ stress, or nullptr. */
    const InSituStress *
    get_in_situ_stress() const;

    /**
     * Makes the block elastic-perfectly plastic (Mohr-Coulomb) if
     * @p parameters are enabled; after the triangulation is filled.
     */
    void
    set_plasticity(const PlasticityParameters &parameters);

    bool
    is_plastic() const;

    /**
     * The return mapping at every quadrature point, from the current
     * solution and the plastic strain of the last converged increment; the
     * result becomes the plastic strain that the next assemble_load() puts
     * into the load (int B^T D eps_p).
     */
    PlasticUpdate
    update_plastic_strain();

    /**
     * Moves the plastic strain in the load by @p omega times the residual
     * of the last update_plastic_strain() (omega = 1: plain fixed point).
     */
    void
    relax_plastic_strain(const double omega);

    /**
     * Newton's method (Plasticity/Method): whether the tangent stiffness
     * differs from the one last assembled, so that the block must be
     * reassembled and refactorised and its flexibility recomputed before
     * the next pass. Always false for the initial-stress method.
     */
    bool
    tangent_changed() const;

    /**
     * Newton's method: with a perfectly plastic tangent, yielded rock and
     * slipping pairs can form a mechanism, and the tangent system is
     * singular although the elastic one is not. @p suspend = true puts the
     * elastic stiffness back and makes update_plastic_strain() do
     * initial-stress iterations for the rest of the step; false (at the
     * start of every step) resumes Newton. Returns whether the stiffness
     * last assembled had a plastic tangent, i.e. whether suspending changes
     * anything.
     */
    bool
    suspend_newton(const bool suspend);

    /** Accepts the plastic strain of the converged increment. */
    void
    commit_plastic_strain();

    /**
     * Goes back to the plastic state of the last commit (a failed increment
     * is retried in smaller steps).
     */
    void
    restore_plastic_state();

    /**
     * D eps_p at every quadrature point (cell-major, for the stresses at
     * output points), and per active cell the fraction of its points
     * yielded and the largest equivalent plastic strain.
     */
    void
    cell_plastic_fields(std::vector<SymmetricTensor<2, 3>> &plastic_stress,
                        std::vector<double>                &yielded,
                        std::vector<double> &equivalent_strain) const;

    void
    assemble_stiffness();

    void
    factorize();

    /** Load vector and constraint values at pseudo-time @p time. */
    void
    assemble_load(BoundaryConditions<dim> &boundary_conditions,
                  const double             time);

    /**
     * Adds point forces at DoFs (contact forces) to the current load; they
     * go through the constraints, so a force on a platen node loads the
     * platen.
     */
    void
    add_point_forces(const std::vector<types::global_dof_index> &dofs,
                     const std::vector<double>                  &forces);

    /**
     * solution = K^{-1} load, with the prescribed values filled in, plus
     * the rigid-body motion sum_i alpha_i floating_modes()[i] if given.
     */
    void
    solve(const std::vector<double> &alpha = {});

    /**
     * Displacements at @p dofs under a unit force at each of @p dofs in
     * turn: the block's contact flexibility (paper eq. 2, C = K^{-1}
     * restricted to contact DoFs): with 500 or more contact DoFs as
     * selected entries of the inverse of a MUMPS factorisation
     * (contact_flexibility()), below that by unit loads on the block's own
     * factorisation, in blocks of right-hand sides. Symmetric.
     */
    FullMatrix<double>
    flexibility(const std::vector<types::global_dof_index> &dofs) const;

    /**
     * Virtual work of the external load of the last assemble_load() in each
     * floating mode: the paper's F_e. Zero for a held block.
     */
    std::vector<double>
    external_load_resultant() const;

    /**
     * The free rigid-body modes as displacement vectors (unit order), zero
     * at every prescribed DoF; empty for a held block.
     */
    const std::vector<Vector<double>> &
    floating_modes() const;

    /**
     * The rigid-body modes of the block as displacement vectors: the dim
     * translations and the rotations (1 in 2D, 3 in 3D) about the block's
     * centre, with lengths scaled by the block's size so that all modes
     * are of unit order.
     */
    std::vector<Vector<double>>
    rigid_body_modes() const;

    /**
     * The combinations of rigid_body_modes() that the supports (prescribed
     * displacements, point supports, platens) leave free, one coefficient
     * vector each in reduced row-echelon form; empty for a held block.
     * Without supports all are free (3 in 2D, 6 in 3D). Found by
     * setup_system().
     */
    const std::vector<Vector<double>> &
    free_rigid_body_modes() const;

    /** "translation x", "rotation about z", ... for messages. */
    static std::string
    describe_rigid_body_mode(const Vector<double> &coefficients);

    /**
     * The physical constraints alone (no pins), with the prescribed values
     * of the last assemble_load().
     */
    const AffineConstraints<double> &
    get_physical_constraints() const;

    /**
     * For the monolithic reference formulation: the stiffness under the
     * physical constraints alone, without pins, so singular for a floating
     * block (its free modes are held by the contact multipliers of the
     * whole system instead). Constrained rows keep a diagonal entry.
     */
    void
    assemble_unpinned_stiffness(SparsityPattern      &pattern,
                                SparseMatrix<double> &matrix) const;

    /**
     * The external load of the last assemble_load() condensed with the
     * physical constraints alone (the lifting of the prescribed
     * displacements included), the right-hand side that goes with
     * assemble_unpinned_stiffness().
     */
    const Vector<double> &
    unpinned_load() const;

    /**
     * The quadrature of the block's stress state: QGauss(p + 1). The
     * plastic strain, Newton's tangents and the stresses written to the
     * output live at its points; every loop over that state uses it.
     */
    QGauss<dim>
    state_quadrature() const;

    /**
     * The stress (3x3; plane strain in 2D) at @p point for the strain
     * @p strain: elastic, plus the in-situ stress, minus D eps_p at point
     * @p q of cell @p cell of state_quadrature() if the block is plastic.
     */
    SymmetricTensor<2, 3>
    stress(const SymmetricTensor<2, dim> &strain,
           const Point<dim>              &point,
           const unsigned int             cell,
           const unsigned int             q) const;

    types::global_dof_index
    n_dofs() const;

    /** "block 2" (the material id), for messages. */
    std::string
    name() const;

    /** Support point of every DoF (with the mapping). */
    std::vector<Point<dim>>
    support_points() const;

    const types::material_id id;
    Triangulation<dim>       triangulation;
    const Material           material;
    const FESystem<dim>      fe;
    const MappingQ<dim>      mapping;
    DoFHandler<dim>          dof_handler;

    Vector<double> solution;

  private:
    /**
     * Cell stiffness from @p fe_values (already reinit'ed on the cell);
     * shared by the matrix and the load assembly.
     */
    void
    cell_matrix(const FEValues<dim> &fe_values,
                FullMatrix<double>  &matrix,
                const unsigned int   cell_index) const;

    /**
     * Newton's method at one point of the plastic state: the residual of
     * the linearisation into @p result, and the new tangent and
     * linearisation point.
     */
    void
    update_newton_point(const std::size_t              index,
                        const SymmetricTensor<2, dim> &strain,
                        const SymmetricTensor<2, 3>   &trial,
                        const SymmetricTensor<2, 3>   &stress,
                        const double                   JxW,
                        PlasticUpdate                 &result);

    /** Adds the stiffness, through @p constraints, to @p matrix. */
    template <typename MatrixType>
    void
    assemble_matrix(const AffineConstraints<double> &constraints,
                    MatrixType                      &matrix) const;

    /**
     * Physical constraints (hanging nodes, prescribed displacements with
     * their values at the functions' current time, point supports, platens)
     * and then @p pins.
     */
    void
    make_constraints(const BoundaryConditions<dim> &boundary_conditions,
                     const std::vector<types::global_dof_index> &pins);

    /** sigma_0 at @p point, zero without an in-situ stress. */
    SymmetricTensor<2, dim>
    initial_stress(const Point<dim> &point) const;

    /** The quadrature of the plastic state: QGauss(p + 1). */
    unsigned int
    n_plastic_points() const;

    /** D eps_p (3x3) at quadrature point @p q of cell @p cell. */
    SymmetricTensor<2, 3>
    plastic_stress(const unsigned int cell, const unsigned int q) const;

    std::unique_ptr<MohrCoulomb>       mohr_coulomb;
    std::vector<SymmetricTensor<2, 3>> plastic_strain_committed;
    std::vector<SymmetricTensor<2, 3>> plastic_strain;      // F(x)
    std::vector<SymmetricTensor<2, 3>> plastic_strain_load; // x
    std::vector<SymmetricTensor<2, 3>> plastic_residual;
    std::vector<SymmetricTensor<2, 3>> plastic_residual_previous;
    bool                               have_previous_residual = false;
    std::vector<bool>                  yielded;
    /**
     * Newton's method: at every point of the plastic state the consistent
     * tangent, whether it is a plastic one, and the strain and (in-plane)
     * stress it was taken at, the linearisation point u_j. The load then
     * carries int B^T (C_t - D) eps(u_j), so that the block's solve is
     * K_t u_{j+1} = f - f_int(u_j) + K_t u_j and keeps the form (and the
     * contact flexibility) of the elastic one.
     */
    struct Linearisation
    {
      std::vector<SymmetricTensor<4, dim>> tangent;
      std::vector<bool>                    plastic;
      std::vector<SymmetricTensor<2, dim>> strain;
      std::vector<SymmetricTensor<2, dim>> stress;
    };
    bool                    newton = false;
    SymmetricTensor<4, dim> elastic_tangent;
    Linearisation           linearisation;
    /** The linearisation at the last commit, for restore_plastic_state(). */
    Linearisation linearisation_committed;
    bool          tangent_is_stale = false;
    /** Whether the stiffness last assembled used a plastic tangent. */
    bool assembled_plastic_tangent = false;
    /** Initial-stress iterations for the rest of the step (suspend_newton). */
    bool                           newton_suspended = false;
    const InSituStress            *in_situ          = nullptr;
    const Excavation              *excavation       = nullptr;
    AffineConstraints<double>      physical_constraints;
    AffineConstraints<double>      constraints;
    AffineConstraints<double>      homogeneous_constraints;
    FloatingModes<dim>             floating;
    TrilinosWrappers::SparseMatrix stiffness;
    DirectSolver                   direct_solver;
    Vector<double>                 load;
    Vector<double>                 external_load;
    Vector<double>                 physical_load;
  };
} // namespace mbfem

#endif

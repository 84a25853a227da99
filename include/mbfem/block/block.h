#ifndef mbfem_block_block_h
#define mbfem_block_block_h

#include <mbfem/block/boundary_conditions.h>
#include <mbfem/block/flexibility.h>
#include <mbfem/block/floating_modes.h>
#include <mbfem/block/plastic_state.h>
#include <mbfem/linear_algebra/direct_solver.h>
#include <mbfem/material/in_situ_stress.h>
#include <mbfem/material/material.h>
#include <mbfem/material/plasticity.h>
#include <mbfem/mesh/mesh.h>

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

#include <limits>
#include <map>
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

    /** The degree of block @p id: its entry in block_degrees or degree. */
    unsigned int
    degree_of(const types::material_id id) const;

    /** The mapping degree of block @p id. */
    unsigned int
    mapping_degree_of(const types::material_id id) const;

    unsigned int degree         = 2;
    unsigned int mapping_degree = 2;
    /** 'Mapping degree = 0': each block's mapping has its own degree. */
    bool mapping_follows_degree = true;
    /** Block id -> degree, for the blocks that differ from degree. */
    std::map<unsigned int, unsigned int> block_degrees;
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
     * Takes the block's mesh from the whole @p mesh: its cells of material
     * id get_id(), with the faces it shares with other blocks marked
     * (extract_block()): how a multi-body problem gives each block its
     * mesh, from the block's own id.
     */
    void
    extract_mesh(const Triangulation<dim> &mesh);

    /**
     * Refines the block's own mesh @p times more ('Mesh/Block refinements'):
     * a finer block beside a coarse one, joined by a mortar interface.
     */
    void
    refine_mesh(const unsigned int times);

    /**
     * Builds the mesh of @p parameters as the block's mesh: for a problem
     * of one block (the order study, unit tests). Built in place, so that
     * a generator's manifolds that refer to their triangulation stay valid.
     */
    void
    create_mesh(const MeshParameters &parameters);

    /**
     * Puts the block on rank @p owner of @p comm (doc/parallel.md): only
     * that rank assembles and factorises its stiffness and solves with it;
     * on the others assemble_stiffness(), factorize() and solve() do
     * nothing, and share_solution() brings the owner's displacement. The
     * mesh, the DoFs and the constraints are on every rank, the loads
     * where assemble_load() is asked to put them there.
     * Before setup_system(); without it the block is this process's own.
     */
    void
    set_owner(const MPI_Comm comm, const unsigned int owner);

    /** Whether this rank owns the block (set_owner()). */
    bool
    is_local() const;

    /** The ranks that share the block, and its owner among them. */
    MPI_Comm
    get_communicator() const;

    unsigned int
    get_owner() const;

    /**
     * The work of factorising the block, for balancing blocks over ranks:
     * cells times DoFs per cell, known once the mesh is.
     */
    double
    cost() const;

    /**
     * Distributes DoFs on the mesh (from extract_mesh() or create_mesh()),
     * builds the constraints, finds the free rigid-body modes and pins
     * them.
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
     * The plastic and Newton state of the block (disabled for an elastic
     * block); the driver updates, relaxes, commits and restores it, the
     * block asks it at assembly. PlasticState::initialize() once the
     * triangulation is filled.
     */
    PlasticState<dim> &
    plastic_state();

    const PlasticState<dim> &
    plastic_state() const;

    /** Whether the block is elastic-perfectly plastic. */
    bool
    is_plastic() const;

    void
    assemble_stiffness();

    void
    factorize();

    /**
     * A block that a stage adds ('Load history/Added blocks'): it carries
     * no load before @p start, and its loads grow linearly from 0 at
     * @p start to full at @p end.
     */
    void
    set_added(const double start, const double end);

    /**
     * A block that a stage removes ('Load history/Removed blocks'): gone
     * after @p start, with no load.
     */
    void
    set_removed(const double start);

    /**
     * The fraction of its loads the block carries at @p time: 1 for a
     * block there from the start, 0 before a stage adds it and after one
     * removes it.
     */
    double
    presence(const double time) const;

    /**
     * Load vector and constraint values at pseudo-time @p time. With
     * @p on_every_rank false, another rank's block gets its constraints
     * only (its loads stay zero): the condensed formulation solves with
     * the load on the owner alone, and share_load_resultant() brings F_e.
     */
    void
    assemble_load(BoundaryConditions<dim> &boundary_conditions,
                  const double             time,
                  const bool               on_every_rank = true);

    /**
     * Adds point forces at DoFs (contact forces) to the current load; they
     * go through the constraints, so a force on a platen node loads the
     * platen.
     */
    void
    add_point_forces(const std::vector<types::global_dof_index> &dofs,
                     const std::vector<double>                  &forces);

    /**
     * Adds point forces that are part of the external load (water pressure
     * on the faces of a joint): to the load, to F_e and to the monolithic
     * system's physical load, after assemble_load().
     */
    void
    add_external_point_forces(const std::vector<types::global_dof_index> &dofs,
                              const std::vector<double> &forces);

    /**
     * solution = K^{-1} load, with the prescribed values filled in, plus
     * the rigid-body motion sum_i alpha_i floating_modes()[i] if given.
     */
    void
    solve(const std::vector<double> &alpha = {});

    /**
     * The owner's solution on every rank of the block's communicator
     * (set_owner()), after solve() on all of them: every rank calls it.
     */
    void
    share_solution();

    /**
     * The owner's external_load_resultant() on every rank of the block's
     * communicator, after assemble_load() and the point forces of the
     * external load on all of them: every rank calls it.
     */
    void
    share_load_resultant();

    /**
     * Replaces the solution by @p displacement (n_dofs() values, its
     * constraints distributed) solved for outside the block: the monolithic
     * system's, which has the block's DoFs among its unknowns.
     */
    void
    set_solution(Vector<double> &&displacement);

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
     * Whether the stiffness stays that of one factorisation (no plastic
     * tangent that changes): then a flexibility may be computed on demand
     * (on_demand_flexibility()), its columns long after the set-up.
     */
    bool
    has_fixed_stiffness() const;

    /**
     * Makes factorize() use MUMPS, for the block's solves too: a flexibility
     * on demand reads selected entries of K^{-1} from MUMPS's factorisation,
     * and one factorisation is then enough. Before factorize(), for a block
     * whose flexibility will be on demand; only with has_fixed_stiffness().
     */
    void
    set_flexibility_on_demand();

    /**
     * The flexibility over @p dofs with the block's MUMPS factorisation
     * kept, for columns on demand (ContactFlexibility). Without
     * set_flexibility_on_demand() before factorize(), the block's solves
     * move to MUMPS here: Amesos's factorisation is freed first, so that
     * the two are never held together.
     */
    std::unique_ptr<ContactFlexibility>
    on_demand_flexibility(const std::vector<types::global_dof_index> &dofs);

    /**
     * Virtual work of the external load of the last assemble_load() in each
     * floating mode: the paper's F_e. Zero for a held block. On another
     * rank's block, the value of the last share_load_resultant().
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

    /** The free modes with the frame they are taken in (FloatingModes). */
    const FloatingModes<dim> &
    get_floating_modes() const
    {
      return floating;
    }

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
     * The load of the last assemble_load() under the physical constraints
     * alone (the lifting of the prescribed displacements included, no
     * pins): the right-hand side of the block in the monolithic system.
     * The point forces of add_point_forces() are not in it.
     */
    const Vector<double> &
    get_physical_load() const;

    /**
     * Adds the stiffness (the tangent one with Newton's method), through
     * @p constraints, to @p matrix: the block's own pinned stiffness, or
     * with the physical constraints alone that of the monolithic system.
     * Instantiated for TrilinosWrappers::SparseMatrix and
     * SparseMatrix<double>.
     */
    template <typename MatrixType>
    void
    assemble_matrix(const AffineConstraints<double> &constraints,
                    MatrixType                      &matrix) const;

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

    /** The block's id: the material id of its cells in the whole mesh. */
    types::material_id
    get_id() const;

    /** The block's own mesh (coarse cells and the refinement). */
    const Triangulation<dim> &
    get_triangulation() const;

    /** The elastic constants and weight of the block. */
    const Material &
    get_material() const;

    /** FE_Q(p)^dim of the displacement. */
    const FESystem<dim> &
    get_fe() const;

    /** MappingQ of the geometry (curved faces stay curved). */
    const MappingQ<dim> &
    get_mapping() const;

    /** The DoFs of get_fe() on get_triangulation(). */
    const DoFHandler<dim> &
    get_dof_handler() const;

    /**
     * The displacement of the last solve() or set_solution(): the
     * response u_F to the load (condensed contact) or the total
     * displacement with the contact forces.
     */
    const Vector<double> &
    get_solution() const;

  private:
    const types::material_id id;
    Triangulation<dim>       triangulation;
    const Material           material;
    const FESystem<dim>      fe;
    const MappingQ<dim>      mapping;
    DoFHandler<dim>          dof_handler;
    Vector<double>           solution;

    /** The ranks that share the block, and the one that owns it. */
    MPI_Comm     communicator = MPI_COMM_SELF;
    unsigned int owner        = 0;
    bool         local        = true;

    /**
     * Cell stiffness from @p fe_values (already reinit'ed on the cell);
     * shared by the matrix and the load assembly.
     */
    void
    cell_matrix(const FEValues<dim> &fe_values,
                FullMatrix<double>  &matrix,
                const unsigned int   cell_index) const;

    /**
     * Physical constraints (hanging nodes, prescribed displacements with
     * their values at the functions' current time, point supports, platens)
     * and then @p pins.
     */
    void
    make_constraints(const BoundaryConditions<dim> &boundary_conditions,
                     const std::vector<types::global_dof_index> &pins);

    /**
     * X = K^{-1} B for @p n_vectors right-hand sides (column-major, leading
     * dimension n_dofs()) with the block's factorisation, whichever it is.
     */
    void
    solve_stiffness(double            *x,
                    const double      *b,
                    const unsigned int n_vectors) const;

    /** sigma_0 at @p point, zero without an in-situ stress. */
    SymmetricTensor<2, dim>
    initial_stress(const Point<dim> &point) const;

    using cell_iterator = typename DoFHandler<dim>::active_cell_iterator;

    /**
     * The steps of assemble_load(), one cell each, adding to @p cell_load:
     * gravity, the body force and the in-situ stress -int B^T sigma_0 in
     * the cell (@p fe_values reinit'ed on it)...
     */
    void
    add_volume_load(const FEValues<dim>           &fe_values,
                    const BoundaryConditions<dim> &boundary_conditions,
                    Vector<double>                &cell_load) const;

    /** ... int B^T s of the plastic state (PlasticState::load_stress())... */
    void
    add_plastic_load(const cell_iterator &cell,
                     FEValues<dim>       &state_values,
                     Vector<double>      &cell_load) const;

    /**
     * ... the in-situ stress on far-field boundaries and on the faces of an
     * excavation, released as @p time goes from 0 to 1...
     */
    void
    add_in_situ_boundary_load(const cell_iterator &cell,
                              const double         time,
                              FEFaceValues<dim>   &fe_face_values,
                              Vector<double>      &cell_load) const;

    /** ... and the tractions. */
    void
    add_traction_load(const cell_iterator           &cell,
                      const BoundaryConditions<dim> &boundary_conditions,
                      FEFaceValues<dim>             &fe_face_values,
                      Vector<double>                &cell_load) const;

    /**
     * Adds @p cell_load to the external load and, through the physical
     * constraints, to the physical load, with the lifting -K u_D where the
     * cell has a prescribed displacement.
     */
    void
    distribute_cell_load(const cell_iterator  &cell,
                         const Vector<double> &cell_load,
                         FEValues<dim>        &state_values);

    PlasticState<dim> plastic;
    /** The stage that adds the block, in t (see set_added()). */
    double added_from = -1., added_until = 0.;
    double removed_after = std::numeric_limits<double>::infinity();

    const InSituStress            *in_situ    = nullptr;
    const Excavation              *excavation = nullptr;
    AffineConstraints<double>      physical_constraints;
    AffineConstraints<double>      constraints;
    AffineConstraints<double>      homogeneous_constraints;
    FloatingModes<dim>             floating;
    TrilinosWrappers::SparseMatrix stiffness;
    /**
     * The stiffness's one factorisation: Amesos's, or MUMPS's once the
     * flexibility is on demand (shared with the ContactFlexibility objects,
     * which read selected entries of K^{-1} from it).
     */
    DirectSolver                 direct_solver;
    std::shared_ptr<MumpsSolver> mumps_solver;
    Vector<double>               load;
    Vector<double>               external_load;
    Vector<double>               physical_load;
    /** F_e as share_load_resultant() received it (another rank's block). */
    std::vector<double> shared_load_resultant;
  };
} // namespace mbfem

#endif

#ifndef mbfem_contact_condensed_system_h
#define mbfem_contact_condensed_system_h

#include <mbfem/block/block.h>
#include <mbfem/contact/contact_solver_parameters.h>
#include <mbfem/contact/interface_system.h>
#include <mbfem/contact/rigid_coupling.h>
#include <mbfem/interface/contact_interface.h>
#include <mbfem/interface/pair_equation.h>
#include <mbfem/linear_algebra/updated_lu.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The interface system of the multi-body method (paper eqs. 7-10, 15),
   * condensed onto the contact pairs through the blocks' flexibilities:
   *
   *   d = Delta_F + C_hat rho + P_hat alpha,   P_hat^T rho + F_e = 0,
   *
   * C_hat = R C_a R^T in the pairs' frames, kept per block so that its
   * memory is the sum over blocks of (contact DoFs of the block)^2, not
   * (all contact DoFs)^2. The unknowns of solve() are rho * scale() (a
   * displacement) and alpha, so that every entry is of unit order whatever
   * the model's units.
   */
  template <int dim>
  class CondensedSystem : public InterfaceSystem<dim>
  {
  public:
    /**
     * The system of @p pairs, whose floating modes @p coupling describes;
     * both must outlive it (ContactSolver owns all three).
     */
    CondensedSystem(const std::vector<ContactPair<dim>>       &pairs,
                    const RigidCoupling<dim>                  &coupling,
                    const ContactSolverParameters::StateSystem state_system);

    /**
     * C_hat from every block's factorisation (Block::flexibility()),
     * scale() and the held directions. @p coupling must be set up.
     */
    void
    setup(const std::vector<std::unique_ptr<Block<dim>>> &blocks) override;

    /** Delta_F, from each block's response u_F in its solution. */
    void
    set_load(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
             IncrementLoads                                 &loads) override;

    bool
    solve(const std::vector<PairEquation<dim>> &equations,
          const IncrementLoads                 &loads,
          Vector<double>                       &solution,
          Vector<double>                       &displacement) override;

    std::vector<std::array<bool, dim>>
    held() const override;

    /** Mean diagonal of C_hat: the scale of the forces in the system. */
    double
    scale() const;

    /**
     * Calls @p add(column, value) with @p factor times row (k, e) of
     * C_hat / scale(), over the columns (@p column_of) of the unknowns: a
     * row of a sparse system, only where two pairs share a block.
     */
    void
    add_row(
      const unsigned int                                           k,
      const unsigned int                                           e,
      const double                                                 factor,
      const std::vector<int>                                      &column_of,
      const std::function<void(const unsigned int, const double)> &add) const;

    /**
     * Computes, on blocks whose flexibility is on demand, the columns
     * H_b(., t f) for every k * dim + f of @p rows (side t of pair k on b)
     * not computed yet: one batch of solves per block. entry(), add_row()
     * and add_entries() read only computed columns, and under mpirun the
     * ranks other than a block's owner hold them at the rows of the sides
     * with a computed column only (BlockFlexibility::kept_rows): call this
     * first with the columns they will read.
     */
    void
    request_columns(const std::vector<unsigned int> &rows) const;

    /**
     * Whole or on demand (Contact/Flexibility columns; auto: on demand
     * from 500 contact DoFs, where Block::flexibility() would take the
     * MUMPS route); before setup().
     */
    void
    set_flexibility_columns(
      const ContactSolverParameters::FlexibilityColumns columns);

    /**
     * The contact DoFs of block @p b among @p pairs: those of the nodes of
     * its pair sides, each once, in the order of the pairs.
     */
    static std::vector<types::global_dof_index>
    contact_dofs(const std::vector<ContactPair<dim>> &pairs,
                 const unsigned int                   b);

    /**
     * Whether the flexibility of @p block over @p n_contact_dofs contact
     * DoFs is on demand under @p columns: the one rule, which also lets a
     * block choose its factorisation before it is computed
     * (Block::set_flexibility_on_demand()).
     */
    static bool
    is_on_demand(const Block<dim> &block,
                 const std::size_t n_contact_dofs,
                 const ContactSolverParameters::FlexibilityColumns columns);

    /** Whether every side of pair @p k is on a block on demand. */
    bool
    on_demand(const unsigned int k) const;

    /**
     * Columns of C_hat computed on demand so far, and how many the
     * blocks on demand have in all (0 and 0 where every H_b is whole).
     */
    std::pair<std::size_t, std::size_t>
    columns_on_demand() const;

    /** Adds every entry of C_hat to @p matrix, (row, column) -> value. */
    void
    add_entries(
      std::map<std::pair<unsigned int, unsigned int>, double> &matrix) const;

    /**
     * d = Delta_F + C_hat rho + P_hat alpha in the pairs' frames, for the
     * solution (rho, alpha) of a system.
     */
    Vector<double>
    relative_displacement(const Vector<double> &solution,
                          const IncrementLoads &loads) const;

  private:
    /**
     * H_b(s i, t j) = sign_s sign_t sum w w R_s[i] . C_b R_t[j] of one block
     * over the pair sides on it. C_hat of two pairs is the sum of H_b over
     * the blocks they share.
     */
    struct BlockFlexibility
    {
      /** The pair of each side on this block (a side per row group). */
      std::vector<unsigned int> pairs;
      /**
       * The block's ranks, and the one that computes H_b and its columns
       * (Block::set_owner()): the others receive them.
       */
      MPI_Comm     communicator = MPI_COMM_SELF;
      unsigned int owner        = 0;
      bool         local        = true;
      /** H_b whole, or empty where it is computed on demand. */
      FullMatrix<double> matrix;

      /**
       * On demand (Contact/Flexibility columns): the block's
       * flexibility, the rows of S over its DoFs, H_b's diagonal (sampled:
       * sampled_diagonal()), and the columns of
       * H_b computed so far (empty where not yet): only those of pairs
       * that carry force, so that memory grows with (sides x closed
       * sides), not (sides)^2.
       */
      std::unique_ptr<ContactFlexibility>      on_demand;
      std::vector<ContactLoad>                 rows;
      std::vector<double>                      diagonal;
      mutable std::vector<std::vector<double>> columns;

      /**
       * Under mpirun, on demand: the rows the iteration reads, those of
       * the sides with a computed column (every direction of such a
       * side), in the order they came, and each row's place among them
       * (-1 where not kept). On every rank; the ranks other than the
       * owner (compact) hold their columns at these rows only, so that no
       * rank holds the others' columns whole (relative_displacement() has
       * H_b f from the owner).
       */
      mutable std::vector<unsigned int> kept_rows;
      mutable std::vector<int>          kept_position;
      bool                              compact = false;

      /**
       * H_b(r, c); on demand, column c must have been computed, and on a
       * compact block row r kept.
       */
      double
      operator()(const unsigned int r, const unsigned int c) const
      {
        if (!on_demand)
          return matrix(r, c);
        if (!compact)
          return columns[c][r];
        Assert(kept_position[r] >= 0, ExcInternalError());
        return columns[c][kept_position[r]];
      }
    };

    /**
     * The system of the last solve(), LU-factorised: a trial whose
     * equations have the same coefficients (only their values differ)
     * reuses it. Dense in matrix, over the unknowns its states leave free
     * (the directions of the pairs that are not open, and the floating
     * modes); or sparse (see use_sparse()) over every pair direction and
     * floating mode, a removed unknown's row saying x_i = 0, in sparse
     * (then matrix is empty). Sparse, the factors are those of an earlier
     * system (base_coefficients) and the rows that changed since are
     * solved for by UpdatedLU, so that a trial that switches few pairs
     * costs substitutions, not a factorisation.
     */
    struct Factorisation
    {
      std::vector<double>        coefficients; // the key
      std::vector<unsigned int>  unknowns;     // active rows of rho
      unsigned int               size = 0;
      LAPACKFullMatrix<double>   matrix;
      bool                       dense = true;
      std::unique_ptr<UpdatedLU> sparse;
      /** The key of sparse's base; empty where it may not be updated. */
      std::vector<double> base_coefficients;
      /** Columns on demand computed when the base was assembled. */
      std::size_t base_columns = 0;
      bool        regular      = false;
    };
    /**
     * C_hat(k * dim + i, l * dim + j), from the blocks' H_b (columns on
     * demand computed first: request_columns()).
     */
    double
    entry(const unsigned int row, const unsigned int column) const;

    /** C_hat(i, i), from the whole H_b or the diagonal kept on demand. */
    double
    diagonal_entry(const unsigned int row) const;

    /** H_b's columns @p columns of an on-demand block, computed and kept. */
    void
    compute_columns(const BlockFlexibility          &flexibility,
                    const std::vector<unsigned int> &columns) const;

    /**
     * Under mpirun, before new @p columns of an on-demand block are
     * computed: their sides' rows added to the kept rows, and @p message
     * sized for share_columns() (room made, so that nothing is allocated
     * between the ranks' steps). Returns the columns computed before, in
     * increasing order.
     */
    std::vector<unsigned int>
    keep_rows(const BlockFlexibility          &flexibility,
              const std::vector<unsigned int> &columns,
              std::vector<double>             &message) const;

    /**
     * Under mpirun, H_b's new @p columns (computed by compute_columns() on
     * the block's owner) at every kept row, and the @p old columns at the
     * rows keep_rows() added, from the owner to every rank in
     * @p message.
     */
    void
    share_columns(const BlockFlexibility          &flexibility,
                  const std::vector<unsigned int> &columns,
                  const std::vector<unsigned int> &old,
                  const unsigned int               n_kept_before,
                  std::vector<double>             &message) const;

    /**
     * H_b f of a block at every row of its sides, from its forced columns,
     * f its sides' forces in @p solution; empty where no side has a force,
     * zeros on a compact block (the owner's come from
     * relative_displacement()).
     */
    std::vector<double>
    block_displacement(const BlockFlexibility &flexibility,
                       const Vector<double>   &solution) const;

    /**
     * setup(), per block: the pair sides on @p block (number @p b), and
     * H_b (or its diagonal on demand) where this rank owns the block. Not
     * const: on demand, the block's solves move to the factorisation the
     * columns come from (Block::on_demand_flexibility()).
     */
    void
    add_block(Block<dim> &block, const unsigned int b);

    /**
     * setup(), under mpirun: H_b (or its diagonal on demand) from each
     * block's owner to every rank, once all ranks have computed theirs.
     */
    void
    share_blocks();

    /**
     * H_b's diagonal on demand, for scale() and the held directions:
     * s^T C s for 32 of the sides' @p rows of each pair direction that
     * move (evenly spaced), their mean for that direction's other rows
     * that move, zero for those that do not (their load reaches no free
     * DoF).
     */
    static std::vector<double>
    sampled_diagonal(const ContactFlexibility       &flexibility,
                     const std::vector<ContactLoad> &rows);

    /** setup(), last: scale() and the held directions. */
    void
    find_held_directions();

    /** solve(), without d: (rho, alpha) into @p solution. */
    bool
    solve_forces(const std::vector<PairEquation<dim>> &equations,
                 const IncrementLoads                 &loads,
                 Vector<double>                       &solution);

    /**
     * The key of @p equations (their coefficients, and which rows say
     * rho_i = 0) and the rows left as @p unknowns.
     */
    void
    set_unknowns(const std::vector<PairEquation<dim>> &equations,
                 std::vector<double>                  &key,
                 std::vector<unsigned int>            &unknowns) const;

    /**
     * The factorisation of the system of @p equations with @p key, dense
     * or sparse (use_sparse()), the columns it reads computed first.
     */
    void
    set_system(const std::vector<PairEquation<dim>> &equations,
               const std::vector<double>            &key,
               const std::vector<unsigned int>      &unknowns);

    /** The right-hand side of the factorised system for @p loads. */
    Vector<double>
    right_hand_side(const std::vector<PairEquation<dim>> &equations,
                    const IncrementLoads                 &loads) const;

    /**
     * Builds and LU-factorises the system of @p equations over
     * system.unknowns; system.regular says whether it has a solution
     * (condition estimate below 1e12).
     */
    void
    assemble(const std::vector<PairEquation<dim>> &equations,
             Factorisation                        &system) const;

    /**
     * The same system as assemble(), sparse over every pair direction and
     * floating mode: the rows that changed since sparse's base replaced
     * (UpdatedLU), or, where they are too many or the change is nearly
     * singular, a new base factorised. system.regular as assemble() says.
     */
    void
    assemble_sparse(const std::vector<PairEquation<dim>> &equations,
                    Factorisation                        &system) const;

    /**
     * The columns of H_b that sparse_row() reads for the rows of
     * @p unknowns: every direction of their pairs, so that a pair whose
     * other directions become unknowns later finds its columns there (its
     * switch replaces its own rows, no new base).
     */
    std::vector<unsigned int>
    sparse_columns(const std::vector<unsigned int> &unknowns) const;

    /**
     * Row @p row of the sparse system of assemble_sparse() (columns
     * increasing; rows beyond n_pairs * dim the floating modes'), @p active
     * saying which rows are not x_i = 0. The columns of every pair
     * direction, open or not, whose H_b is whole or whose column was
     * computed (sparse_columns()), so that a pair that switches changes its
     * own rows only; on demand the columns of pairs never requested are
     * left out (their x_i = 0).
     */
    UpdatedLU::Row
    sparse_row(const std::vector<PairEquation<dim>> &equations,
               const std::vector<bool>              &active,
               const unsigned int                    row) const;

    /**
     * The sparse system's condition estimate over the unknowns left free:
     * estimate_condition()'s of the dense system, or, where rows were
     * replaced, UpdatedLU::condition_bound() where that is a hundred times
     * below the limit.
     */
    void
    estimate_sparse_condition(Factorisation &system) const;

    /**
     * Solves the sparse system in place (its unknowns, with x_i = 0 for
     * the removed ones). Where rows were replaced and the answer's backward
     * error is above 1e-10, factorises a new base and solves again (false
     * where that is not regular); a new base's answer is taken as a fresh
     * LU's always was.
     */
    bool
    solve_sparse(const std::vector<PairEquation<dim>> &equations,
                 Factorisation                        &system,
                 Vector<double>                       &x) const;

    /**
     * Whether the system over @p unknowns is factorised sparse: by the
     * State system parameter, or (auto) when it has at least 1000 unknowns
     * and at most a tenth of its entries can be non-zero (two pairs share
     * no block elsewhere).
     */
    bool
    use_sparse(const std::vector<unsigned int> &unknowns) const;

    /**
     * Adds H_b f to @p d for one block: f its sides' forces in
     * @p solution (relative_displacement()).
     */
    void
    add_block_displacement(const BlockFlexibility &flexibility,
                           const Vector<double>   &solution,
                           Vector<double>         &d) const;

    /** Sets system.regular from a condition estimate of the dense LU. */
    void
    estimate_condition(Factorisation &system, const double norm) const;

    const std::vector<ContactPair<dim>>        &pairs;
    const RigidCoupling<dim>                   &coupling;
    const unsigned int                          n_pairs;
    const ContactSolverParameters::StateSystem  state_system;
    ContactSolverParameters::FlexibilityColumns flexibility_columns =
      ContactSolverParameters::FlexibilityColumns::automatic;

    std::vector<BlockFlexibility> block_flexibility;
    /** For each pair, its sides: (index into block_flexibility, side). */
    std::vector<std::vector<std::pair<unsigned int, unsigned int>>> pair_sides;
    double                             flexibility_scale = 1.;
    std::vector<std::array<bool, dim>> held_directions;
    /** P_hat's non-zero entries: per pair direction, and per mode. */
    std::vector<UpdatedLU::Row> coupling_rows, coupling_columns;
    Factorisation               factorisation;
  };
} // namespace mbfem

#endif

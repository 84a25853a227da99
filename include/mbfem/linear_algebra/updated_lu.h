#ifndef mbfem_linear_algebra_updated_lu_h
#define mbfem_linear_algebra_updated_lu_h

#include <mbfem/linear_algebra/sparse_lu.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * Solves with a sparse matrix A that differs from a factorised base A_0
   * in a few rows, without factorising A: the rows i_1 ... i_m replaced,
   * A = A_0 + sum_a e_(i_a) d_a^T (d_a the new row minus the old), and by
   * the Sherman-Morrison-Woodbury formula
   *
   *   A^{-1} b = y - Z S^{-1} D y,  y = A_0^{-1} b,  Z = A_0^{-1} [e_(i_a)],
   *   S = I + D Z  (m x m, D the rows d_a^T).
   *
   * A column of Z is one substitution with A_0's factors, computed when its
   * row first changes and kept until the next factorisation, so a sequence
   * of matrices that each change one more pair's rows (the trial states of
   * the load path and the fast iteration, CondensedSystem) costs a few
   * substitutions per matrix instead of a factorisation (on the jointed
   * slope's 4442 unknowns a substitution takes about a fortieth of one).
   * The right-hand sides of a state iteration change only in the rows of
   * the pairs whose states changed, so A_0^{-1} b is remembered for the
   * last few b: where b differs from such a b_0 only in replaced rows,
   * y = y_0 + Z (b - b_0) without a substitution.
   * det A = det A_0 det S, so A is singular where S is; a nearly singular S
   * is refused (replace_rows() false) and the caller factorises A itself,
   * whose verdict is then the one of a fresh LU.
   */
  class UpdatedLU
  {
  public:
    /** A sparse row: (column, value), columns in increasing order. */
    using Row = std::vector<std::pair<unsigned int, double>>;

    /**
     * Factorises A_0 = @p rows (square) by SparseLU and forgets every
     * change. False where it is singular (a zero pivot).
     */
    bool
    factorize(const std::vector<Row> &rows);

    /** SparseLU::set_blocks() of the bases' factorisations. */
    void
    set_blocks(const unsigned int size, const unsigned int n_in_blocks);

    /** Whether a base is factorised. */
    bool
    factorized() const;

    /** The number of unknowns. */
    unsigned int
    size() const;

    /**
     * A = A_0 with rows @p indices (increasing) replaced by @p rows; every
     * other row as in A_0 (an earlier change is undone). False where the
     * change has more than max_rank() rows, S is nearly singular (|S^{-1}|
     * above 1e10, S being I where nothing changed) or condition_bound()
     * reaches 1e12: then factorise A.
     */
    bool
    replace_rows(const std::vector<unsigned int> &indices,
                 const std::vector<Row>          &rows);

    /** The rows replaced now (m). */
    unsigned int
    rank() const;

    /**
     * The largest change replace_rows() takes: m columns of Z cost m
     * substitutions and every solve 2 n m flops more, so a factorisation,
     * some substitutions_per_factorization() substitutions, is cheaper
     * beyond a fraction of that (at least 8, at most 200 rows).
     */
    unsigned int
    max_rank() const;

    /**
     * x = A^{-1} x in place, with up to two steps of iterative refinement
     * against A itself (none without @p refine, for a condition estimate's
     * probes). Returns the backward error
     * |b - A x|_inf / (|A|_inf |x|_inf + |b|_inf) of the answer, which a
     * caller compares with what it can accept (a backward stable LU gives
     * some 1e-16); 0 without @p refine. A refined solve remembers its
     * A_0^{-1} b (mutable state: not for concurrent calls).
     */
    double
    solve(Vector<double> &x, const bool refine = true) const;

    /**
     * The largest sum of absolute values in A's columns @p columns (true):
     * the 1-norm of the part of A that a caller solves with.
     */
    double
    l1_norm(const std::vector<bool> &columns) const;

    /** y = A x. */
    void
    vmult(Vector<double> &y, const Vector<double> &x) const;

    /**
     * A's condition number in the 1-norm bounded from above by A_0's and
     * S's and the norms of Z and D, |A|_1 <= |A_0|_1 + |D|_1 and
     * |A^{-1}|_1 <= |A_0^{-1}|_1 (1 + |Z|_1 |S^{-1}|_1 |D|_1), the inverses'
     * norms estimated from below by probes (so an estimate, within a small
     * factor: the unit test finds a factor 1.7 below the true value on a
     * random matrix). Where it is far below a limit, A is regular without
     * a condition estimate of its own.
     */
    double
    condition_bound() const;

    /** Factorisations, and Z columns computed, since construction. */
    std::pair<unsigned int, unsigned int>
    counts() const;

    /**
     * Calls of A_0's factors since construction (a refined one counts
     * once), and solves whose y = A_0^{-1} b came from a remembered one
     * instead.
     */
    std::pair<unsigned int, unsigned int>
    solve_counts() const;

  private:
    /**
     * x = A^{-1} x by the formula, not refined against A; with @p remember,
     * y = A_0^{-1} b from a remembered one where it can, else by a
     * substitution refined against A_0 (UMFPACK's own steps), which is then
     * remembered.
     */
    void
    apply_inverse(Vector<double> &x, const bool remember = false) const;

    /**
     * x = A_0^{-1} x from a remembered (b_0, y_0) whose b_0 equals x
     * outside the replaced rows; false where none does.
     */
    bool
    recall_base_solution(Vector<double> &x) const;

    /**
     * Row @p i of A_0 replaced by @p row (columns increasing): its
     * difference d and |row|_1 appended to the change.
     */
    void
    add_difference(const unsigned int i, const Row &row);

    /** Z's columns of rows no longer changed, once Z has grown large. */
    void
    drop_unused_columns();

    /** Z's columns of the changed rows not computed yet. */
    void
    compute_missing_columns();

    /**
     * The norms of condition_bound() for the present change, S's LU
     * computed.
     */
    void
    set_change_norms();

    /**
     * S = I + D Z of the present change, from @p last_entries (S of the
     * change @p last_changed with differences @p last_difference) where
     * they still hold.
     */
    void
    assemble_capacitance(const std::vector<unsigned int> &last_changed,
                         const std::vector<Row>          &last_difference,
                         const FullMatrix<double>        &last_entries);

    /** Back to A = A_0: no rows replaced (Z's columns are kept). */
    void
    forget_change();

    /** x = A_0^{-1} x by A_0's factors, counted. */
    void
    substitute(Vector<double> &x, const bool refine) const;

    /** |A|_inf, for the backward error. */
    double
    infinity_norm() const;

    /** The 1-norms of A_0 and (estimated from below) of its inverse. */
    void
    estimate_base_condition();


    SparsityPattern      pattern;
    SparseMatrix<double> base;
    /**
     * A base's pattern is analysed once (the unit rows move with the
     * states), so not UMFPACK's METIS option, whose analysis of A^T A's
     * pattern is dear where rows are long (with it against COLAMD: the
     * 5 x 5 x 5 cube 40.3 -> 30.1 s, the jointed slope 20.1 -> 21.5 s),
     * but the nested dissection of a merged graph (set_blocks()): METIS's
     * fill at COLAMD's cost (doc/state_iteration.md).
     */
    SparseLU lu{SparseLU::Ordering::nested_dissection};
    bool     is_factorized = false;
    double   base_norm     = 0.;
    /** A_0^{-1} e_i for the rows changed since the factorisation. */
    std::map<unsigned int, Vector<double>> z;
    /** The 1-norms of Z's columns, for condition_bound(). */
    std::map<unsigned int, double> z_norm;
    /** The change: rows i_a, their differences d_a, and S's LU. */
    std::vector<unsigned int> changed;
    std::vector<Row>          difference;
    std::vector<double>       changed_row_norm; // |new row|_1
    LAPACKFullMatrix<double>  capacitance;
    /** S's entries (capacitance holds its LU). */
    FullMatrix<double> capacitance_entries;
    unsigned int       n_factorizations = 0, n_columns = 0;
    /** (b_0, A_0^{-1} b_0), the most recent first, since the factorisation. */
    mutable std::vector<std::pair<Vector<double>, Vector<double>>>
                         base_solutions;
    mutable unsigned int n_substitutions = 0, n_recalled = 0;
    /** The norms of condition_bound(). */
    double base_l1_norm = 0., base_inverse_l1_norm = 0., change_l1_norm = 0.,
           z_l1_norm = 0., capacitance_inverse_l1_norm = 0.;
  };
} // namespace mbfem

#endif

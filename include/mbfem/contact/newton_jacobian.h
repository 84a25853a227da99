#ifndef mbfem_contact_newton_jacobian_h
#define mbfem_contact_newton_jacobian_h

#include <mbfem/linear_algebra/sparse_lu.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The linear algebra of the semismooth Newton method
   * (semismooth_newton.cc), sparse: the relative displacements
   * d = d_0 + A u, A holding the flexibility only where two pairs share a
   * block and the rigid-mode coupling of the pairs' blocks, and the
   * generalised Jacobian J, assembled row by row as J = D_u + D_d A on the
   * pairs' rows (D_u, D_d the joint law's derivatives, a pair's own
   * columns only) and the coupling's transpose on the floating blocks'
   * rows. A block touches few neighbours, so a Newton step costs one
   * sparse LU (UMFPACK) of a matrix whose rows hold a few blocks' contact
   * DoFs, not a dense LU over every pair: on the jointed slope's 1906
   * pairs, 4442 unknowns (doc/state_iteration.md).
   */
  class NewtonJacobian
  {
  public:
    /** A sparse row: (column, value). */
    using Row = std::vector<std::pair<unsigned int, double>>;

    /**
     * Sets up A from its non-zero rows (@p rows_of_a, one per pair
     * component; the rows of the floating blocks' unknowns beyond them are
     * zero) over @p n columns. Pair k's rows are k * @p block_size ... and
     * its own columns are in the pattern of J even where A has none there.
     * With @p mode_diagonal, so are the diagonal entries of the rows beyond
     * A's (the floating blocks' springs of the proximal iteration).
     */
    void
    reinit(const std::vector<Row> &rows_of_a,
           const unsigned int      n,
           const unsigned int      block_size,
           const bool              mode_diagonal = false);

    /** The number of unknowns. */
    unsigned int
    size() const;

    /** d = A u (zero beyond A's rows). */
    void
    multiply(const Vector<double> &u, Vector<double> &d) const;

    /** Zero J, to assemble it again. */
    void
    clear_jacobian();

    /** J(row, column) += value. */
    void
    add(const unsigned int row, const unsigned int column, const double value);

    /** J's @p row += @p factor times row @p source of A. */
    void
    add_row_of_a(const unsigned int row,
                 const unsigned int source,
                 const double       factor);

    /**
     * Solves J x = b in place (b in, x out). False where J is singular
     * (UMFPACK's zero pivot) or b or x is not finite. GMRES preconditioned
     * by the factors of an earlier J solves it first, where it converges
     * within a budget cheaper than a new factorisation (the Jacobians of
     * successive Newton steps, and of the solves after a joint breaks,
     * differ in few rows); else J is factorised. On that route a singular
     * J whose range holds b can give a solution (true): GMRES does not
     * test singularity.
     */
    bool
    solve(Vector<double> &b);

    /**
     * How many solves made a new LU, and how many used the old one (with
     * GMRES, or alone where J had not changed).
     */
    std::pair<unsigned int, unsigned int>
    solve_counts() const;

    /**
     * Levenberg and Marquardt's step: (J^T J + lambda diag(J^T J)) x =
     * -J^T F, as the sparse augmented system [I J; J^T -lambda D] [r; x] =
     * [-F; 0], which never forms J^T J. False where it is singular.
     */
    bool
    damped_least_squares(const Vector<double> &residual,
                         const double          lambda,
                         Vector<double>       &step);

  private:
    SparsityPattern      pattern;
    SparseMatrix<double> a_matrix, jacobian;
    /**
     * J's factors; where the pattern is kept, METIS's ordering serves every
     * J of it (with the zeros dropped, COLAMD's, analysed each time).
     */
    SparseLU     lu;
    unsigned int n_rows_of_a = 0;
    /**
     * A hash of each row of the J that lu holds the factors of (empty:
     * none), to count the rows changed since without a copy of J (on the
     * 1013-block wall a copy was 0.65 GB).
     */
    std::vector<std::uint64_t> factored_rows;
    /** Whether the next solve() factorises without trying GMRES first. */
    bool         refactorize_next = false;
    unsigned int n_factorized = 0, n_old_factors = 0;

    /** GMRES's iterations that cost less than about half a factorisation. */
    unsigned int
    gmres_budget() const;

    /** Each row's hash of J's values. */
    std::vector<std::uint64_t>
    row_hashes() const;

    /** The number of rows whose @p hashes differ from the J factorised. */
    unsigned int
    count_changed(const std::vector<std::uint64_t> &hashes) const;

    /**
     * J x = b by GMRES, right-preconditioned by the factors of the last J
     * factorised (J_0): J J_0^{-1} is the identity plus a matrix of rank
     * at most @p n_changed (the rows changed), so GMRES converges within
     * n_changed + 1 iterations in exact arithmetic, each iteration a
     * forward and a backward substitution. Returns its iterations, or
     * @p budget + 1 (b unchanged) where it did not reach GMRES's
     * |J x - b| <= 1e-12 |b| within @p budget, or the true residual
     * is above ten times that.
     */
    unsigned int
    solve_with_old_lu(Vector<double>    &b,
                      const unsigned int budget,
                      const unsigned int n_changed) const;
    /**
     * The Levenberg-Marquardt system [I J; J^T -lambda D], its pattern
     * built at its first use after reinit(), and its factors.
     */
    SparsityPattern      augmented_pattern;
    SparseMatrix<double> augmented;
    SparseLU             augmented_lu;
  };
} // namespace mbfem

#endif

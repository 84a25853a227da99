#ifndef mbfem_linear_algebra_sparse_lu_h
#define mbfem_linear_algebra_sparse_lu_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The LU factorisation of a deal.II SparseMatrix by UMFPACK, as
   * SparseDirectUMFPACK does it, with two differences that matter for the
   * semismooth Newton method's systems (NewtonJacobian):
   *
   * - METIS's nested dissection orders the unknowns (or, by the
   *   constructor's argument or set_ordering(), UMFPACK's default COLAMD,
   *   or METIS on a graph with singletons left out and a pair's directions
   *   merged, both cheap enough where the analysis is redone at every
   *   factorisation, the second with less fill). A
   * condensed system is a graph of blocks, each a dense clique of its pairs'
   * unknowns; on the jointed slope's Jacobian (4442 unknowns) METIS needs 1.5
   * times fewer flops than UMFPACK's default (COLAMD), on the
   * Levenberg-Marquardt system 2.7 times fewer (doc/state_iteration.md).
   * - The symbolic analysis (ordering, fronts) is kept and reused while
   *   the sparsity pattern stays the same, as it does over a Newton
   *   iteration, so the ordering's cost is paid once per pattern.
   */
  class SparseLU
  {
  public:
    /** The fill-reducing ordering of the symbolic analysis. */
    enum class Ordering
    {
      /** METIS's nested dissection (of A^T A's pattern, UMFPACK's way). */
      metis,
      /** UMFPACK's default: COLAMD (AMD where it takes A as symmetric). */
      amd,
      /**
       * METIS's nested dissection as the metis option, with singletons
       * and a pair's directions taken together first, so that it costs
       * little more than COLAMD: for an analysis at every factorisation.
       */
      nested_dissection
    };

    SparseLU(const Ordering ordering = Ordering::metis);

    SparseLU(const SparseLU &) = delete;

    SparseLU &
    operator=(const SparseLU &) = delete;

    ~SparseLU();

    /**
     * Factorises @p matrix (square). False where UMFPACK finds it
     * singular (a zero pivot); throws on UMFPACK's other errors. With
     * @p drop_zeros the entries that are exactly zero are left out of
     * UMFPACK's pattern (less fill where many are; the analysis is then
     * redone whenever the nonzeros move).
     */
    bool
    factorize(const SparseMatrix<double> &matrix,
              const bool                  drop_zeros = false);

    /**
     * The ordering of the next analysis (the kept one is dropped where it
     * changes).
     */
    void
    set_ordering(const Ordering new_ordering);

    /**
     * For the nested_dissection ordering: the first @p n_in_blocks rows
     * and columns come in blocks of @p size (a contact pair's directions),
     * which it keeps together. Without, each row is on its own.
     */
    void
    set_blocks(const unsigned int size, const unsigned int n_in_blocks);

    /**
     * x = A^{-1} x, in place, with the last factorisation; with @p refine
     * UMFPACK's iterative refinement (its default, up to two steps, each
     * a product with A and another substitution) improves it, which a
     * preconditioner does not need.
     */
    void
    solve(Vector<double> &x, const bool refine = true) const;

    /**
     * The last factorisation's flops over those of a substitution with its
     * factors (two per entry of L and U, a multiplication and an addition:
     * L's in the forward sweep, U's in the backward one; UMFPACK's own
     * count of a solve's flops agrees).
     */
    double
    substitutions_per_factorization() const;

    /**
     * Whether the last analysis used the nested_dissection ordering's
     * order (false where METIS failed and UMFPACK ordered instead, or for
     * the other orderings).
     */
    bool
    order_given() const;

    /** How often factorize() reused the symbolic analysis, and made one. */
    std::pair<unsigned int, unsigned int>
    symbolic_counts() const;

  private:
    /** Frees UMFPACK's objects. */
    void
    clear_symbolic();

    void
    clear_numeric();

    /** A^T in compressed columns (A's rows, columns sorted): UMFPACK's form. */
    std::vector<long>   column_start, row_index;
    std::vector<double> values;
    void               *symbolic = nullptr;
    void               *numeric  = nullptr;
    Ordering            ordering;
    unsigned int        block_size = 1, n_blocked = 0;
    bool                given_order = false;
    unsigned int        reused = 0, analysed = 0;
    /** UMFPACK's flops and entries of L and U of the last factorisation. */
    double factor_flops = 0., factor_entries = 0.;
  };
} // namespace mbfem

#endif

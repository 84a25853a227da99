#ifndef mbfem_linear_algebra_mumps_solver_h
#define mbfem_linear_algebra_mumps_solver_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <memory>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * A symmetric matrix factorised by MUMPS (Debian's libmumps-dev, one
   * process on MPI_COMM_SELF), called through its C API rather than
   * through Amesos, because the multi-body method needs what Amesos does
   * not expose: selected entries of the inverse (ICNTL(30)). A block's
   * contact flexibility is (K^{-1}) restricted to its contact DoFs, which
   * MUMPS computes with sparse right-hand sides and pruned triangular
   * solves, several times cheaper than solving against dense unit loads
   * (design.md section 4: 5.0 s against 11.8 s for 4131 contact DoFs of a
   * 37,179-DoF block; the Schur complement of ICNTL(19) and its inverse,
   * the other road, 5.3 s). A block whose flexibility is on demand also
   * solves with it (Block::set_flexibility_on_demand()), so that it holds
   * one factorisation, not this one beside Amesos's.
   *
   * Debian's MUMPS has no METIS or SCOTCH: the ordering is PORD. Not
   * thread-safe: one object is used by one thread at a time.
   */
  class MumpsSolver
  {
  public:
    MumpsSolver();

    ~MumpsSolver();

    MumpsSolver(const MumpsSolver &) = delete;
    MumpsSolver &
    operator=(const MumpsSolver &) = delete;

    /**
     * Analysis and factorisation of the symmetric @p matrix (its upper
     * triangle is read): LDL^T without pivoting if @p positive_definite,
     * with pivoting otherwise. Throws ExcSingularMatrix if singular.
     */
    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix,
              const bool                            positive_definite = true);

    /**
     * X = A^{-1} B for @p n_vectors dense right-hand sides stored one after
     * the other in @p b (column-major, leading dimension size()).
     */
    void
    solve(double *x, const double *b, const unsigned int n_vectors) const;

    /**
     * The entries (A^{-1})_{ij} for i in @p rows and j in @p columns, from
     * the factorisation (ICNTL(30)).
     */
    FullMatrix<double>
    inverse_entries(const std::vector<unsigned int> &rows,
                    const std::vector<unsigned int> &columns) const;

    /**
     * The entries (A^{-1})_{ij} for i in @p rows_of_column[j], every column
     * j < size() (none where empty): a sparse pattern, such as the small
     * diagonal blocks of a flexibility, far cheaper than whole columns. The
     * rows of a column must be distinct; the values come in their order.
     */
    std::vector<std::vector<double>>
    inverse_entries(
      const std::vector<std::vector<unsigned int>> &rows_of_column) const;

    std::size_t
    size() const;

  private:
    struct Data;

    /** Copies the upper triangle into MUMPS's coordinate arrays. */
    void
    set_matrix(const TrilinosWrappers::SparseMatrix &matrix);

    /** Runs job @p job; throws with MUMPS's INFOG(1), INFOG(2) if < 0. */
    void
    run(const int job, const char *what) const;

    /**
     * ICNTL(30): the entries of A^{-1} whose (1-based) rows @p indices
     * lists per column between @p pointers (compressed columns over all
     * columns), into @p values in the same order.
     */
    void
    selected_entries(std::vector<int>    &pointers,
                     std::vector<int>    &indices,
                     std::vector<double> &values) const;

    std::unique_ptr<Data> data;
  };
} // namespace mbfem

#endif

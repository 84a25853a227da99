#ifndef mbfem_linear_algebra_convex_qp_h
#define mbfem_linear_algebra_convex_qp_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * A dense convex quadratic program
   *
   *   min 1/2 x^T H x + c^T x   s.t.   A x = b,   C x <= d,
   *
   * H symmetric positive semidefinite, the rows of C sparse (a few entries
   * each), solved by Mehrotra's primal-dual interior-point method (Nocedal
   * and Wright, Numerical Optimization, 16.6), each step an LU of the
   * reduced KKT matrix [H + C^T D C, A^T; A, 0] by LAPACK. Written for De
   * Saxce's fixed point, whose QPs are small and dense (a few hundred
   * pairs): Debian's QP solvers did not serve there (doc/decisions.md,
   * "The QPs of De Saxce's fixed point").
   */
  class ConvexQp
  {
  public:
    /** A row of C: its entries (column, value) and d. */
    struct Row
    {
      std::vector<std::pair<unsigned int, double>> entries;
      double                                       bound = 0.;
    };

    FullMatrix<double> H, A;
    Vector<double>     c, b;
    std::vector<Row>   rows;

    /** How solve() ended. */
    enum class Status
    {
      optimal,
      infeasible,
      stalled
    };

    /**
     * Solves to @p tolerance (residuals relative to the data, and the mean
     * complementarity); x, y (A's multipliers) and z (C's), with
     * H x + c + A^T y + C^T z = 0.
     */
    Status
    solve(const double tolerance, const unsigned int max_iterations = 100);

    Vector<double> x, y, z;
    unsigned int   iterations = 0;

  private:
    /** The residuals of the KKT conditions at (x, y, z, s). */
    struct Residuals
    {
      Vector<double> dual, equality, inequality;
    };

    /** A step in (x, y, z, s). */
    struct Step
    {
      Vector<double> x, y, z, s;
    };

    void
    residuals(const Vector<double> &s, Residuals &r) const;

    /** The reduced KKT matrix at (z, s), LU-factorised; false if singular. */
    bool
    factorise(const Vector<double> &s, LAPACKFullMatrix<double> &K) const;

    /** The step for the complementarity right-hand side @p r_c. */
    void
    newton_step(const LAPACKFullMatrix<double> &K,
                const Vector<double>           &s,
                const Residuals                &r,
                const Vector<double>           &r_c,
                Step                           &step) const;

    /** C v and C^T w. */
    void
    multiply_rows(const Vector<double> &v, Vector<double> &out) const;
    void
    multiply_rows_transposed(const Vector<double> &w,
                             Vector<double>       &out) const;
  };
} // namespace mbfem

#endif

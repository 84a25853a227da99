#ifndef mbfem_linear_algebra_direct_solver_h
#define mbfem_linear_algebra_direct_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace mbfem
{
  using namespace dealii;

  /**
   * A sparse direct solver from Trilinos' Amesos, used through the Epetra
   * matrix inside deal.II's TrilinosWrappers::SparseMatrix.
   *
   * The multi-body method factorises each block's stiffness once and then
   * solves it against many right-hand sides (the external load of every
   * increment and one unit load per contact degree of freedom), so this
   * class separates factorize() from solve() and solves whole blocks of
   * right-hand sides in one call. deal.II 9.4's SolverDirect solves only
   * one vector at a time.
   */
  class DirectSolver
  {
  public:
    struct Parameters
    {
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm);

      /** Amesos package name, e.g. "Amesos_Klu" or "Amesos_Mumps". */
      std::string package = "Amesos_Klu";
    };

    explicit DirectSolver(const std::string &package = "Amesos_Klu");

    ~DirectSolver();

    /**
     * Symbolic and numeric factorisation of @p matrix, which must stay alive
     * as long as this object solves with it. Throws with a message if the
     * matrix is singular (a block whose supports leave a rigid motion).
     */
    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix);

    /** x = A^{-1} b. */
    void
    solve(Vector<double> &x, const Vector<double> &b) const;

    /**
     * X = A^{-1} B for @p n_vectors right-hand sides stored one after the
     * other (column-major, leading dimension = matrix size) in @p b.
     */
    void
    solve(double *x, const double *b, const unsigned int n_vectors) const;

    /**
     * Frees the factorisation (size() is then 0): for a block whose solves
     * move to another one (Block::on_demand_flexibility()).
     */
    void
    clear();

    std::size_t
    size() const;

  private:
    std::string                           package;
    const TrilinosWrappers::SparseMatrix *matrix = nullptr;
    std::unique_ptr<Epetra_LinearProblem> linear_problem;
    std::unique_ptr<Amesos_BaseSolver>    solver;
  };
} // namespace mbfem

#endif

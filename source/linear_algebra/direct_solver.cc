#include <mbfem/base/exceptions.h>
#include <mbfem/linear_algebra/direct_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>

namespace mbfem
{
  void
  DirectSolver::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    {
      prm.declare_entry(
        "Direct solver",
        "Amesos_Klu",
        Patterns::Selection("Amesos_Klu|Amesos_Mumps"),
        "Trilinos Amesos sparse direct solver used to factorise each block's "
        "stiffness once (then reused for every load increment and unit "
        "load). KLU is serial and robust; MUMPS uses nested dissection and "
        "is faster on large 3D blocks.");
    }
    prm.leave_subsection();
  }



  void
  DirectSolver::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    package = prm.get("Direct solver");
    prm.leave_subsection();
  }



  DirectSolver::DirectSolver(const std::string &package)
    : package(package)
  {}



  DirectSolver::~DirectSolver() = default;



  void
  DirectSolver::factorize(const TrilinosWrappers::SparseMatrix &A)
  {
    // A solver refers to its linear problem (MUMPS even in its
    // destructor): release the old solver before the old problem.
    solver.reset();
    matrix         = &A;
    linear_problem = std::make_unique<Epetra_LinearProblem>();
    // Amesos wants a non-const operator but does not change it.
    linear_problem->SetOperator(
      const_cast<Epetra_CrsMatrix *>(&A.trilinos_matrix()));

    Amesos factory;
    AssertThrow(factory.Query(package.c_str()),
                ExcMessage("The Trilinos installation has no " + package +
                           " (Linear solver/Direct solver)."));
    solver.reset(factory.Create(package.c_str(), *linear_problem));
    AssertThrow(solver != nullptr,
                ExcMessage("Could not create the direct solver " + package));

    int ierr = solver->SymbolicFactorization();
    AssertThrow(ierr == 0,
                ExcMessage("Symbolic factorisation failed in " + package +
                           " (error " + std::to_string(ierr) + ")."));
    ierr = solver->NumericFactorization();
    AssertThrow(ierr == 0,
                Exceptions::ExcSingularMatrix(
                  "The stiffness matrix is singular (" + package + " error " +
                  std::to_string(ierr) +
                  "): the supports leave a rigid-body motion free."));
  }



  void
  DirectSolver::solve(Vector<double> &x, const Vector<double> &b) const
  {
    Assert(x.size() == size() && b.size() == size(),
           ExcDimensionMismatch(x.size(), size()));
    solve(x.data(), b.data(), 1);
  }



  void
  DirectSolver::solve(double            *x,
                      const double      *b,
                      const unsigned int n_vectors) const
  {
    Assert(solver != nullptr, ExcMessage("factorize() first."));
    if (n_vectors == 0)
      return;
    const Epetra_Map &map = matrix->trilinos_matrix().RangeMap();
    const int         n   = map.NumMyElements();

    // View, not copy: Amesos writes the solution straight into x.
    Epetra_MultiVector X(View, map, x, n, n_vectors);
    Epetra_MultiVector B(View, map, const_cast<double *>(b), n, n_vectors);
    linear_problem->SetLHS(&X);
    linear_problem->SetRHS(&B);
    const int ierr = solver->Solve();
    AssertThrow(ierr == 0,
                ExcMessage("The direct solve failed (" + package + " error " +
                           std::to_string(ierr) + ")."));
    linear_problem->SetLHS(nullptr);
    linear_problem->SetRHS(nullptr);
  }



  void
  DirectSolver::clear()
  {
    // The solver before its problem, as in factorize().
    solver.reset();
    linear_problem.reset();
    matrix = nullptr;
  }



  std::size_t
  DirectSolver::size() const
  {
    return matrix == nullptr ? 0 : matrix->m();
  }
} // namespace mbfem

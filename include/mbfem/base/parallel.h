#ifndef mbfem_base_parallel_h
#define mbfem_base_parallel_h

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The few things the multi-body method does across MPI ranks (issue 30,
   * doc/parallel.md): each block lives on one rank, its owner, which alone
   * factorises its stiffness and solves with it; what the other ranks need
   * of it (its displacement, its flexibility) is broadcast from there, so
   * that every rank holds the same interface system and runs the same
   * contact iteration. On one process every call is a plain call.
   */
  namespace Parallel
  {
    /** The number of ranks of MPI_COMM_WORLD; 1 before MPI_Init. */
    unsigned int
    n_ranks();

    /**
     * The owner rank of each block, balanced by @p costs (one per block)
     * over @p n_ranks: the largest block first, each to the least loaded
     * rank. The same on every rank.
     */
    std::vector<unsigned int>
    assign_owners(const std::vector<double> &costs, const unsigned int n_ranks);

    /**
     * Runs @p work on every rank of @p comm. An exception on any of them
     * ends the call on all: the lowest rank that failed rethrows its own,
     * the others throw its message (as ExcSingularMatrix if it was one,
     * so that the same handler catches it everywhere). Without this, an
     * error on one rank would leave the others waiting for its results.
     */
    void
    together(const MPI_Comm comm, const std::function<void()> &work);

    /**
     * Runs @p work on rank @p owner of @p comm, with together()'s
     * handling of an exception there.
     */
    void
    on_owner(const MPI_Comm               comm,
             const unsigned int           owner,
             const std::function<void()> &work);

    /** @p values (sized alike on every rank) from rank @p owner. */
    void
    broadcast(const MPI_Comm     comm,
              const unsigned int owner,
              double            *values,
              const std::size_t  n);

    void
    broadcast(const MPI_Comm     comm,
              const unsigned int owner,
              Vector<double>    &values);

    void
    broadcast(const MPI_Comm      comm,
              const unsigned int  owner,
              FullMatrix<double> &values);

    /**
     * Throws unless @p values (a hash of them) are the same on every rank
     * of MPI_COMM_WORLD: the check that the ranks' contact iterations, fed
     * the same data, took the same states (@p what names the values).
     */
    void
    check_same_on_all_ranks(const std::vector<unsigned long long> &values,
                            const std::string                     &what);
  } // namespace Parallel
} // namespace mbfem

#endif

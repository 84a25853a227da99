#include <mbfem/base/exceptions.h>
#include <mbfem/base/hash.h>
#include <mbfem/base/parallel.h>

#include <algorithm>
#include <exception>
#include <limits>
#include <new>
#include <numeric>

namespace mbfem
{
  namespace Parallel
  {
    namespace
    {
      /** Whether MPI calls may be made (between MPI_Init and its end). */
      bool
      running()
      {
        int initialised = 0, finalised = 0;
        MPI_Initialized(&initialised);
        MPI_Finalized(&finalised);
        return initialised != 0 && finalised == 0;
      }

      /** How the owner's work ended, as on_owner() passes it on. */
      enum Failure : int
      {
        none     = 0,
        other    = 1,
        singular = 2,
        memory   = 3
      };
    } // namespace



    unsigned int
    n_ranks()
    {
      return running() ? Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) : 1;
    }



    std::vector<unsigned int>
    assign_owners(const std::vector<double> &costs, const unsigned int n_ranks)
    {
      std::vector<unsigned int> order(costs.size());
      std::iota(order.begin(), order.end(), 0);
      // Largest first; equal costs in block order, so every rank agrees.
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const unsigned int a, const unsigned int b) {
                         return costs[a] > costs[b];
                       });
      std::vector<double>       load(std::max(1u, n_ranks), 0.);
      std::vector<unsigned int> owner(costs.size(), 0);
      for (const unsigned int b : order)
        {
          const auto rank =
            std::min_element(load.begin(), load.end()) - load.begin();
          owner[b] = rank;
          load[rank] += costs[b];
        }
      return owner;
    }



    void
    together(const MPI_Comm comm, const std::function<void()> &work)
    {
      if (!running() || Utilities::MPI::n_mpi_processes(comm) == 1)
        {
          work();
          return;
        }
      const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
      int                failure = none;
      std::string        message;
      std::exception_ptr caught;
      try
        {
          work();
        }
      catch (const Exceptions::ExcSingularMatrix &e)
        {
          failure = singular;
          message = message_of(e);
          caught  = std::current_exception();
        }
      catch (const ExceptionBase &e)
        {
          failure = other;
          message = message_of(e);
          caught  = std::current_exception();
        }
      catch (const std::bad_alloc &)
        {
          failure = memory;
          caught  = std::current_exception();
        }
      catch (const std::exception &e)
        {
          failure = other;
          message = e.what();
          caught  = std::current_exception();
        }
      catch (...)
        {
          failure = other;
          message = "An exception that mbfem does not know ended the work "
                    "of MPI rank " +
                    std::to_string(rank) + ".";
          caught = std::current_exception();
        }
      // The lowest rank that failed speaks for all.
      const unsigned int size = Utilities::MPI::n_mpi_processes(comm);
      const unsigned int first =
        Utilities::MPI::min(failure == none ? size : rank, comm);
      if (first == size)
        return;
      MPI_Bcast(&failure, 1, MPI_INT, first, comm);
      // Without the end of line that print_info() left: the exception
      // thrown below adds its own.
      message.erase(message.find_last_not_of(" \n") + 1);
      message = Utilities::MPI::broadcast(comm, message, first);
      if (rank == first)
        std::rethrow_exception(caught);
      if (failure == memory)
        throw std::bad_alloc();
      if (failure == singular)
        AssertThrow(false, Exceptions::ExcSingularMatrix(message));
      AssertThrow(false, ExcMessage(message));
    }



    void
    on_owner(const MPI_Comm               comm,
             const unsigned int           owner,
             const std::function<void()> &work)
    {
      together(comm, [&]() {
        if (!running() || Utilities::MPI::this_mpi_process(comm) == owner)
          work();
      });
    }



    void
    broadcast(const MPI_Comm     comm,
              const unsigned int owner,
              double            *values,
              const std::size_t  n)
    {
      if (!running() || Utilities::MPI::n_mpi_processes(comm) == 1)
        return;
      // MPI counts are int: large arrays go in pieces.
      constexpr std::size_t piece = std::size_t(1) << 27; // 1 GiB
      for (std::size_t first = 0; first < n; first += piece)
        MPI_Bcast(values + first,
                  static_cast<int>(std::min(piece, n - first)),
                  MPI_DOUBLE,
                  owner,
                  comm);
    }



    void
    broadcast(const MPI_Comm     comm,
              const unsigned int owner,
              Vector<double>    &values)
    {
      broadcast(comm, owner, values.data(), values.size());
    }



    void
    broadcast(const MPI_Comm      comm,
              const unsigned int  owner,
              FullMatrix<double> &values)
    {
      if (!values.empty())
        broadcast(comm, owner, &values(0, 0), values.n_elements());
    }



    void
    check_same_on_all_ranks(const std::vector<unsigned long long> &values,
                            const std::string                     &what)
    {
      if (n_ranks() == 1)
        return;
      std::uint64_t hash = Hash::start;
      for (const unsigned long long value : values)
        hash = Hash::add(hash, value);
      unsigned long long low = hash, high = hash;
      MPI_Allreduce(
        MPI_IN_PLACE, &low, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
      MPI_Allreduce(MPI_IN_PLACE,
                    &high,
                    1,
                    MPI_UNSIGNED_LONG_LONG,
                    MPI_MAX,
                    MPI_COMM_WORLD);
      AssertThrow(low == high,
                  ExcMessage("The MPI ranks disagree on " + what +
                             ", although each ran the same contact iteration "
                             "on the same data: a defect of mbfem; please "
                             "report it with the parameter file and the "
                             "number of ranks."));
    }
  } // namespace Parallel
} // namespace mbfem

#include <mbfem/base/interruption.h>
#include <mbfem/base/parallel.h>

#include <csignal>
#include <cstdio>

namespace mbfem
{
  namespace
  {
    volatile std::sig_atomic_t signal_received = 0;

    extern "C" void
    record_signal(const int signal)
    {
      signal_received = signal;
    }

    /** Blocks (SIG_BLOCK) or unblocks (SIG_UNBLOCK) SIGINT and SIGTERM. */
    void
    mask_termination_signals(const int how)
    {
      sigset_t signals;
      sigemptyset(&signals);
      sigaddset(&signals, SIGINT);
      sigaddset(&signals, SIGTERM);
      sigprocmask(how, &signals, nullptr);
    }
  } // namespace



  void
  catch_termination_signals()
  {
    struct sigaction action = {};
    action.sa_handler       = record_signal;
    sigemptyset(&action.sa_mask);
    // SA_RESETHAND: a second signal takes the default action (ends the run).
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    mask_termination_signals(SIG_UNBLOCK); // one held back arrives now
  }



  void
  hold_termination_signals()
  {
    mask_termination_signals(SIG_BLOCK);
  }



  void
  release_termination_signals()
  {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }



  int
  received_signal()
  {
    return signal_received;
  }



  void
  stop_if_signalled(const int last_complete_increment)
  {
    // The screen line of the increment reaches a log file now, not when
    // a buffer fills.
    std::fflush(stdout);
    // Under mpirun the ranks stop together, at the same check, if any of
    // them was signalled.
    int signal = signal_received;
    if (Parallel::n_ranks() > 1)
      MPI_Allreduce(MPI_IN_PLACE, &signal, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (signal != 0)
      throw Interrupted{signal, last_complete_increment};
  }
} // namespace mbfem

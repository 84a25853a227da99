#ifndef mbfem_base_interruption_h
#define mbfem_base_interruption_h

namespace mbfem
{
  /**
   * Makes SIGINT and SIGTERM end a simulation between increments instead of
   * in the middle of one: the handler only records the signal (no I/O is
   * safe in it), the load stepping checks it once an increment is written
   * (stop_if_signalled()), and main() exits with 128 + the signal. A second
   * signal ends the run at once, as without the handler.
   */
  void
  catch_termination_signals();

  /**
   * Holds SIGINT and SIGTERM back (blocks them) until
   * catch_termination_signals(): Open MPI's start-up sets them to their
   * default action, so a signal then killed mbfem in the middle of it (and
   * Open MPI's daemon reported a broken pipe). A signal held back is
   * delivered to mbfem's handler once it is installed.
   */
  void
  hold_termination_signals();

  /**
   * Gives SIGINT and SIGTERM their default action again (the run ends at
   * once), for work that has no increments to finish (the order study).
   */
  void
  release_termination_signals();

  /** The signal received since catch_termination_signals(), or 0. */
  int
  received_signal();

  /** Thrown by stop_if_signalled(); caught by main(). */
  struct Interrupted
  {
    int signal;
    /**
     * -1: stopped during the set-up, before any increment was written;
     * -2: during a trial of strength reduction (nothing written).
     */
    int last_complete_increment;
  };

  /**
   * Throws Interrupted if a signal arrived. Call it when increment
   * @p last_complete_increment is solved and all its files are written, or
   * with -1 between the steps of the set-up (mesh, blocks, flexibilities),
   * so that a signal during a long set-up ends the run there.
   */
  void
  stop_if_signalled(const int last_complete_increment);
} // namespace mbfem

#endif

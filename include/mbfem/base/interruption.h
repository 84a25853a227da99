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

  /** The signal received since catch_termination_signals(), or 0. */
  int
  received_signal();

  /** Thrown by stop_if_signalled(); caught by main(). */
  struct Interrupted
  {
    int          signal;
    unsigned int last_complete_increment;
  };

  /**
   * Throws Interrupted if a signal arrived. Call it when increment
   * @p last_complete_increment is solved and all its files are written.
   */
  void
  stop_if_signalled(const unsigned int last_complete_increment);
} // namespace mbfem

#endif

#ifndef mbfem_base_exceptions_h
#define mbfem_base_exceptions_h

#include <deal.II/base/exceptions.h>

#include <string>

namespace mbfem
{
  using namespace dealii;

  /**
   * The failures a smaller load step or another method may cure, as types,
   * so that step halving and Newton's fallback catch exactly these and let
   * everything else (bad input, programming errors) end the run.
   */
  namespace Exceptions
  {
    /**
     * An iteration (contact states, plastic strain) stopped without
     * converging: the states cycle, or the iteration count ran out. Not a
     * statement that no solution exists.
     */
    DeclException1(ExcIncrementNotConverged, std::string, << arg1);

    /**
     * The increment has no solution with the states tried: a floating
     * block is not held, or the interface system is singular.
     */
    DeclException1(ExcNoEquilibrium, std::string, << arg1);

    /** A sparse or dense factorisation met a zero pivot. */
    DeclException1(ExcSingularMatrix, std::string, << arg1);
  } // namespace Exceptions

  /** The text of a deal.II exception, without its leading blank lines. */
  std::string
  message_of(const ExceptionBase &e);
} // namespace mbfem

#endif

#ifndef mbfem_base_exceptions_h
#define mbfem_base_exceptions_h

#include <deal.II/base/exceptions.h>

#include <sstream>
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
     * block is not held, or the interface system is singular. Once the
     * run ends with it (after any step halvings), the statics certificate
     * has proved it: no contact forces within the joints' strength
     * balance the floating blocks' loads (exit code 2).
     */
    DeclException1(ExcNoEquilibrium, std::string, << arg1);

    /**
     * No equilibrium once the joints the increment's load path broke have
     * lost their strength, where rigid-block statics with them whole
     * admits forces (exit code 2 too): a verdict for the path's history
     * (doc/decisions.md, "Joints the load path broke"), which strength
     * reduction reports as such.
     */
    class ExcNoEquilibriumAfterBreaking : public ExcNoEquilibrium
    {
    public:
      using ExcNoEquilibrium::ExcNoEquilibrium;
    };

    /**
     * An increment failed for good (after any step halvings), although the
     * statics certificate found contact forces within the joints' strength
     * that balance the floating blocks, and so does limit equilibrium along
     * the mechanism of the statics limit: most likely the iteration, not
     * the model, is at fault (exit code 3).
     */
    DeclException1(ExcNotConvergedButAdmissible, std::string, << arg1);

    /**
     * An increment failed for good, statics alone admits forces, but limit
     * equilibrium along the mechanism of the statics limit (shear against
     * the slip, as in Hoek and Bray's wedge analysis) does not: the blocks
     * cannot move that way in equilibrium. A kinematic verdict, weaker than
     * exit code 2's: another state might hold them (exit code 4).
     */
    DeclException1(ExcNoEquilibriumAlongMechanism, std::string, << arg1);

    /** A sparse or dense factorisation met a zero pivot. */
    DeclException1(ExcSingularMatrix, std::string, << arg1);
  } // namespace Exceptions

  /**
   * The exit code that tells how a run failed: 2 no equilibrium
   * (certified by statics), 4 none along the mechanism of the statics
   * limit (limit equilibrium), 3 the iteration failed although both admit
   * forces, 1 anything else.
   */
  int
  exit_code(const ExceptionBase &e);

  /** The text of a deal.II exception, without its leading blank lines. */
  std::string
  message_of(const ExceptionBase &e);

  /**
   * Holds back what is written to std::cerr while it lives. deal.II's
   * FunctionParser prints muparser's error dump there before it throws; the
   * error reaches the user once, in mbfem's own message.
   */
  class QuietCerr
  {
  public:
    QuietCerr();
    ~QuietCerr();

  private:
    std::ostringstream held;
    std::streambuf    *original;
  };
} // namespace mbfem

#endif

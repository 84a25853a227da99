#ifndef mbfem_contact_contact_solver_parameters_h
#define mbfem_contact_contact_solver_parameters_h

#include <mbfem/contact/state_method.h>

#include <deal.II/base/parameter_handler.h>

namespace mbfem
{
  using namespace dealii;

  /**
   * The contact solver's entries of subsection "Contact": how the
   * interface system is formed and solved, and the state methods. The
   * interfaces themselves and their joint laws are ContactParameters'
   * (mbfem/interface/contact_interface.h), which shares the subsection.
   */
  struct ContactSolverParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    unsigned int max_iterations = 100;
    /** Which formulations run (see the entry's text). */
    enum class Formulation : unsigned char
    {
      condensed,
      monolithic,
      both
    };
    Formulation formulation = Formulation::condensed;

    /**
     * How the condensed state system is factorised: dense LU (LAPACK) or
     * sparse LU (UMFPACK), or chosen by its size and fill (see the entry).
     */
    enum class StateSystem : unsigned char
    {
      automatic,
      dense,
      sparse
    };
    StateSystem state_system = StateSystem::automatic;

    /**
     * Whether a block's flexibility is computed whole at the start or
     * column by column as pairs close (see the entry).
     */
    enum class FlexibilityColumns : unsigned char
    {
      automatic,
      whole,
      on_demand
    };
    FlexibilityColumns flexibility_columns = FlexibilityColumns::automatic;

    /** The methods of the state iteration and their limits. */
    StateMethodParameters state_method;

    /** Whether the condensed (multi-body) formulation runs. */
    bool
    runs_condensed() const
    {
      return formulation != Formulation::monolithic;
    }

    /** Whether the monolithic reference runs. */
    bool
    runs_monolithic() const
    {
      return formulation != Formulation::condensed;
    }
  };
} // namespace mbfem

#endif

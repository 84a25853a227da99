#ifndef mbfem_contact_continuation_state_method_h
#define mbfem_contact_continuation_state_method_h

#include <mbfem/contact/state_method.h>

#include <string>

namespace mbfem
{
  /**
   * 'State method = load continuation': the fast iteration at each of
   * 'Contact/Load continuation/Load factors' (10, 5, 2, 1) times the
   * increment's load, each from the states of the last; concluded if it
   * concluded at 1 with an acceptable answer. Where it fails, the states
   * stay as the methods before it left them. Condensed formulation only.
   */
  template <int dim>
  class ContinuationStateMethod : public StateMethodInterface<dim>
  {
  public:
    static std::string
    name();

    static std::string
    description();

    static StateMethodTraits
    traits();

    StateMethodOutcome
    run(IncrementContext<dim> &increment) override;
  };
} // namespace mbfem

#endif

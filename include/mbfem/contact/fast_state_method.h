#ifndef mbfem_contact_fast_state_method_h
#define mbfem_contact_fast_state_method_h

#include <mbfem/contact/state_method.h>

#include <string>

namespace mbfem
{
  /**
   * 'State method = fast': the fast iteration (FastIteration) from the
   * committed states (or, on a repeated solve of the same increment, from
   * the last solve's). Its answer is refused where the states leave a
   * mechanism.
   */
  template <int dim>
  class FastStateMethod : public StateMethodInterface<dim>
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

#ifndef mbfem_contact_de_saxce_state_method_h
#define mbfem_contact_de_saxce_state_method_h

#include <mbfem/contact/state_method.h>

#include <string>

namespace mbfem
{
  /**
   * 'State method = De Saxce': De Saxce's fixed point of convex QPs
   * (DeSaxceMethod) on the increment's condensed problem; its states then
   * polished by the fast iteration. For increments whose events all happen
   * at s = 0+ (gravity from the unloaded state), where the load path
   * degenerates. Its iterations are the QPs and the fast iteration's.
   * Where it fails, the states stay as the methods before it left them.
   * Condensed formulation only.
   */
  template <int dim>
  class DeSaxceStateMethod : public StateMethodInterface<dim>
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

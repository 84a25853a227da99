#ifndef mbfem_contact_lemke_state_method_h
#define mbfem_contact_lemke_state_method_h

#include <mbfem/contact/state_method.h>

#include <string>

namespace mbfem
{
  /**
   * 'State method = Lemke': complementary pivoting (LemkeMethod) on the
   * increment's condensed problem from the committed states; its states
   * then polished by the fast iteration. Its iterations are the pivots and
   * the fast iteration's. Where it fails, the states stay as the methods
   * before it left them. Condensed formulation only.
   */
  template <int dim>
  class LemkeStateMethod : public StateMethodInterface<dim>
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

#ifndef mbfem_contact_load_path_state_method_h
#define mbfem_contact_load_path_state_method_h

#include <mbfem/contact/contact_state.h>
#include <mbfem/contact/state_method.h>

#include <string>

namespace mbfem
{
  /**
   * 'State method = load path': the increment's load followed from the
   * committed state (LoadPath), one pair switching where its condition
   * fails; where it reaches the increment's end, its states solved and
   * checked by the fast iteration. Condensed formulation only.
   */
  template <int dim>
  class LoadPathStateMethod : public StateMethodInterface<dim>
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

  private:
    /**
     * At s = 1: the fast iteration from the path's @p states. @p outcome
     * converges if they settle and leave no mechanism, and then counts the
     * fast iteration's iterations too (a failure counts the path's switches
     * only).
     */
    static void
    finish(IncrementContext<dim> &increment,
           const StateTrial<dim> &states,
           StateMethodOutcome    &outcome);
  };
} // namespace mbfem

#endif

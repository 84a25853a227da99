#ifndef mbfem_contact_newton_state_method_h
#define mbfem_contact_newton_state_method_h

#include <mbfem/contact/state_method.h>

#include <string>

namespace mbfem
{
  /**
   * 'State method = semismooth Newton': the increment as one nonsmooth
   * system (SemismoothNewton) from the last increment's answer or the
   * increment's bonded one; its states then polished by the fast iteration.
   * Its iterations are the Newton steps and the polishing fast iteration's.
   * Where it fails, the states stay as the methods before it left them.
   * Condensed formulation only.
   */
  template <int dim>
  class NewtonStateMethod : public StateMethodInterface<dim>
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
    /** Newton's start: see run(). */
    static Vector<double>
    start(IncrementContext<dim> &increment);
  };
} // namespace mbfem

#endif

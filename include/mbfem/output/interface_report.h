#ifndef mbfem_output_interface_report_h
#define mbfem_output_interface_report_h

#include <mbfem/contact/contact_solver.h>
#include <mbfem/interface/contact_interface.h>

#include <deal.II/base/conditional_ostream.h>

namespace mbfem
{
  using namespace dealii;

  /**
   * Per interface at the end of a run: the largest tractions, the extent of
   * the closed and of the stuck pairs, whether the paper's Table 1 holds
   * (slipping pairs on the Mohr-Coulomb cone, stuck pairs inside it), and
   * in 2D the errors against 'Contact/Exact traction'.
   */
  template <int dim>
  void
  print_interface_summary(const ContactSolver<dim> &contact,
                          const ContactParameters  &parameters,
                          ConditionalOStream       &pcout);
} // namespace mbfem

#endif

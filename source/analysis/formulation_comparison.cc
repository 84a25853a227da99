#include <mbfem/analysis/formulation_comparison.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace mbfem
{
  FormulationComparison::FormulationComparison(const bool test_mode)
    : test_mode(test_mode)
  {}



  template <int dim>
  void
  FormulationComparison::compare(const ContactSolver<dim> &condensed,
                                 const ContactSolver<dim> &reference,
                                 const double              displacement_scale,
                                 ConditionalOStream       &out)
  {
    const unsigned int n_pairs     = condensed.pairs().size();
    double             force_scale = 1e-300;
    for (unsigned int i = 0; i < n_pairs; ++i)
      force_scale = std::max(force_scale, condensed.local_force(i).norm());
    double       force = 0., gap = 0., slip = 0.;
    unsigned int differ = 0;
    for (unsigned int i = 0; i < n_pairs; ++i)
      {
        if (condensed.state(i) != reference.state(i) ||
            condensed.broken(i) != reference.broken(i))
          ++differ;
        force = std::max(
          force,
          (condensed.local_force(i) - reference.local_force(i)).norm() /
            force_scale);
        gap  = std::max(gap,
                       std::abs(condensed.gap(i) - reference.gap(i)) /
                         displacement_scale);
        slip = std::max(slip,
                        (condensed.slip(i) - reference.slip(i)).norm() /
                          displacement_scale);
      }
    largest_force_difference = std::max(largest_force_difference, force);
    largest_gap_difference   = std::max(largest_gap_difference, gap);
    largest_slip_difference  = std::max(largest_slip_difference, slip);
    state_differences += differ;
    last_comparison = {{static_cast<double>(differ), force, gap, slip}};

    out << "    monolithic reference: stick/slip/open "
        << reference.count(ContactState::stick) << "/"
        << reference.count(ContactState::slip) << "/"
        << reference.count(ContactState::open) << ", states differ at "
        << differ << " of " << n_pairs << " pairs; differences (relative) "
        << "forces " << format(force) << ", gaps " << format(gap) << ", slips "
        << format(slip) << "\n";
  }



  void
  FormulationComparison::print_summary(ConditionalOStream &out) const
  {
    const bool agree =
      state_differences == 0 && largest_force_difference <= 1e-6 &&
      largest_gap_difference <= 1e-6 && largest_slip_difference <= 1e-6;
    out << "  condensed against monolithic over all increments: "
        << "states equal at every increment "
        << (state_differences == 0 ? "yes" : "NO")
        << "; largest differences (relative): forces "
        << format(largest_force_difference) << ", gaps "
        << format(largest_gap_difference) << ", slips "
        << format(largest_slip_difference) << "; within 1e-6 "
        << (agree ? "yes" : "NO") << "\n";
  }



  std::string
  FormulationComparison::format(const double e) const
  {
    // Round-off differences vary by machine: below 1e-9 they are printed
    // as such, so that the tests compare what matters.
    std::ostringstream s;
    if (e < 1e-9 && test_mode)
      s << "below 1e-9";
    else
      s << std::scientific << std::setprecision(2) << e;
    return s.str();
  }



  template void
  FormulationComparison::compare(const ContactSolver<2> &,
                                 const ContactSolver<2> &,
                                 const double,
                                 ConditionalOStream &);
  template void
  FormulationComparison::compare(const ContactSolver<3> &,
                                 const ContactSolver<3> &,
                                 const double,
                                 ConditionalOStream &);
} // namespace mbfem

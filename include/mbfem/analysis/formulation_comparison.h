#ifndef mbfem_analysis_formulation_comparison_h
#define mbfem_analysis_formulation_comparison_h

#include <mbfem/contact/contact_solver.h>

#include <deal.II/base/conditional_ostream.h>

#include <array>
#include <string>

namespace mbfem
{
  using namespace dealii;

  /**
   * 'Contact/Formulation = both': the condensed formulation's pairs
   * against the monolithic reference's at every increment (states,
   * forces, gaps, slips), and the largest differences over the run. Its
   * own class so that the driver only asks for a comparison and prints
   * the summary.
   */
  class FormulationComparison
  {
  public:
    /** @p test_mode prints round-off below 1e-9 as such. */
    explicit FormulationComparison(const bool test_mode);

    /**
     * Compares the pairs of @p condensed and @p reference after an
     * increment, forces relative to the largest pair force and gaps and
     * slips relative to @p displacement_scale (the model's largest
     * displacement: while all pairs stick, gaps and slips are round-off
     * of zero and cannot be their own scale); prints a line to @p out.
     */
    template <int dim>
    void
    compare(const ContactSolver<dim> &condensed,
            const ContactSolver<dim> &reference,
            const double              displacement_scale,
            ConditionalOStream       &out);

    /** The last comparison: pairs whose states differ, forces, gaps, slips. */
    const std::array<double, 4> &
    last() const
    {
      return last_comparison;
    }

    /** The line at the end of a run: the largest differences of all. */
    void
    print_summary(ConditionalOStream &out) const;

  private:
    /** @p e in scientific notation, or "below 1e-9" in test mode. */
    std::string
    format(const double e) const;

    const bool            test_mode;
    double                largest_force_difference = 0.;
    double                largest_gap_difference   = 0.;
    double                largest_slip_difference  = 0.;
    unsigned int          state_differences        = 0;
    std::array<double, 4> last_comparison          = {{0., 0., 0., 0.}};
  };
} // namespace mbfem

#endif

#ifndef mbfem_analysis_order_study_h
#define mbfem_analysis_order_study_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  template <int dim>
  struct Parameters;

  /** Subsection "Order study". */
  struct OrderStudyParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    std::vector<unsigned int> degrees;
    std::vector<unsigned int> refinements;
    std::string               table_file;

    /**
     * Relative errors below this are round-off: the solution lies in the
     * finite element space (or the solver's precision is reached) and no
     * rate is shown.
     */
    double round_off_floor = 1e-12;
  };

  /** One row of the order study: a degree on a mesh level. */
  struct OrderStudyRow
  {
    unsigned int degree;
    unsigned int refinement;
    unsigned int n_cells;
    unsigned int n_dofs;
    double       displacement_error;
    double       stress_error;
    double       displacement_rate; // NaN where there is no rate
    double       stress_rate;
  };

  /**
   * The comparison a user of this tool makes first: the same problem at
   * element orders p and mesh levels, with L2 errors of displacement and
   * stress against the closed form and the observed rates (expected p+1
   * and p for smooth solutions). The table goes to the screen and to CSV.
   */
  template <int dim>
  class OrderStudy
  {
  public:
    OrderStudy(const Parameters<dim> &parameters, ConditionalOStream &pcout);

    void
    run();

    /**
     * Rates between consecutive levels of each degree, in place; none where
     * an error is below @p round_off_floor.
     */
    static void
    compute_rates(std::vector<OrderStudyRow> &rows,
                  const double                round_off_floor);

  private:
    OrderStudyRow
    solve_one(const unsigned int degree, const unsigned int refinement) const;

    /**
     * solve_one() for every degree and level, in the table's order; under
     * mpirun each rank solves a share of them and the rows are exchanged
     * (doc/parallel.md).
     */
    std::vector<OrderStudyRow>
    solve_all(const Timer &timer) const;

    void
    print_table(const std::vector<OrderStudyRow> &rows) const;

    void
    write_csv(const std::vector<OrderStudyRow> &rows) const;

    const Parameters<dim> &parameters;
    ConditionalOStream    &pcout;
  };
} // namespace mbfem

#endif

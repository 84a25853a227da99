#ifndef mbfem_contact_de_saxce_method_h
#define mbfem_contact_de_saxce_method_h

#include <mbfem/contact/contact_problem.h>
#include <mbfem/contact/contact_state.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * De Saxce's fixed point on one increment's condensed problem
   * (ContactProblem): with a shift s_k of each pair's normal gap held, the
   *
   *   min 1/2 r^T W r + (q + mu s e_N)^T r,
   *   |r_T| <= c A + mu r_N, r_N >= 0 (or the tension limit), G^T r + f = 0
   *
   * is a convex QP (W is the blocks' symmetric flexibility), whose optimality
   * conditions are the joint law where s_k = |u_T,k| (De Saxce's bipotential;
   * Acary, Cadoux, Lemarechal and Malick 2011 prove that the fixed point
   * exists where statics admits forces strictly inside the cones). The
   * iteration is s <- (1 - omega) s + omega |u_T|. It needs no load path:
   * it concludes where every event of the increment happens at s = 0+
   * (gravity from the unloaded state). Each QP is solved by ConvexQp's
   * interior-point method (the cone faceted in 3D, inscribed, 64 faces);
   * whether statics admits forces at all, by Clp's simplex first. A joint whose
   * gap opens breaks and the fixed point runs again. Like Lemke's method it
   * does not decide the increment: its answer gives states, which the fast
   * iteration then solves exactly and checks (doc/state_iteration.md,
   * "De Saxce's fixed point").
   */
  template <int dim>
  class DeSaxceMethod
  {
  public:
    /**
     * The method on @p contact_problem (referenced, with W), at most
     * @p max_qps QPs in all, relaxation @p relaxation of the shift.
     */
    DeSaxceMethod(const ContactProblem<dim> &contact_problem,
                  const unsigned int         max_qps,
                  const double               relaxation);

    /** Runs the fixed point, breaking the joints that open; adds the QPs to
     * @p qps. True if it settled. */
    bool
    solve(unsigned int &qps);

    /** Why solve() failed. */
    std::string
    failure() const;

    /**
     * Whether solve() failed because statics admits no forces once the
     * joints it broke have lost their strength; those joints (the rest
     * as in @p committed) for the statics certificate.
     */
    bool
    stopped_after_breaking() const;
    std::vector<bool>
    broken_flags(const std::vector<bool> &committed) const;

    /** The states of solve()'s answer, the rest as in @p committed. */
    StateTrial<dim>
    answer_states(const StateTrial<dim> &committed) const;

  private:
    /**
     * One QP with the shifts @p shift (in the scaled units); false where
     * it is infeasible or not solved. Sets r, alpha and u (scaled).
     */
    bool
    solve_qp(const std::vector<double> &shift);

    /** Whether statics admits forces in the cones (an LP, Clp). */
    bool
    statics_admits() const;

    /** The fixed point at the present broken set; false if it failed. */
    bool
    fixed_point(unsigned int &qps, const unsigned int max);

    /** The pairs whose gap the answer opens and that have strength to lose. */
    std::vector<unsigned int>
    newly_open() const;

    /** The tolerance of the QPs' answers, relative to their scales. */
    static constexpr double answer_tolerance = 1e-6;

    const ContactProblem<dim> &problem;
    const unsigned int         max_qps;
    const double               relaxation;
    /** Forces in units of F, displacements of U = F times the mean
     * flexibility (the QPs are solved in these units). */
    double            force_unit = 1., displacement_unit = 1.;
    std::vector<bool> broken;
    bool              statics_failed_after_breaking = false;
    std::string       why;
    Vector<double>    r, alpha, u;
  };
} // namespace mbfem

#endif

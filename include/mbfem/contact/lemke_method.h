#ifndef mbfem_contact_lemke_method_h
#define mbfem_contact_lemke_method_h

#include <mbfem/contact/contact_problem.h>
#include <mbfem/contact/contact_state.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * Lemke's complementary pivoting method on one increment's condensed
   * problem (ContactProblem, doc/contact_problems.md), written as a linear
   * complementarity problem w = M z + q, z >= 0, w >= 0, z . w = 0
   * (doc/state_iteration.md, doc/decisions.md):
   *
   * - per pair the normal force r_N + sigma_t A, against the gap u_N;
   * - the tangential force as non-negative components beta_j along
   *   directions d_j of the tangent plane (2D: +t and -t, Table 1's law;
   *   3D: a faceted friction cone), each against d_j . u_T + lambda, and
   *   lambda against the cone's room c A + mu max(r_N, 0) - sum beta_j
   *   (with a tension limit, max(r_N, 0) is a variable p of its own,
   *   against p - r_N >= 0);
   * - a tied pair's force and the floating amplitudes alpha as free
   *   variables (the difference of two non-negative ones) against the
   *   equalities u = 0 and G^T r + f = 0 written as two inequalities.
   *
   * This is the class of problems for which Klarbring and Pang (1998)
   * give existence where statics admits forces strictly inside the cones,
   * under conditions doc/decisions.md discusses; Lemke's method ends at a
   * solution or on a secondary ray, and with the lexicographic ratio test
   * it does not cycle on degenerate problems. A joint that opens breaks
   * (its cohesion and tension are lost) and the problem is solved again,
   * until no more break. Like the semismooth Newton method it does not
   * decide the increment: its answer gives states, which ContactSolver's
   * fast iteration then solves and checks with the same tolerances as
   * every other method (in 3D on the round cone).
   */
  template <int dim>
  class LemkeMethod
  {
  public:
    /**
     * The method on @p contact_problem (referenced, not copied; its W may
     * be filled after construction, before solve(): size() does not need
     * it), with
     * 'Contact/Lemke's limits: it is not tried above @p variable_limit
     * variables, and gives up after @p pivots_per_variable pivots per
     * variable.
     */
    LemkeMethod(const ContactProblem<dim> &contact_problem,
                const unsigned int         variable_limit,
                const unsigned int         pivots_per_variable);

    /**
     * Solves the problem, breaking the joints that open; adds the pivots
     * to @p pivots. True if it ended at a solution.
     */
    bool
    solve(unsigned int &pivots);

    /** Why solve() failed: a secondary ray, the pivot limit, or size. */
    std::string
    failure() const;

    /** The states of solve()'s answer, the rest as in @p committed. */
    StateTrial<dim>
    answer_states(const StateTrial<dim> &committed) const;

    /** The number of complementarity variables of the problem. */
    unsigned int
    size() const;

  private:
    /** How one pair's variables sit in z (invalid where it has none). */
    struct PairVariables
    {
      unsigned int normal      = numbers::invalid_unsigned_int;
      unsigned int shear       = numbers::invalid_unsigned_int; // the first
      unsigned int lambda      = numbers::invalid_unsigned_int;
      unsigned int compression = numbers::invalid_unsigned_int; // max(r_N,0)
      unsigned int tied        = numbers::invalid_unsigned_int; // 2 dim
    };

    /** Numbers the variables of every pair and of alpha. */
    void
    number_variables();

    /** M and q of the problem with the joints in broken. */
    void
    assemble(FullMatrix<double> &M, Vector<double> &q) const;

    /**
     * assemble(), the rows of pair @p k's variables, from the pairs'
     * displacements U z + u0.
     */
    void
    add_pair_rows(const unsigned int        k,
                  const FullMatrix<double> &U,
                  const Vector<double>     &u0,
                  FullMatrix<double>       &M,
                  Vector<double>           &q) const;

    /** assemble(), the floating blocks' equilibrium G^T r + f = 0. */
    void
    add_equilibrium_rows(
      const std::vector<std::vector<std::pair<unsigned int, double>>> &R,
      const Vector<double>                                            &r0,
      FullMatrix<double>                                              &M,
      Vector<double>                                                  &q) const;

    /**
     * Per row of r (pair k, direction e): the variables of z and their
     * coefficients in r; and the constant part of r (the tension shift).
     */
    void
    force_map(std::vector<std::vector<std::pair<unsigned int, double>>> &R,
              Vector<double> &r0) const;

    /**
     * Lemke's method on w = M z + q (physical units, scaled here; both are
     * changed), its answer into @p z; false, saying why, if it did not end
     * at a solution or @p pivots reached @p max_pivots.
     */
    bool
    solve_lcp(FullMatrix<double> &M,
              Vector<double>     &q,
              Vector<double>     &z,
              const unsigned int  max_pivots,
              unsigned int       &pivots);

    /**
     * Where a ray's unbounded @p variable (w_i as i, z_i as n + i) is a
     * free variable's half whose twin is among the @p basic variables: an
     * artefact of the split, said in the failure.
     */
    std::string
    describe_ray(const unsigned int               variable,
                 const std::vector<unsigned int> &basic) const;

    /** The largest force and relative displacement of the answer. */
    std::pair<double, double>
    scales() const;

    /** r, alpha and u from the LCP's answer z. */
    void
    set_answer(const Vector<double> &z);

    /** The pairs that the answer opens and that have strength to lose. */
    std::vector<unsigned int>
    newly_open() const;

    /** The tangential direction d_j of pair variables (local frame). */
    Tensor<1, dim>
    direction(const unsigned int j) const;

    const ContactProblem<dim> &problem;
    const unsigned int         n_directions;
    const unsigned int         max_variables;
    const unsigned int         max_pivots_per_variable;
    std::vector<PairVariables> variables;
    unsigned int               alpha_plus = 0, n_variables = 0;
    /**
     * Per variable of z: whether it is a force, and whether the row of its
     * complement is in units of force (the cones' room, the positive part
     * of r_N, equilibrium) rather than displacement: solve_lcp() scales by
     * them.
     */
    std::vector<bool> variable_is_force, row_is_force;
    /** Joints the method has broken (beyond those of the problem). */
    std::vector<bool> broken;
    std::string       why;
    /** The answer: forces, amplitudes and relative displacements. */
    Vector<double> r, alpha, u;
  };
} // namespace mbfem

#endif

#ifndef mbfem_contact_contact_problem_h
#define mbfem_contact_contact_problem_h

#include <mbfem/interface/joint_law.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * One increment's condensed contact problem, in the conventions of the
   * frictional contact library FCLIB (Acary, Bremond, Huber): per pair its
   * local frame, the normal component first, then the tangential ones, and
   *
   *   u = W r + q + G alpha,     G^T r + f = 0,
   *
   * r the pairs' forces (on side b, r_N > 0 compression), u_N the normal
   * gap, u_T the tangential relative displacement of this increment,
   * W the blocks' flexibility (the paper's C_a in the frames), G the
   * floating modes' coupling and f their load resultant. It is what the
   * state iteration solves, written down so that another contact solver
   * can be run on it (doc/contact_problems.md), and the seam along which
   * the solver's methods can be separated from the blocks.
   */
  template <int dim>
  struct ContactProblem
  {
    /** Joint data and the state found, per pair. */
    struct Pair
    {
      Point<dim> point;
      double     area = 0.;
      /** The pair's joint law (written as mu, c A and sigma_t A). */
      JointLaw joint;
      /** Rows: the normal, then the tangents (the global axes if tied). */
      Tensor<2, dim>        frame;
      bool                  broken = false, tensile_slip = false, tied = false;
      std::array<bool, dim> held{};
      std::string           state;
      /** 3D slip: the friction direction s and the weight beta of the
       * linearised direction law (0 in 2D). */
      Tensor<1, dim> slip_direction;
      double         direction_stiffness = 0.;
    };

    unsigned int increment = 0;
    double       time      = 0.;
    unsigned int n_pairs = 0, n_alpha = 0;
    /** W's entries, (row, column) -> value; rows of pairs that share a block.
     */
    std::map<std::pair<unsigned int, unsigned int>, double> W;
    FullMatrix<double>                                      G;
    std::vector<double>                                     q, f;
    std::vector<Pair>                                       pairs;
    /** The solution found (empty if the increment failed). */
    std::vector<double> r, alpha, u;

    /**
     * Writes @p stem.json (everything but the matrices), @p stem-W.mtx and
     * @p stem-G.mtx (Matrix Market, coordinate, 17 digits), atomically.
     */
    void
    write(const std::string &stem) const;
  };
} // namespace mbfem

#endif

#ifndef mbfem_contact_contact_state_h
#define mbfem_contact_contact_state_h

#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /** The contact states of the paper's Table 1. */
  enum class ContactState : unsigned char
  {
    stick,
    slip,
    open
  };

  std::string
  to_string(const ContactState state);

  /**
   * The state check's relative tolerance: a pair fails its condition where
   * the violation exceeds this times the increment's largest force or
   * displacement. Every method reads states with it (the fast iteration's
   * check, the load path's margins, the Newton answer's states), so that
   * they decide alike.
   */
  constexpr double state_tolerance = 1e-9;

  /**
   * 3D slip directions have settled when none turned by more than this
   * (the norm of the change of a unit vector, about the angle in radians)
   * in the last solve: the fast iteration's and the load path's Newton
   * step on the directions stop there.
   */
  constexpr double direction_tolerance = 1e-6;

  /**
   * The states of every pair that a step of the state iteration assumes,
   * with what the joint law needs besides: whether a joint has broken,
   * slips in tension (no friction), and in 3D the slip direction and its
   * linearisation's weight. The methods of the state iteration pass these
   * between them.
   */
  template <int dim>
  struct StateTrial
  {
    std::vector<ContactState>   state;
    std::vector<bool>           broken;
    std::vector<bool>           tensile_slip;   // slip with r_N < 0: no mu
    std::vector<Tensor<1, dim>> slip_direction; // local, tangential
    /**
     * 3D: (c A + mu r_N) / |slip increment| at the last iterate, the
     * weight of the linearised slip direction; 0 holds it fixed.
     */
    std::vector<double> direction_stiffness;
  };
} // namespace mbfem

#endif

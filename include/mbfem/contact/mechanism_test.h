#ifndef mbfem_contact_mechanism_test_h
#define mbfem_contact_mechanism_test_h

#include <mbfem/contact/contact_state.h>
#include <mbfem/contact/interface_system.h>
#include <mbfem/contact/rigid_coupling.h>
#include <mbfem/interface/contact_interface.h>

#include <deal.II/lac/vector.h>

#include <array>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * Whether the states of a trial hold every floating block: the rigid
   * motions they leave free (no normal motion at a closed pair, no
   * tangential motion at a stuck one; a slipping pair resists only by its
   * strength), and the messages that name each block that can move. The
   * fast iteration asks it why a trial is singular, the load path where
   * its path ends at a mechanism, and the entry point whether an answer
   * stands.
   *
   * Everything is referenced, not copied (the owner, ContactSolver, keeps
   * the pairs, the held directions, the loads and the coupling).
   */
  template <int dim>
  class MechanismTest
  {
  public:
    using Trial = StateTrial<dim>;

    MechanismTest(const std::vector<ContactPair<dim>>      &pairs,
                  const std::vector<std::array<bool, dim>> &held,
                  const IncrementLoads                     &loads,
                  const RigidCoupling<dim>                 &coupling);

    /**
     * The motion that the states of @p trial leave free and the loads
     * drive (the free space's projection of the loads' work on the modes)
     * as floating amplitudes; empty if the states hold every block.
     */
    Vector<double>
    motion(const Trial &trial) const;

    /**
     * motion() in words: each moving block, its pairs' states and its
     * motion; empty if the states hold every block.
     */
    std::string
    describe(const Trial &trial) const;

    /**
     * Which floating blocks the pairs of @p trial cannot hold whatever
     * the loads, and in which modes; empty if every block is held.
     */
    std::string
    unheld_blocks(const Trial &trial) const;

    /** Message for a singular system: which block is not held. */
    std::string
    diagnose_singular(const Trial &trial) const;

  private:
    const std::vector<ContactPair<dim>>      &pairs;
    const std::vector<std::array<bool, dim>> &held;
    const IncrementLoads                     &loads;
    const RigidCoupling<dim>                 &coupling;
  };
} // namespace mbfem

#endif

#ifndef mbfem_contact_interface_system_h
#define mbfem_contact_interface_system_h

#include <mbfem/block/block.h>
#include <mbfem/interface/pair_equation.h>

#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The loads of an increment as the interface system sees them: the
   * relative displacement of the pairs under the external loads alone
   * (Delta_F in the pairs' frames; condensed only, the monolithic system
   * holds its loads itself) and F_e, the floating blocks' load resultants
   * per amplitude. The load path scales both.
   */
  struct IncrementLoads
  {
    Vector<double>      displacement;
    std::vector<double> resultant;

    /**
     * These loads at the fraction @p s of the way from @p start (s = 0) to
     * @p full (s = 1), or beyond (s > 1, the load continuation).
     */
    void
    set_fraction(const IncrementLoads &start,
                 const IncrementLoads &full,
                 const double          s)
    {
      displacement = start.displacement;
      displacement.sadd(1. - s, s, full.displacement);
      for (unsigned int a = 0; a < resultant.size(); ++a)
        resultant[a] = (1. - s) * start.resultant[a] + s * full.resultant[a];
    }
  };



  /**
   * The interface system of the state iteration, whichever way it is
   * solved: given the equation of every pair direction (PairEquation, the
   * rows of Table 1 for the states in hand), the pairs' forces rho, the
   * floating modes' amplitudes alpha and the relative displacements d in
   * the pairs' frames. CondensedSystem is the multi-body method's (through
   * the blocks' flexibilities), MonolithicSystem the reference (every
   * block's displacement in one sparse system).
   */
  template <int dim>
  class InterfaceSystem
  {
  public:
    virtual ~InterfaceSystem() = default;

    /**
     * What does not change with the loads: flexibilities (condensed) or
     * stiffnesses (monolithic), and the directions held by supports.
     */
    virtual void
    setup(const std::vector<std::unique_ptr<Block<dim>>> &blocks) = 0;

    /**
     * The loads of the increment (every block has had assemble_load();
     * condensed, its solution holds its response to them): Delta_F into
     * @p loads, or the monolithic system's own right-hand side.
     */
    virtual void
    set_load(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
             IncrementLoads                                 &loads) = 0;

    /**
     * Solves the system of @p equations under @p loads: (rho, alpha) into
     * @p solution (monolithic: rho only), d into @p displacement. False if
     * the system is singular.
     */
    virtual bool
    solve(const std::vector<PairEquation<dim>> &equations,
          const IncrementLoads                 &loads,
          Vector<double>                       &solution,
          Vector<double>                       &displacement) = 0;

    /**
     * Pair directions in which no free DoF moves (both nodes on supports):
     * their force goes to the supports.
     */
    virtual std::vector<std::array<bool, dim>>
    held() const = 0;
  };
} // namespace mbfem

#endif

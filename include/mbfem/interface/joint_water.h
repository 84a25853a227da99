#ifndef mbfem_interface_joint_water_h
#define mbfem_interface_joint_water_h

#include <mbfem/block/block.h>
#include <mbfem/interface/contact_interface.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>

#include <memory>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * Subsection "Water pressure": the pore pressure p_w in some joints, as a
   * function of position and t or hydrostatic below a water level.
   */
  template <int dim>
  struct WaterPressureParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Whether any joint carries water. */
    bool
    enabled() const
    {
      return !interfaces.empty();
    }

    /** p_w at @p point and pseudo-time @p time. */
    double
    pressure(const Point<dim> &point, const double time) const;

    /** 'all', 'blocks 1:2', 'boundaries 3:4' or joint-set names. */
    std::vector<std::string> interfaces;
    /** The pressure function (if no water level is given). */
    std::shared_ptr<Functions::ParsedFunction<dim>> function;
    /** The water level as a function of t (hydrostatic), or none. */
    std::shared_ptr<FunctionParser<1>> level;
    double                             unit_weight = 9810.;
  };



  /**
   * Water in the joints (design.md, section 5): p_w acts on both faces of
   * a wet joint, so each wet pair's blocks are pushed apart by p_w A along
   * its normal, lumped to its nodes with the pair's own weights. The pair
   * force r is then the effective (solid) force, and the joint law, the
   * state iteration and the statics certificate see the effective forces
   * without knowing of water: an open joint carries p_w on both faces, a
   * closed one grips with r_N = N - p_w A. Applied as an external load,
   * p_w enters each block's response and its floating resultant F_e.
   */
  template <int dim>
  class JointWater
  {
  public:
    /**
     * The wet pairs of @p pairs: those of the interfaces (of @p contact,
     * after 'Interfaces = all' found them) that @p parameters names; an
     * entry that names none ends the run.
     */
    JointWater(const WaterPressureParameters<dim>  &parameters,
               const ContactParameters             &contact,
               const std::vector<ContactPair<dim>> &pairs,
               const unsigned int                   n_blocks);

    /** p_w of pair @p k at @p time (0 for a dry pair). */
    double
    pressure(const unsigned int k, const double time) const;

    /** Adds p_w A on both faces of the wet pairs to block @p b's load. */
    void
    add_load(const unsigned int b, Block<dim> &block, const double time) const;

    /** The sum of p_w A over the wet pairs: the uplift resultant U. */
    double
    resultant(const double time) const;

    unsigned int
    n_wet_pairs() const;

  private:
    const WaterPressureParameters<dim>  &parameters;
    const std::vector<ContactPair<dim>> &pairs;
    std::vector<bool>                    wet;
    /** Per block: the wet pair sides on it, as (pair, sign). */
    std::vector<std::vector<std::pair<unsigned int, int>>> sides_on_block;
  };
} // namespace mbfem

#endif

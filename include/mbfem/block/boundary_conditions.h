#ifndef mbfem_block_boundary_conditions_h
#define mbfem_block_boundary_conditions_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/point.h>
#include <deal.II/fe/component_mask.h>

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * Supports and loads of a block, all functions of position and
   * pseudo-time t (the load history): prescribed displacements on boundary
   * ids with a choice of components (rollers are a single component),
   * tractions on boundary ids, and a body force per unit volume.
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Every boundary id named in the input must exist in the mesh: a typo
     * would otherwise leave a face silently unloaded or unsupported.
     */
    void
    check_boundary_ids(const std::set<types::boundary_id> &present) const;

    /** Sets the pseudo-time of all functions. */
    void
    set_time(const double time);

    /** Prescribed components per boundary id. */
    std::map<types::boundary_id, ComponentMask> dirichlet;

    std::set<types::boundary_id> traction_boundaries;

    /**
     * Rigid loading platens: on each boundary id, all nodes share one
     * displacement component (normally the face normal), so the face
     * translates without rotating, as under a stiff loading plate. The
     * moment of the loads applied through it is carried by the platen.
     */
    std::map<types::boundary_id, unsigned int> rigid_platens;

    /** Supports at single points: the node at the point, given components. */
    std::vector<std::pair<Point<dim>, ComponentMask>> point_supports;

    std::shared_ptr<Functions::ParsedFunction<dim>> prescribed_displacement;
    std::shared_ptr<Functions::ParsedFunction<dim>> traction;
    std::shared_ptr<Functions::ParsedFunction<dim>> body_force;
    /**
     * Whether every expression of 'Body force' is the number 0 (the
     * default): then the load assembly does not evaluate it at every
     * quadrature point (muparser's call costs more than the rest of the
     * point's work).
     */
    bool body_force_is_zero = false;

    /**
     * Pseudo-time over which the unit weight is ramped ('Gravity ramp
     * time'); 0: the weight acts in full at every increment.
     */
    double gravity_ramp_time = 0.;
    /** The part of the unit weight acting at the time of set_time(). */
    double gravity_factor = 1.;
  };

  /**
   * Parses a ParsedFunction in the current subsection of @p prm, turning a
   * syntax error in an expression into a message that names @p where.
   */
  template <int dim>
  std::shared_ptr<Functions::ParsedFunction<dim>>
  parse_function(ParameterHandler  &prm,
                 const unsigned int n_components,
                 const std::string &where);

  /**
   * A function read by parse_function(): where, the constants its
   * 'Function constants' names, and how to read it again with other
   * values of them (a random constant of 'Mode = reliability': a reservoir
   * level written once as a constant in the traction and the uplift).
   */
  struct ParsedFunctionEntry
  {
    std::string                                                where;
    std::map<std::string, double>                              constants;
    std::function<void(const std::map<std::string, double> &)> set_constants;
  };

  /** The functions parse_function() has read in this process, in order. */
  std::vector<ParsedFunctionEntry> &
  parsed_functions();

  /** "0: xy, 2: y" -> {0: mask(x,y), 2: mask(y)}; @p where names the entry. */
  template <int dim>
  std::map<types::boundary_id, ComponentMask>
  parse_component_map(const std::string &text, const std::string &where);
} // namespace mbfem

#endif

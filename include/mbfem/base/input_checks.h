#ifndef mbfem_base_input_checks_h
#define mbfem_base_input_checks_h

#include <mbfem/base/parameters.h>
#include <mbfem/base/text_input.h>
#include <mbfem/block/block.h>

#include <deal.II/base/function.h>
#include <deal.II/grid/tria.h>

#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <vector>

/**
 * @file The checks of an input against itself and against the mesh that
 * run before anything is assembled: a wrong model that runs is worse than
 * one that stops, because its numbers get used. doc/refusals.md lists them
 * with their messages. The geometry of the cells is checked in
 * mbfem/mesh/mesh_checks.h.
 */

namespace mbfem
{
  using namespace dealii;

  /** @name Parameter values */
  /** @{ */

  /**
   * The 'Function constants' entry of a ParsedFunction ('P=1, D=2'):
   * every name must be a name muparser accepts and not one of the
   * function's variables, every value one finite number. deal.II reads
   * the first number of the text ('2/3' becomes 2) and accepts inf and
   * nan; muparser rejects a bad name with an exception that is no
   * std::exception ('unknown error').
   */
  void
  check_function_constants(const std::string &constants,
                           const std::string &variables,
                           const std::string &where);

  /**
   * The 'Variable names' entry of a ParsedFunction in @p dim dimensions:
   * @p dim names of coordinates and optionally one of time, each a name
   * muparser accepts, none twice.
   */
  void
  check_variable_names(const std::string &variables,
                       const unsigned int dim,
                       const std::string &where);

  /**
   * Every function of the input (loads, prescribed displacements, body
   * force, exact solution) must be finite where it is used, at t = 0 and at
   * the end of every increment: at the vertices of the faces it loads or
   * supports, and for the body force and the exact solution at the
   * vertices and cell centres of every block.
   */
  template <int dim>
  void
  check_functions_are_finite(
    Parameters<dim>                                &parameters,
    const std::vector<std::unique_ptr<Block<dim>>> &blocks);
  /** @} */

  /** @name Ids against the mesh */
  /** @{ */

  /**
   * Every id named in the input, in every subsection, exists in @p mesh:
   * boundary ids (prescribed, traction, platen, in-situ stress, released,
   * interfaces by boundaries), material ids (block materials, excavated
   * ids, interfaces by blocks, which must also share faces). A typo would
   * otherwise leave a face unloaded, unsupported or free.
   */
  template <int dim>
  void
  check_ids_against_mesh(const Parameters<dim>    &parameters,
                         const Triangulation<dim> &mesh);

  /**
   * @p id, named in the entry @p entry, is one of the boundary ids
   * @p present, or the error lists them.
   */
  void
  check_boundary_id(const types::boundary_id            id,
                    const std::string                  &entry,
                    const std::set<types::boundary_id> &present);

  /**
   * Every point support lies on a support point of some block (within
   * 1e-6 of the block's size), or the error gives the nearest one. A point
   * where blocks meet holds all of them: that is written to @p out.
   */
  template <int dim>
  void
  check_point_supports(const BoundaryConditions<dim>                  &bc,
                       const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                       std::ostream                                   &out);
  /** @} */
} // namespace mbfem

#endif

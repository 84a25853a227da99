#ifndef mbfem_analysis_input_checks_h
#define mbfem_analysis_input_checks_h

#include <mbfem/analysis/parameters.h>
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

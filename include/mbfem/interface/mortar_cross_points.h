#ifndef mbfem_interface_mortar_cross_points_h
#define mbfem_interface_mortar_cross_points_h

#include <mbfem/block/block.h>
#include <mbfem/interface/contact_interface.h>

#include <deal.II/base/conditional_ostream.h>

#include <memory>
#include <vector>

namespace mbfem
{
  /**
   * Mortar interfaces on a loop of interfaces at a point where three or
   * more blocks meet (a T- or X-junction whose blocks are joined pairwise
   * there). Where the meshes match at the point, the mortar pairs there tie
   * one node to one node (ties_one_node_to_one()) and the cross-point rule
   * (cross_points.h) takes them like node-to-node pairs. A loop through a
   * mortar pair that weights several nodes is left as it is and its rows
   * are not exactly dependent (measured models solved, one with the
   * formulations disagreeing): said on @p pcout, naming the first such
   * interface and point. A node counts at a point where its weight is
   * above 1e-6; points are compared on a grid of @p coincident.
   */
  template <int dim>
  void
  check_mortar_cross_points(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    const std::vector<ContactPair<dim>>            &pairs,
    const std::vector<InterfaceDeclaration>        &interfaces,
    const double                                    coincident,
    ConditionalOStream                             &pcout);
} // namespace mbfem

#endif

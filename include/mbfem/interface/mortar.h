#ifndef mbfem_interface_mortar_h
#define mbfem_interface_mortar_h

#include <mbfem/block/block.h>
#include <mbfem/interface/contact_interface.h>

#include <memory>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The pairs of mortar interface @p k ('blocks 1:2 mortar', 'boundaries
   * 3:4 mortar'; doc/mortar.md), appended to @p pairs. The meshes of the two
   * sides need not match: one side (the one with fewer nodes on the
   * interface, or with more if @p on_finer_side) carries the contact
   * forces as Lagrange multipliers in the
   * dual basis of its trace, one pair per node of it; the other side's
   * displacement enters each pair as the weighted sum sum_k (M_jk / D_j)
   * u_k, with
   *
   *   D_j  = integral of psi_j over the part of the side facing the other,
   *   M_jk = integral of psi_j phi_k (projected along the side's normal),
   *
   * from exact integration over the segments (2D) or clipped polygons (3D,
   * flat faces) where the projected faces overlap. The weights of a pair
   * sum to 1, so rigid motions open no gap, and on matching meshes they are
   * 1 at the facing node: the pairs of node-to-node contact. The pair's
   * area is D_j, its normal the side's normal at the node, its initial gap
   * the psi_j-weighted mean distance along that normal; only points within
   * @p reach of the other side count.
   *
   * Returns where the side's nodes are that got no pair: their dual
   * functions face nothing within @p reach (or too little of it), which
   * the interface's summary line says.
   */
  template <int dim>
  std::vector<Point<dim>>
  mortar_pairs(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
               const InterfaceDeclaration                     &declaration,
               const unsigned int                              k,
               const double                                    reach,
               const double                                    coincident,
               const bool                                      on_finer_side,
               std::vector<ContactPair<dim>>                  &pairs);
} // namespace mbfem

#endif

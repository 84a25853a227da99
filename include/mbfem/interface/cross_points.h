#ifndef mbfem_interface_cross_points_h
#define mbfem_interface_cross_points_h

#include <mbfem/interface/contact_interface.h>

#include <vector>

namespace mbfem
{
  /** What resolve_cross_points() did, for the screen. */
  struct CrossPointReport
  {
    /** Points where the node-to-node pairs close a cycle. */
    unsigned int n_points = 0;
    /** Pairs merged into a neighbour (one per independent cycle). */
    unsigned int n_merged = 0;
  };

  /**
   * Points shared by three or more blocks (T- and X-junctions in 2D, edges
   * and corners in 3D): the rule, applied to the pairs themselves so that
   * the condensed and the monolithic formulations get the same one.
   *
   * At such a point every block has a node, and node-to-node pairs on every
   * interface that meets there join them in a closed loop: k nodes, k - 1
   * independent relative displacements, more pairs than that. While the
   * pairs of a loop all stick, their relative displacements are not
   * independent (they sum to zero around the loop), so the same motion is
   * prescribed twice and the interface system is singular; the force the
   * point transfers is then split among the pairs in infinitely many ways.
   *
   * The rule. Take the graph whose vertices are the interface nodes and
   * whose edges are the pairs, and a spanning forest of it (Kruskal, pairs
   * in the order of their interfaces, so the pair of the interface declared
   * last closes a loop). Pairs on the forest stay node-to-node. Each pair
   * that would close a loop (a chord) is not dropped but merged into the
   * nearest pair of its own interface (same two blocks) whose nodes belong
   * to no other pair: the merged pair's sides are the two nodes of each
   * side, weighted by their tributary areas (PairSide), its area the sum.
   * Why this is right:
   * - no redundancy in any combination of states: the forest's rows involve
   *   the cross-point nodes without a loop, and each merged pair's rows
   *   involve its neighbour's nodes, which nothing else constrains; so the
   *   rows stay independent whichever of them are stick, slip or open;
   * - exact while everything sticks: the forest makes the cross-point nodes
   *   move together, so the chord's relative displacement there is zero and
   *   the merged pair's condition is the neighbour's own; the displacements
   *   are those of the node-to-node model (the bonded mesh);
   * - every interface keeps its own law at the point: the chord's interface
   *   applies its normal and tangential law to the area-weighted mean of
   *   the point and its neighbour (a crosspoint modification, as mortar
   *   methods do), so it can open or slip there, which dropping the pair
   *   would forbid;
   * - no force is lost: the merged pair puts its share (its area fraction)
   *   of its force on the cross-point nodes;
   * - rigid-block statics keeps every pair: the merged pair remembers the
   *   node-to-node pairs it stands for (ContactPair::cross_point_pairs),
   *   and the statics certificate takes each as a candidate of its own
   *   (ContactSolver::statics()). A rigid-block LP has no use for
   *   independent rows, and the merged pair alone would tie the force
   *   across the chord's interface at the point to a fixed share at its
   *   neighbour: the pivot of a toppling block, where that force must act
   *   alone (issue 65: 0.9625 instead of 1.0526).
   * Mortar pairs take part where they tie one node to one node (matching
   * meshes: ties_one_node_to_one()); a mortar pair that weights several
   * nodes is no edge of the graph and takes no chord over. Throws if a chord's
   * interface has no such free pair (an interface whose every node is a
   * cross-point: refine the mesh or raise the degree).
   */
  /**
   * The index of the one node of @p side whose weight is above 1e-6 of its
   * largest, invalid if there are several. A mortar pair of meshes that
   * match at its node has one: the others' weights are round-off of the
   * mortar integrals (meshes written by gmsh match to some 1e-12), or of a
   * gap of some 1e-7 of the cells (doc/mortar.md). Merging a chord into
   * such a pair is safe: its rows keep their small weights.
   */
  template <int dim>
  unsigned int
  dominant_node(const PairSide<dim> &side);

  /**
   * Whether @p pair ties one node to one node (dominant_node() on both
   * sides): every node-to-node pair, and mortar pairs where the meshes
   * match. These are the edges of the cross-point rule's node graph.
   */
  template <int dim>
  bool
  ties_one_node_to_one(const ContactPair<dim> &pair);

  template <int dim>
  CrossPointReport
  resolve_cross_points(std::vector<ContactPair<dim>>           &pairs,
                       const std::vector<InterfaceDeclaration> &interfaces);
} // namespace mbfem

#endif

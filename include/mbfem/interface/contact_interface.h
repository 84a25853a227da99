#ifndef mbfem_interface_contact_interface_h
#define mbfem_interface_contact_interface_h

#include <mbfem/block/block.h>
#include <mbfem/interface/joint_law.h>
#include <mbfem/interface/joint_sets.h>
#include <mbfem/mesh/joint_faces.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /** One contact interface as declared in subsection "Contact". */
  struct InterfaceDeclaration
  {
    /** "blocks 1:2" (the faces the two blocks share in the mesh) or
     * "boundaries 3:4" (faces with these boundary ids). */
    bool         by_blocks = true;
    unsigned int side_a    = 0;
    unsigned int side_b    = 0;
    JointLaw     joint;
    std::string  description;
    /** Found by 'Interfaces = all', not declared one by one. */
    bool found = false;
    /** The joint set it belongs to (found interfaces), or empty. */
    std::string joint_set;
    /**
     * 'blocks 1:2 mortar': the meshes need not match, the pairs are the
     * mortar side's multipliers (mortar.h) instead of facing nodes.
     */
    bool mortar = false;
  };

  /** Subsection "Contact": the interfaces and their Mohr-Coulomb data. */
  struct ContactParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * The declared interfaces; with 'all', find_contact_pairs() adds every
     * pair of blocks that share faces in the mesh.
     */
    std::vector<InterfaceDeclaration> interfaces;
    /** 'Interfaces = all' (possibly with declared 'boundaries' entries). */
    bool all_shared_faces = false;
    /** Law of the found interfaces that no joint set claims. */
    JointLaw default_joint;
    /** Joint sets of the found interfaces, by orientation or mesh group. */
    std::vector<JointSet> joint_sets;
    double                search_distance = 0.;
    /** 'Mortar side = finer': the multipliers on the side with more nodes. */
    bool mortar_on_finer_side = false;

    /** Whether the input declares any contact interface. */
    bool
    declares_interfaces() const
    {
      return all_shared_faces || !interfaces.empty();
    }
    /** Closed-form contact tractions to measure the pairs against. */
    bool compute_traction_errors = false;
    std::shared_ptr<Functions::ParsedFunction<2>> exact_normal_traction;
    std::shared_ptr<Functions::ParsedFunction<2>> exact_tangential_traction;
  };

  /**
   * One side of a contact pair: the displacement of the side is the
   * weighted sum sum_i w_i u(node_i) of its nodes' displacements, and the
   * pair's force on the side goes to its nodes with the same weights (so
   * that the two are work-conjugate). A node-to-node pair has one node of
   * weight 1; a mortar or node-to-segment side has several.
   */
  template <int dim>
  struct PairSide
  {
    /** One node: its dim DoFs and its weight. */
    struct Node
    {
      std::array<types::global_dof_index, dim> dofs;
      double                                   weight = 1.;
    };

    /** Index into the vector of blocks. */
    unsigned int      block = 0;
    std::vector<Node> nodes;
    /** Where the side is, for messages and output. */
    Point<dim> point;
  };

  /**
   * A contact pair: side a on one block facing side b on another. The
   * force r acts on b and -r on a; r_N = r.n > 0 is compression; the gap
   * is g0 + (u_b - u_a).n. The normal points from a to b: the outward
   * normal of a where the sides coincide, the line joining them where a gap
   * separates them (the common normal of two curved surfaces, so that
   * closing the gap is not mistaken for slip).
   */
  template <int dim>
  struct ContactPair
  {
    unsigned int  interface;
    PairSide<dim> a;
    PairSide<dim> b;
    /** Rows: normal, then the dim-1 tangents; orthonormal. */
    Tensor<2, dim> frame;
    double         initial_gap;
    /** Tributary area (length in 2D, per unit thickness). */
    double area;
    /** Friction, cohesion and tensile strength of the joint. */
    JointLaw joint;
    /**
     * Index into ContactParameters::joint_sets of the set that gave the
     * law (numbers::invalid_unsigned_int: none), for what is named by set
     * later ('Mode = reliability').
     */
    unsigned int joint_set = numbers::invalid_unsigned_int;
    /**
     * Both nodes on a support that fixes a direction oblique to the
     * interface (a fault meeting a roller boundary): the frame is then the
     * global axes, the supports carry the force in the fixed direction, and
     * the pair stays stuck in the free one. Such a pair has fewer free
     * relative motions than contact conditions; tying it keeps the
     * geostatic state in equilibrium.
     */
    bool tied = false;
    /**
     * A pair into which resolve_cross_points() merged the pairs closing a
     * loop at a point of three or more blocks: the node-to-node pairs it
     * stands for, itself as it was found first, then those merged into it.
     * Empty for every other pair. The elastic model needs the merged pair
     * (its rows independent); rigid-block statics needs each of these, for
     * a force at the point itself is a force the blocks can exchange
     * there (the certificate, ContactSolver::statics()).
     */
    std::vector<ContactPair<dim>> cross_point_pairs;

    /** Side a (@p sign < 0, force -r) or side b (@p sign > 0, force r). */
    const PairSide<dim> &
    side(const int sign) const
    {
      return sign < 0 ? a : b;
    }

    /** Midpoint of the two sides. */
    Point<dim>
    midpoint() const
    {
      return Point<dim>(0.5 * (a.point + b.point));
    }

    /**
     * u_b - u_a in global components (sum_i w_i u(node_i) over each side),
     * from the displacements of @p blocks (Block::get_solution()).
     */
    Tensor<1, dim>
    relative_displacement(
      const std::vector<std::unique_ptr<Block<dim>>> &blocks) const;
  };



  /**
   * The orthonormal frame of a pair whose normal is @p normal (any length):
   * rows normal, then the tangents.
   */
  template <int dim>
  Tensor<2, dim>
  frame_of_normal(const Tensor<1, dim> &normal);



  /**
   * Finds the contact pairs of every declared interface (with
   * 'Interfaces = all' first adding to @p parameters every pair of blocks
   * that share faces, with its joint set's law): coincident support
   * points (initial gap 0), or, where a gap separates the surfaces, mutually
   * nearest support points within the search distance. Each pair gets its
   * frame and the tributary area of its nodes, which is their lumped
   * (Gauss-Lobatto) boundary weight, the mean of the two sides. Nodes left
   * without a partner, or matched ambiguously, end the run with their count
   * and coordinates. Pairs on a support oblique to their interface are
   * tied (ContactPair::tied). Where three or more blocks meet, the pairs
   * are made free of loops by resolve_cross_points() (cross_points.h).
   * The pairs of found interfaces on faces of @p joint_faces' groups take
   * the law of the joint set that names the group (assign_joint_sets()).
   */
  template <int dim>
  std::vector<ContactPair<dim>>
  find_contact_pairs(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                     ContactParameters                              &parameters,
                     const JointFaces<dim> &joint_faces,
                     ConditionalOStream    &pcout);
} // namespace mbfem

#endif

#ifndef mbfem_contact_interface_h
#define mbfem_contact_interface_h

#include <mbfem/block.h>

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
    bool         by_blocks            = true;
    unsigned int side_a               = 0;
    unsigned int side_b               = 0;
    double       friction_coefficient = 0.;
    double       cohesion             = 0.;
    double       tensile_strength     = 0.;
    std::string  description;
  };

  /** Subsection "Contact": the interfaces and their Mohr-Coulomb data. */
  struct ContactParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    std::vector<InterfaceDeclaration> interfaces;
    double                            search_distance = 0.;
    unsigned int                      max_iterations  = 100;
    /** "condensed", "monolithic" or "both" (see the entry's text). */
    std::string formulation = "condensed";

    /** Closed-form contact tractions to measure the pairs against. */
    bool compute_traction_errors = false;
    std::shared_ptr<Functions::ParsedFunction<2>> exact_normal_traction;
    std::shared_ptr<Functions::ParsedFunction<2>> exact_tangential_traction;
  };

  /**
   * A contact pair: a node of block a facing a node of block b. The force
   * r acts on b and -r on a; r_N = r.n > 0 is compression; the gap is
   * g0 + (u_b - u_a).n. The normal points from a to b: the outward normal
   * of a where the nodes coincide, the line joining them where a gap
   * separates them (the common normal of two curved surfaces, so that
   * closing the gap is not mistaken for slip).
   */
  template <int dim>
  struct ContactPair
  {
    unsigned int interface;
    unsigned int block_a; // index into the vector of blocks
    unsigned int block_b;
    std::array<types::global_dof_index, dim> dofs_a;
    std::array<types::global_dof_index, dim> dofs_b;
    Point<dim>                               point_a;
    Point<dim>                               point_b;
    /** Rows: normal, then the dim-1 tangents; orthonormal. */
    Tensor<2, dim> frame;
    double         initial_gap;
    /** Tributary area (length in 2D, per unit thickness). */
    double area;
    double friction_coefficient;
    double cohesion;
    double tensile_strength;
    /**
     * Both nodes on a support that fixes a direction oblique to the
     * interface (a fault meeting a roller boundary): the frame is then the
     * global axes, the supports carry the force in the fixed direction, and
     * the pair stays stuck in the free one. Such a pair has fewer free
     * relative motions than contact conditions; tying it keeps the
     * geostatic state in equilibrium.
     */
    bool tied = false;
  };

  /**
   * Finds the contact pairs of every declared interface: coincident support
   * points (initial gap 0), or, where a gap separates the surfaces, mutually
   * nearest support points within the search distance. Each pair gets its
   * frame and the tributary area of its nodes, which is their lumped
   * (Gauss-Lobatto) boundary weight, the mean of the two sides. Nodes left
   * without a partner, or matched ambiguously, end the run with their count
   * and coordinates. Pairs on a support oblique to their interface are
   * tied (ContactPair::tied).
   */
  template <int dim>
  std::vector<ContactPair<dim>>
  find_contact_pairs(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                     const ContactParameters                        &parameters,
                     ConditionalOStream                             &pcout);
} // namespace mbfem

#endif

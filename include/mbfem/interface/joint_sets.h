#ifndef mbfem_interface_joint_sets_h
#define mbfem_interface_joint_sets_h

#include <mbfem/interface/joint_law.h>

#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * A set of joints with one Mohr-Coulomb law, recognised by orientation:
   * a jointed rock mass is cut by a few families of near-parallel joints
   * (bedding, one or two cross sets), and what a geologist knows about each
   * family is its dip, dip direction and strength. An interface found by
   * 'Contact/Interfaces = all' belongs to the first set whose plane is
   * within the set's tolerance of the interface's mean plane; the others
   * keep the default law (the 'Friction coefficient', 'Cohesion' and
   * 'Tensile strength' entries).
   *
   * Orientation as in the field: dip in [0, 90] degrees from the
   * horizontal, dip direction the azimuth (clockwise from north = +y in 3D)
   * towards which the plane dips. In 2D the section is the x-y plane with y
   * up and x to the east: dip direction 90 dips towards +x, 270 towards -x.
   * The upward normal of a set's plane is therefore
   *   3D: (sin(dip) sin(dd), sin(dip) cos(dd), cos(dip)),
   *   2D: (sin(dip) sin(dd), cos(dip)),
   * and an interface of unit normal n belongs to the set if the angle
   * between the two planes, acos(|n . normal|), is at most the tolerance
   * (so the sign of n, i.e. which block is side a, does not matter).
   */
  struct JointSet
  {
    std::string name;
    double      dip           = 0.;
    double      dip_direction = 0.;
    double      tolerance     = 5.;
    JointLaw    joint;
    /**
     * For 'Mesh/Source = rock mass': the spacing of the set's planes and
     * a point one of them passes through (empty: the domain's origin).
     * Spacing 0 with a point: one plane (a fault); without: a set that
     * only gives the law of joints a mesh file has.
     */
    double              spacing = 0.;
    std::vector<double> point;
    /**
     * 'group name': the set is the joints of a mesh file's physical group
     * of that name (curves in 2D, surfaces in 3D, between blocks), and
     * claims their faces whatever their orientation; empty: a set by
     * orientation.
     */
    std::string group;

    /** Upward unit normal of the set's plane. */
    template <int dim>
    Tensor<1, dim>
    normal() const;

    /** Whether a plane of unit normal @p n belongs to the set. */
    template <int dim>
    bool
    contains(const Tensor<1, dim> &n) const;
  };

  /**
   * Reads 'Contact/Joint sets': sets separated by ';', each
   * 'name: key value, key value, ...' with the keys dip, dip direction,
   * tolerance (degrees), friction, cohesion, tensile strength, spacing,
   * point (2 or 3 numbers separated by spaces) and group (a name). Strength
   * values not given are those of @p defaults. Throws with the text that
   * could not be read.
   */
  std::vector<JointSet>
  parse_joint_sets(const std::string &text, const JointLaw &defaults);
} // namespace mbfem

#endif

#ifndef mbfem_interface_joint_assignment_h
#define mbfem_interface_joint_assignment_h

#include <mbfem/interface/contact_interface.h>
#include <mbfem/mesh/joint_faces.h>

#include <deal.II/base/conditional_ostream.h>

#include <vector>

namespace mbfem
{
  using namespace dealii;

  /** Where the pairs meet the mesh's joint groups (JointFaces). */
  struct PairGroups
  {
    /** The group of each pair's faces, or numbers::invalid_unsigned_int. */
    std::vector<unsigned int> of_pair;
    /** Per group, the area of its faces that lie between two blocks. */
    std::vector<double> area_between_blocks;
  };

  /**
   * The laws of the pairs of every interface found by 'Interfaces = all':
   * a pair on a face of a mesh joint group that a joint set names ('group
   * name') takes that set's law; the other pairs of the interface take the
   * first set (without a group) whose plane contains their mean plane, or
   * the default law. The interface is named by the set of most of its
   * area (for 'Water pressure' and the screen). Declared interfaces keep
   * their own law. Prints a line per mesh group, and the interfaces whose
   * pairs fall in more than one set. Throws if a set names a group the
   * mesh does not have between two blocks.
   */
  template <int dim>
  void
  assign_joint_sets(ContactParameters             &parameters,
                    const JointFaces<dim>         &joint_faces,
                    const PairGroups              &groups,
                    std::vector<ContactPair<dim>> &pairs,
                    ConditionalOStream            &pcout);
} // namespace mbfem

#endif

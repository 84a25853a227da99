#ifndef mbfem_mesh_joint_faces_h
#define mbfem_mesh_joint_faces_h

#include <mbfem/mesh/gmsh_check.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The joints of a hand-made gmsh mesh by physical group: the curves (2D)
   * or surfaces (3D) between blocks that the mesh puts in named groups, so
   * that 'Contact/Joint sets' entries with a 'group' give their faces a
   * law. A face of a block is found by where its centre lies, not by its
   * index, so that the groups survive the copy of each block's cells into
   * its own triangulation and any refinement of the blocks afterwards.
   */
  template <int dim>
  class JointFaces
  {
  public:
    JointFaces() = default;

    /** The joints read from a gmsh file (the mesh's coordinates). */
    explicit JointFaces(const GmshJointElements &elements);

    /** The number of groups (0: the mesh has no joints in groups). */
    unsigned int
    n_groups() const
    {
      return names.size();
    }

    /** The name of group @p g (its physical name, or its number). */
    const std::string &
    name(const unsigned int g) const
    {
      return names[g];
    }

    /** The area (length in 2D) of the faces of group @p g in the mesh. */
    double
    area(const unsigned int g) const
    {
      return areas[g];
    }

    /**
     * The group whose faces contain @p point (the centre of a block's
     * face), or numbers::invalid_unsigned_int.
     */
    unsigned int
    group_of(const Point<dim> &point) const;

  private:
    /** A joint element: its group and corners (in gmsh's order). */
    struct Face
    {
      unsigned int            group;
      std::vector<Point<dim>> corners;
      Point<dim>              centre;
      Tensor<1, dim>          normal;
    };

    bool
    contains(const Face &face, const Point<dim> &point) const;

    std::array<long long, dim>
    bin_of(const Point<dim> &point) const;

    std::vector<std::string> names;
    std::vector<double>      areas;
    std::vector<Face>        faces;
    /** Faces by the bin of their centre; a bin is as wide as the largest. */
    std::map<std::array<long long, dim>, std::vector<unsigned int>> bins;
    double bin_size = 1.;
    /** Distance from a face's plane that still counts as on it. */
    double tolerance = 0.;
  };
} // namespace mbfem

#endif

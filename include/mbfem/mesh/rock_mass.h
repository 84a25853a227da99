#ifndef mbfem_mesh_rock_mass_h
#define mbfem_mesh_rock_mass_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * A family of parallel joint planes as the rock mass generator takes it:
   * the set's name, the unit normal of its planes (3 components; the third
   * 0 in 2D), the spacing between planes (0: one plane, a fault) and a
   * point one of them passes through. The laws of the joints are not the
   * generator's business: the contact set-up recognises each joint by its
   * orientation (JointSet).
   */
  struct JointPlanes
  {
    std::string           name;
    std::array<double, 3> normal{};
    double                spacing = 0.;
    std::array<double, 3> point{};
  };

  /**
   * 'Mesh/Source = rock mass': the domain that the joint sets cut into
   * blocks ('Mesh/Rock mass') and the size of its elements. The domain is
   * a box (a rectangle in 2D) by its lower corner and its size, or a
   * slope: a profile in the vertical plane through x (its face dipping
   * towards +x), extruded along y in 3D, optionally on a base that the
   * joints do not cut (the rock the slope was cut from).
   */
  struct RockMassParameters
  {
    /** Declares the subsection 'Rock mass' (in 'Mesh', entered). */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads it, in 'Mesh' (entered). */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * The lowest corner and the extents, dim numbers each (checked against
     * the model's dimension by build_rock_mass()).
     */
    std::vector<double> origin, size;
    /** "box", "slope" or "file". */
    std::string domain = "box";
    /**
     * For "file": a geometry gmsh reads (.brep, .step, .stp, or a .geo of
     * the OpenCASCADE kernel), each of its volumes (surfaces in 2D) cut by
     * the joints; resolved against the parameter file's folder.
     */
    std::string geometry_file;
    /**
     * The slope (Origin: the foot of its back, at the level of its toe):
     * height, dip of the face in degrees, width of the crest from the back
     * to the top of the face, length along y (3D).
     */
    double slope_height = 10., face_angle = 60., crest_width = 10.,
           slope_length = 10.;
    /** The base under and behind the slope: depth, behind, in front. */
    std::array<double, 3> base{};
    /** The target edge length of the blocks' elements. */
    double mesh_size = 1.;
    /**
     * "split": gmsh's tetrahedra (triangles) split into hexahedra
     * (quadrilaterals), any block; "structured": transfinite hexahedra
     * (quadrilaterals), for blocks that are all hexahedra
     * (quadrilaterals), as a box cut by three (two) sets.
     */
    std::string block_meshes = "split";
  };

  /** What the generator built, for the screen and the checks. */
  struct RockMassSummary
  {
    unsigned int n_blocks = 0;
    /** Planes of each set that cut the domain, in the order given. */
    std::vector<unsigned int> planes_per_set;
    /** Whether block 1 is the uncut base of a slope. */
    bool has_base = false;
    /** The domain's volume (area in 2D) and the blocks' sum of it. */
    double domain_measure = 0., blocks_measure = 0.;
    double smallest = 0., largest = 0.;
    /** Blocks smaller than half an element (mesh_size^dim / 2). */
    unsigned int n_small = 0;
    unsigned int n_cells = 0;
  };

  /**
   * Cuts the domain of @p parameters by every plane of @p sets (gmsh's
   * OpenCASCADE fragments: the faces two blocks share are one surface, so
   * their meshes match node to node), meshes each block with hexahedra
   * (quadrilaterals in 2D; gmsh's subdivision of its tetrahedra, its
   * full-quad recombination in 2D), and writes @p msh_file (MSH 2.2):
   * one physical group per block, numbered from 1 by the blocks' centres
   * (lowest first, then y, then x; a slope's base is block 1), and
   * boundary ids on the faces of the domain's bounding box: 1 bottom,
   * 2 top, 3 x = min, 4 x = max, 5 y = min, 6 y = max (3D; in 2D bottom
   * and top are y = min and y = max). Throws naming the set where a set
   * misses the domain or is spaced closer than the mesh size, and with
   * gmsh's message where gmsh fails.
   */
  template <int dim>
  RockMassSummary
  build_rock_mass(const RockMassParameters       &parameters,
                  const std::vector<JointPlanes> &sets,
                  const std::string              &msh_file);
} // namespace mbfem

#endif

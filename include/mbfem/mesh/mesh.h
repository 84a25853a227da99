#ifndef mbfem_mesh_mesh_h
#define mbfem_mesh_mesh_h

#include <mbfem/mesh/joint_faces.h>
#include <mbfem/mesh/rock_mass.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * Where the mesh comes from: a gmsh file, whose physical groups give the
   * material ids (one per block) and boundary ids (loaded faces, supports,
   * contact surfaces), or one of deal.II's GridGenerator functions called by
   * name, which is what the verification problems use.
   */
  struct MeshParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * @p input_folder is the folder of the parameter file: relative mesh
     * paths are taken from there, so a run works from any working folder.
     */
    void
    parse_parameters(ParameterHandler &prm, const std::string &input_folder);

    std::string source;
    /**
     * The gmsh file: read (Source = gmsh), or written by the rock mass
     * generator before it is read (Source = rock mass).
     */
    std::string mesh_file;
    /** Source = rock mass: the domain the joint sets cut. */
    RockMassParameters rock_mass;
    std::string        generator_name;
    std::string        generator_arguments;
    unsigned int       initial_refinement = 0;

    /** Expression of x, y(, z) giving the block of the cell at that centre. */
    std::string block_id_function;

    /** Block id -> refinements of that block after extraction. */
    std::map<unsigned int, unsigned int> block_refinements;

    /** Boundary id -> centre of the circle (sphere) that face lies on. */
    std::map<types::boundary_id, std::vector<double>> circular_boundaries;
  };

  /**
   * Boundary id given, in a block's own triangulation, to the faces it
   * shares with block @p neighbour in the mesh: the two sides of a contact
   * interface declared by blocks ("blocks 1:2").
   */
  inline types::boundary_id
  interface_boundary_id(const types::material_id neighbour)
  {
    return 10000 + neighbour;
  }

  /** The material ids of the mesh, i.e. its blocks, in increasing order. */
  template <int dim>
  std::vector<types::material_id>
  block_ids(const Triangulation<dim> &mesh);

  /**
   * Copies the active cells of @p mesh with material id @p id into
   * @p block as its coarse mesh, with their manifolds. Faces on the boundary
   * of @p mesh keep their boundary ids; faces shared with a cell of another
   * block get interface_boundary_id(that block).
   */
  template <int dim>
  void
  extract_block(const Triangulation<dim> &mesh,
                const types::material_id  id,
                Triangulation<dim>       &block);

  /**
   * Builds the mesh described by @p parameters into @p triangulation, and
   * into @p joint_faces (if given) the faces of a gmsh file's joints in
   * physical groups.
   */
  template <int dim>
  void
  create_mesh(const MeshParameters &parameters,
              Triangulation<dim>   &triangulation,
              JointFaces<dim>      *joint_faces = nullptr);

  /** The boundary ids present on the boundary of @p triangulation. */
  template <int dim>
  std::set<types::boundary_id>
  boundary_ids_of(const Triangulation<dim> &triangulation);

  /**
   * The largest distance between two boundary vertices of @p triangulation:
   * the value of GridTools::diameter, which in deal.II 9.4 loops over all
   * pairs of vertices (4e9 pairs, 5 s, for a 300 x 300 mesh; hours for
   * 1e6 cells), found over the pairs of boundary vertices only.
   */
  template <int dim>
  double
  diameter(const Triangulation<dim> &triangulation);
} // namespace mbfem

#endif

#ifndef mbfem_mesh_h
#define mbfem_mesh_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include <set>
#include <string>

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

    std::string  source;
    std::string  mesh_file;
    std::string  generator_name;
    std::string  generator_arguments;
    unsigned int initial_refinement = 0;
  };

  /** Builds the mesh described by @p parameters into @p triangulation. */
  template <int dim>
  void
  create_mesh(const MeshParameters &parameters,
              Triangulation<dim>   &triangulation);

  /** The boundary ids present on the boundary of @p triangulation. */
  template <int dim>
  std::set<types::boundary_id>
  boundary_ids_of(const Triangulation<dim> &triangulation);
} // namespace mbfem

#endif

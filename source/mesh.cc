#include <mbfem/mesh.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <fstream>

namespace mbfem
{
  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      prm.declare_entry(
        "Source",
        "generator",
        Patterns::Selection("gmsh|generator"),
        "Where the mesh comes from. 'gmsh': read 'Mesh file' (a gmsh .msh "
        "file; physical groups of cells give the material id, i.e. the "
        "block, and physical groups of faces give boundary ids). "
        "'generator': call the deal.II GridGenerator function named in "
        "'Generator name' with 'Generator arguments'.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "Path of the gmsh .msh file, for Source = gmsh. A "
                        "relative path is taken from the folder of the "
                        "parameter file.");
      prm.declare_entry(
        "Generator name",
        "subdivided_hyper_rectangle",
        Patterns::Anything(),
        "Name of a deal.II GridGenerator function, e.g. "
        "subdivided_hyper_rectangle, hyper_rectangle, quarter_hyper_shell, "
        "hyper_shell, plate_with_a_hole (see the deal.II documentation of "
        "GridGenerator::generate_from_name_and_arguments).");
      prm.declare_entry(
        "Generator arguments",
        "5,1 : 0,0 : 10,2 : true",
        Patterns::Anything(),
        "Arguments of the generator function, separated by ':' in the order "
        "of its C++ signature, points as comma-separated coordinates. The "
        "default makes a 10 x 2 rectangle of 5 x 1 cells with boundary ids "
        "0 (x = 0), 1 (x = 10), 2 (y = 0), 3 (y = 2).");
      prm.declare_entry("Initial global refinement",
                        "0",
                        Patterns::Integer(0, 12),
                        "Number of times every cell is split (in two in each "
                        "direction) after the mesh is made.");
    }
    prm.leave_subsection();
  }



  void
  MeshParameters::parse_parameters(ParameterHandler  &prm,
                                   const std::string &input_folder)
  {
    prm.enter_subsection("Mesh");
    {
      source              = prm.get("Source");
      mesh_file           = prm.get("Mesh file");
      generator_name      = prm.get("Generator name");
      generator_arguments = prm.get("Generator arguments");
      initial_refinement  = prm.get_integer("Initial global refinement");
    }
    prm.leave_subsection();

    if (source == "gmsh")
      {
        AssertThrow(!mesh_file.empty(),
                    ExcMessage("Mesh/Source is gmsh but 'Mesh/Mesh file' is "
                               "empty: name the .msh file to read."));
        if (mesh_file.front() != '/' && !input_folder.empty())
          mesh_file = input_folder + "/" + mesh_file;
      }
  }



  template <int dim>
  void
  create_mesh(const MeshParameters &parameters,
              Triangulation<dim>   &triangulation)
  {
    if (parameters.source == "gmsh")
      {
        std::ifstream in(parameters.mesh_file);
        AssertThrow(in.good(),
                    ExcMessage("Cannot open the mesh file <" +
                               parameters.mesh_file +
                               "> named by 'Mesh/Mesh file'."));
        GridIn<dim> grid_in(triangulation);
        try
          {
            grid_in.read_msh(in);
          }
        catch (ExceptionBase &e)
          {
            std::ostringstream message;
            e.print_info(message);
            AssertThrow(false,
                        ExcMessage("Could not read the gmsh file <" +
                                   parameters.mesh_file + "> as a " +
                                   std::to_string(dim) +
                                   "D mesh: " + message.str()));
          }
      }
    else
      {
        try
          {
            GridGenerator::generate_from_name_and_arguments(
              triangulation,
              parameters.generator_name,
              parameters.generator_arguments);
          }
        catch (std::exception &e)
          {
            AssertThrow(
              false,
              ExcMessage("Mesh/Generator name = '" + parameters.generator_name +
                         "' with Mesh/Generator arguments = '" +
                         parameters.generator_arguments + "' did not make a " +
                         std::to_string(dim) + "D mesh: " + e.what()));
          }
      }
    triangulation.refine_global(parameters.initial_refinement);
  }



  template <int dim>
  std::set<types::boundary_id>
  boundary_ids_of(const Triangulation<dim> &triangulation)
  {
    const std::vector<types::boundary_id> ids =
      triangulation.get_boundary_ids();
    return std::set<types::boundary_id>(ids.begin(), ids.end());
  }



  template void
  create_mesh(const MeshParameters &, Triangulation<2> &);
  template void
  create_mesh(const MeshParameters &, Triangulation<3> &);
  template std::set<types::boundary_id>
  boundary_ids_of(const Triangulation<2> &);
  template std::set<types::boundary_id>
  boundary_ids_of(const Triangulation<3> &);
} // namespace mbfem

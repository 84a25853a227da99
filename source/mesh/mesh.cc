#include <mbfem/base/exceptions.h>
#include <mbfem/base/text_input.h>
#include <mbfem/mesh/gmsh_check.h>
#include <mbfem/mesh/mesh.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <regex>
#include <sstream>

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
        Patterns::Selection("gmsh|generator|rock mass"),
        "Where the mesh comes from. 'gmsh': read 'Mesh file' (a gmsh .msh "
        "file; physical groups of cells give the material id, i.e. the "
        "block, and physical groups of faces give boundary ids). "
        "'generator': call the deal.II GridGenerator function named in "
        "'Generator name' with 'Generator arguments'. 'rock mass': the box "
        "of 'Rock mass' cut into blocks by the planes of every joint set of "
        "'Contact/Joint sets' that has a spacing, meshed by gmsh and written "
        "to <Output directory>/<Base name>-rock-mass.msh before it is read "
        "(doc/rock_mass.md).");
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
      prm.declare_entry(
        "Block id function",
        "",
        Patterns::Anything(),
        "Splits the mesh into blocks: an expression of the cell centre "
        "(x, y(, z)) whose value, rounded, is the cell's material id, i.e. "
        "its block; e.g. '(y > 1) + (y > 2)' cuts a column into three "
        "stacked blocks. Empty: a gmsh mesh keeps the material ids of its "
        "physical groups, a generated mesh is one block (id 0) whatever ids "
        "the generator gave its cells (colorize=true numbers cells by "
        "quadrant).");
      prm.declare_entry(
        "Circular boundaries",
        "",
        Patterns::Anything(),
        "Faces that lie on a circle (2D) or sphere (3D), as 'id: centre' "
        "separated by ';', e.g. '3: 0,-8; 4: 0,8'. Refinement puts new "
        "vertices on the circle and MappingQ curves the cells, so a gmsh "
        "mesh of a disk stays round. deal.II's generators set their own.");
      prm.declare_entry("Initial global refinement",
                        "0",
                        Patterns::Integer(0, 12),
                        "Number of times every cell is split (in two in each "
                        "direction) after the mesh is made.");
      prm.declare_entry(
        "Block refinements",
        "",
        Patterns::Anything(),
        "Further global refinements of single blocks after they are taken "
        "from the mesh, 'id: n' separated by ';' (e.g. '1: 1' halves the "
        "cells of block 1 once more). The blocks' meshes then no longer "
        "match at their common faces: declare those interfaces 'mortar' "
        "(Contact/Interfaces).");
    }
    RockMassParameters::declare_parameters(prm);
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
      block_id_function   = prm.get("Block id function");
      rock_mass.parse_parameters(prm);
      if (!rock_mass.geometry_file.empty() &&
          rock_mass.geometry_file.front() != '/' && !input_folder.empty())
        rock_mass.geometry_file = input_folder + "/" + rock_mass.geometry_file;
      block_refinements = parse_id_values(prm.get("Block refinements"),
                                          "Mesh/Block refinements",
                                          0,
                                          6);
      circular_boundaries.clear();
      const std::string where = "Mesh/Circular boundaries";
      for (const auto &entry :
           split_list(prm.get("Circular boundaries"), ';', where))
        {
          const auto parts = Utilities::split_string_list(entry, ':');
          AssertThrow(parts.size() == 2,
                      ExcMessage(where + ": cannot read '" + entry +
                                 "'; write 'id: x,y(,z)'."));
          const auto ids = parse_id_list(parts[0], where);
          AssertThrow(ids.size() == 1,
                      ExcMessage(where + ": '" + entry +
                                 "' needs one boundary id before ':' (give "
                                 "each id its own entry, separated by ';')."));
          const unsigned int id = ids[0];
          AssertThrow(circular_boundaries.count(id) == 0,
                      ExcMessage(where + ": boundary id " + parts[0] +
                                 " is given twice."));
          for (const auto &x : split_list(parts[1], ',', where))
            circular_boundaries[id].push_back(
              parse_finite_number(x, where + ", id " + parts[0]));
        }
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



  namespace
  {
    /**
     * The numbers in 'Generator arguments' that deal.II would convert
     * without a check: a count past 32 bits wraps around to a small or zero
     * one (4294967296 cells became 0 and crashed), and inf or nan make
     * non-finite vertices.
     */
    void
    check_generator_numbers(const std::string &arguments)
    {
      const std::regex number("[-+]?[0-9.]+([eE][-+]?[0-9]+)?|inf|nan",
                              std::regex::icase);
      const std::regex count("[-+]?[0-9]+");
      for (auto it =
             std::sregex_iterator(arguments.begin(), arguments.end(), number);
           it != std::sregex_iterator();
           ++it)
        {
          const std::string text    = it->str();
          const double      value   = std::strtod(text.c_str(), nullptr);
          const bool        integer = std::regex_match(text, count);
          AssertThrow(std::isfinite(value) &&
                        (!integer || std::abs(value) < 2147483648.),
                      ExcMessage("Mesh/Generator arguments = '" + arguments +
                                 "': " + text +
                                 " is not a number mbfem passes to deal.II "
                                 "(numbers must be finite, and whole numbers "
                                 "such as counts of cells below 2^31)."));
        }
    }

    /**
     * More cells than a direct solver on one process can handle on a
     * machine of 24 GB: a 1000 x 1000 block of FE_Q(1) (2e6 DoFs) peaked at
     * 6.6 GB with KLU; 3000 x 3000 cells ran out of memory.
     */
    constexpr double max_cells = 2e6;

    /**
     * The counts of cells of subdivided_hyper_rectangle/cube: deal.II
     * converts -1 to 4294967295 cells (and runs out of memory) and reads a
     * list of the wrong length beyond its end.
     */
    template <int dim>
    void
    check_subdivisions(const std::string &name,
                       const std::string &arguments,
                       const unsigned int refinement)
    {
      const auto fields = Utilities::split_string_list(arguments, ':');
      if (name.rfind("subdivided_hyper_", 0) != 0 || fields.empty() ||
          fields[0].find_first_of(".;eE") != std::string::npos)
        return; // not counts (step sizes are checked by deal.II)
      const auto        counts  = Utilities::split_string_list(fields[0], ',');
      const bool        is_cube = (name == "subdivided_hyper_cube");
      double            n_cells = 1.;
      const std::string where =
        "Mesh/Generator arguments = '" + arguments + "' for " + name + ": ";
      AssertThrow(counts.size() == (is_cube ? 1u : unsigned(dim)),
                  ExcMessage(where + "the first argument needs " +
                             std::to_string(is_cube ? 1 : dim) +
                             " count(s) of cells, got '" + fields[0] + "'."));
      for (const auto &count : counts)
        {
          const double n = std::strtod(count.c_str(), nullptr);
          AssertThrow(n >= 1. && n <= max_cells,
                      ExcMessage(where + "the count of cells '" + count +
                                 "' must be a whole number from 1 to " +
                                 std::to_string(int(max_cells)) + "."));
          n_cells *= (is_cube ? std::pow(n, dim) : n);
        }
      // Checked before the mesh is made: 9e6 coarse cells alone took 38 s
      // and 3.2 GB before the refinement was refused.
      n_cells *= std::pow(2., dim * refinement);
      std::ostringstream count;
      count << n_cells;
      AssertThrow(n_cells <= max_cells,
                  ExcMessage(where + "that makes " + count.str() + " cells" +
                             (refinement > 0 ?
                                " after 'Initial global refinement' = " +
                                  std::to_string(refinement) :
                                std::string()) +
                             ", more than mbfem can solve (" +
                             std::to_string(int(max_cells)) + ")."));
    }

    template <int dim>
    void
    generate_mesh(const MeshParameters &parameters,
                  Triangulation<dim>   &triangulation)
    {
      const std::string what =
        "Mesh/Generator name = '" + parameters.generator_name +
        "' with Mesh/Generator arguments = '" + parameters.generator_arguments +
        "' did not make a " + std::to_string(dim) + "D mesh: ";
      check_generator_numbers(parameters.generator_arguments);
      check_subdivisions<dim>(parameters.generator_name,
                              parameters.generator_arguments,
                              parameters.initial_refinement);
      // Only the message of deal.II's exception: what() would add the
      // source location and a stack trace of deal.II's internals.
      try
        {
          GridGenerator::generate_from_name_and_arguments(
            triangulation,
            parameters.generator_name,
            parameters.generator_arguments);
        }
      catch (ExceptionBase &e)
        {
          AssertThrow(false, ExcMessage(what + Utilities::trim(message_of(e))));
        }
      catch (std::exception &e)
        {
          AssertThrow(false, ExcMessage(what + e.what()));
        }
      AssertThrow(triangulation.n_active_cells() > 0,
                  ExcMessage(what + "it has no cells."));
    }
  } // namespace



  namespace
  {
    /**
     * Reads the gmsh file of 'Mesh/Mesh file' into @p triangulation;
     * returns its joints (faces between cells in physical groups), which
     * GridIn does not read.
     */
    template <int dim>
    JointFaces<dim>
    read_gmsh_mesh(const MeshParameters &parameters,
                   Triangulation<dim>   &triangulation)
    {
      std::ifstream in(parameters.mesh_file);
      AssertThrow(in.good(),
                  ExcMessage("Cannot open the mesh file <" +
                             parameters.mesh_file +
                             "> named by 'Mesh/Mesh file': looked in the "
                             "folder <" +
                             std::filesystem::absolute(parameters.mesh_file)
                               .parent_path()
                               .lexically_normal()
                               .string() +
                             "> (a relative path is taken from the folder "
                             "of the parameter file that sets it)."));
      const GmshJointElements joints =
        check_gmsh_file(parameters.mesh_file,
                        dim,
                        parameters.block_id_function.empty());
      std::istringstream without_joints(joints.text_for_grid_in);
      GridIn<dim>        grid_in(triangulation);
      const std::string  what = "Could not read the gmsh file <" +
                               parameters.mesh_file + "> as a " +
                               std::to_string(dim) + "D mesh: ";
      try
        {
          grid_in.read_msh(joints.elements.empty() ?
                             static_cast<std::istream &>(in) :
                             without_joints);
        }
      catch (ExceptionBase &e)
        {
          AssertThrow(false, ExcMessage(what + Utilities::trim(message_of(e))));
        }
      catch (std::exception &e)
        {
          AssertThrow(false, ExcMessage(what + e.what()));
        }
      return JointFaces<dim>(joints);
    }



    /**
     * Material id = block: from 'Mesh/Block id function' if given, else 0
     * for a generated mesh (gmsh meshes keep their physical groups).
     */
    template <int dim>
    void
    assign_block_ids(const MeshParameters &parameters,
                     Triangulation<dim>   &triangulation)
    {
      if (!parameters.block_id_function.empty())
        {
          FunctionParser<dim> block_id;
          try
            {
              const QuietCerr quiet;
              block_id.initialize(FunctionParser<dim>::default_variable_names(),
                                  parameters.block_id_function,
                                  {});
              block_id.value(Point<dim>());
            }
          catch (ExceptionBase &e)
            {
              std::ostringstream message;
              e.print_info(message);
              AssertThrow(false,
                          ExcMessage("Mesh/Block id function '" +
                                     parameters.block_id_function +
                                     "' cannot be parsed: " + message.str()));
            }
          for (const auto &cell : triangulation.active_cell_iterators())
            {
              const double id = std::round(block_id.value(cell->center()));
              AssertThrow(id >= 0. && id < 10000.,
                          ExcMessage("Mesh/Block id function gives " +
                                     std::to_string(id) + " at (" +
                                     Utilities::to_string(cell->center()[0]) +
                                     ", ...): block ids are 0 to 9999."));
              cell->set_material_id(static_cast<types::material_id>(id));
            }
        }
      else if (parameters.source == "generator")
        for (const auto &cell : triangulation.active_cell_iterators())
          cell->set_material_id(0);
    }



    /**
     * The vertices of the faces with boundary id @p id lie on one circle
     * (sphere) about @p centre: a centre that is not the arc's, or an id
     * of a straight boundary, would make the manifold move the refined
     * and curved nodes to another geometry than the mesh's.
     */
    template <int dim>
    void
    check_on_circle(const Triangulation<dim> &triangulation,
                    const types::boundary_id  id,
                    const Point<dim>         &centre)
    {
      std::vector<Point<dim>> vertices;
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          for (const unsigned int v : face->vertex_indices())
            vertices.push_back(face->vertex(v));
      double r_min = std::numeric_limits<double>::infinity(), r_max = 0.;
      for (const auto &vertex : vertices)
        {
          r_min = std::min(r_min, vertex.distance(centre));
          r_max = std::max(r_max, vertex.distance(centre));
        }
      const BoundingBox<dim> box(vertices);
      // gmsh places the nodes of an arc on it to round-off; 1e-6 of the
      // radius leaves room for a mesh written with 10 digits.
      std::ostringstream text;
      text << "Mesh/Circular boundaries: the faces with boundary id " << id
           << " do not lie on a " << (dim == 2 ? "circle" : "sphere")
           << " about (" << centre << "): their vertices are " << r_min
           << " to " << r_max
           << " from it. Give the centre of the arc, and only ids of "
              "curved boundaries.";
      // A centre a million arc lengths away (1e308) makes every distance
      // equal in round-off: no circle the faces could follow.
      const double extent = box.side_length(0) + box.side_length(1) +
                            (dim == 3 ? box.side_length(dim - 1) : 0.);
      AssertThrow(r_max - r_min <= 1e-6 * r_max && r_min > 0. &&
                    r_max <= 1e6 * extent,
                  ExcMessage(text.str()));
    }



    /** A SphericalManifold on each face set of 'Mesh/Circular boundaries'. */
    template <int dim>
    void
    attach_circular_boundaries(const MeshParameters &parameters,
                               Triangulation<dim>   &triangulation)
    {
      types::manifold_id manifold = 100;
      for (const auto &[id, centre] : parameters.circular_boundaries)
        {
          AssertThrow(centre.size() == dim,
                      ExcMessage(
                        "Mesh/Circular boundaries: the centre for id " +
                        std::to_string(id) + " needs " + std::to_string(dim) +
                        " coordinates."));
          Point<dim> c;
          for (unsigned int d = 0; d < dim; ++d)
            c[d] = centre[d];
          bool found = false;
          for (const auto &face : triangulation.active_face_iterators())
            if (face->at_boundary() && face->boundary_id() == id)
              {
                face->set_all_manifold_ids(manifold);
                found = true;
              }
          AssertThrow(found,
                      ExcMessage("Mesh/Circular boundaries: the mesh has no "
                                 "face with boundary id " +
                                 std::to_string(id) + "."));
          check_on_circle(triangulation, id, c);
          triangulation.set_manifold(manifold, SphericalManifold<dim>(c));
          ++manifold;
        }
    }
  } // namespace



  template <int dim>
  void
  create_mesh(const MeshParameters &parameters,
              Triangulation<dim>   &triangulation,
              JointFaces<dim>      *joint_faces)
  {
    JointFaces<dim> joints;
    if (parameters.source == "gmsh" || parameters.source == "rock mass")
      joints = read_gmsh_mesh(parameters, triangulation);
    else
      generate_mesh(parameters, triangulation);
    if (joint_faces != nullptr)
      *joint_faces = joints;
    AssertThrow(triangulation.all_reference_cells_are_hyper_cube(),
                ExcMessage(
                  "The mesh " +
                  (parameters.source != "generator" ?
                     "<" + parameters.mesh_file + "> " :
                     std::string()) +
                  "has triangles or tetrahedra; mbfem's FE_Q elements "
                  "need quadrilaterals or hexahedra (in gmsh: "
                  "Mesh.RecombineAll = 1 and Mesh.SubdivisionAlgorithm "
                  "= 1 or 2)."));
    assign_block_ids(parameters, triangulation);
    attach_circular_boundaries(parameters, triangulation);
    AssertThrow(triangulation.n_active_cells() *
                    std::pow(2., dim * parameters.initial_refinement) <=
                  max_cells,
                ExcMessage("Mesh/Initial global refinement = " +
                           std::to_string(parameters.initial_refinement) +
                           " would make more cells than mbfem can solve (" +
                           std::to_string(int(max_cells)) + ")."));
    triangulation.refine_global(parameters.initial_refinement);
  }



  template <int dim>
  std::vector<types::material_id>
  block_ids(const Triangulation<dim> &mesh)
  {
    std::set<types::material_id> ids;
    for (const auto &cell : mesh.active_cell_iterators())
      ids.insert(cell->material_id());
    return std::vector<types::material_id>(ids.begin(), ids.end());
  }



  namespace
  {
    /**
     * The cells, boundary faces and vertices of one block as they are
     * collected from the whole mesh, for Triangulation::create_triangulation.
     */
    template <int dim>
    struct BlockMeshData
    {
      explicit BlockMeshData(const Triangulation<dim> &mesh)
        : mesh(mesh)
      {}

      /** The block's number of the mesh's vertex @p global (added once). */
      unsigned int
      number(const unsigned int global)
      {
        const auto [it, inserted] =
          vertex_number.emplace(global, vertices.size());
        if (inserted)
          vertices.push_back(mesh.get_vertices()[global]);
        return it->second;
      }

      const Triangulation<dim>            &mesh;
      std::map<unsigned int, unsigned int> vertex_number;
      std::vector<Point<dim>>              vertices;
      std::vector<CellData<dim>>           cells;
      SubCellData                          faces;
      std::set<unsigned int>               interior_faces;
    };



    /**
     * The boundary id face @p f of @p cell (of block @p id) gets in the
     * block, or false if the block need not list the face.
     */
    template <int dim>
    bool
    block_face_id(const typename Triangulation<dim>::active_cell_iterator &cell,
                  const unsigned int                                       f,
                  const types::material_id                                 id,
                  std::set<unsigned int> &interior_faces,
                  types::boundary_id     &boundary_id)
    {
      const auto face = cell->face(f);
      if (face->at_boundary())
        boundary_id = face->boundary_id();
      else if (cell->neighbor(f)->material_id() != id)
        boundary_id = interface_boundary_id(cell->neighbor(f)->material_id());
      else if (face->manifold_id() != numbers::flat_manifold_id &&
               interior_faces.insert(face->index()).second)
        // An interior face keeps its manifold: without it, it would be
        // flat in the block while its cells are curved, and MappingQ(p >=
        // 2) in 3D gives a wrong geometry.
        boundary_id = numbers::internal_face_boundary_id;
      else
        return false;
      return true;
    }



    /** Adds @p face with @p boundary_id, and in 3D its curved edges. */
    template <int dim, typename FaceIterator>
    void
    add_block_face(const FaceIterator      &face,
                   const types::boundary_id boundary_id,
                   BlockMeshData<dim>      &data)
    {
      CellData<dim - 1> face_data(face->n_vertices());
      for (const unsigned int v : face->vertex_indices())
        face_data.vertices[v] = data.number(face->vertex_index(v));
      face_data.boundary_id = boundary_id;
      face_data.manifold_id = face->manifold_id();
      if constexpr (dim == 2)
        data.faces.boundary_lines.push_back(face_data);
      else
        {
          data.faces.boundary_quads.push_back(face_data);
          // Edges of curved faces need their manifold too.
          for (const unsigned int l : face->line_indices())
            if (face->line(l)->manifold_id() != numbers::flat_manifold_id)
              {
                CellData<1> line(2);
                line.vertices[0] = data.number(face->line(l)->vertex_index(0));
                line.vertices[1] = data.number(face->line(l)->vertex_index(1));
                line.boundary_id = numbers::internal_face_boundary_id;
                line.manifold_id = face->line(l)->manifold_id();
                data.faces.boundary_lines.push_back(line);
              }
        }
    }



    /**
     * Every manifold the block's cells, faces and edges refer to (the
     * triangulation's own list may omit ids that only faces carry, and an
     * id without its manifold crashes MappingQ in a Release build).
     */
    template <int dim>
    void
    copy_manifolds(const BlockMeshData<dim> &data, Triangulation<dim> &block)
    {
      std::set<types::manifold_id> used;
      for (const auto &cell : data.cells)
        used.insert(cell.manifold_id);
      for (const auto &face : data.faces.boundary_lines)
        used.insert(face.manifold_id);
      for (const auto &face : data.faces.boundary_quads)
        used.insert(face.manifold_id);
      for (const auto manifold : used)
        if (manifold != numbers::flat_manifold_id)
          block.set_manifold(manifold, data.mesh.get_manifold(manifold));
    }
  } // namespace



  template <int dim>
  void
  extract_block(const Triangulation<dim> &mesh,
                const types::material_id  id,
                Triangulation<dim>       &block)
  {
    BlockMeshData<dim> data(mesh);
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->material_id() == id)
        {
          CellData<dim> cell_data(cell->n_vertices());
          for (const unsigned int v : cell->vertex_indices())
            cell_data.vertices[v] = data.number(cell->vertex_index(v));
          cell_data.material_id = id;
          cell_data.manifold_id = cell->manifold_id();
          data.cells.push_back(cell_data);

          for (const unsigned int f : cell->face_indices())
            {
              types::boundary_id boundary_id;
              if (block_face_id<dim>(
                    cell, f, id, data.interior_faces, boundary_id))
                add_block_face(cell->face(f), boundary_id, data);
            }
        }

    block.clear();
    block.create_triangulation(data.vertices, data.cells, data.faces);
    copy_manifolds(data, block);
  }



  template <int dim>
  std::set<types::boundary_id>
  boundary_ids_of(const Triangulation<dim> &triangulation)
  {
    const std::vector<types::boundary_id> ids =
      triangulation.get_boundary_ids();
    return std::set<types::boundary_id>(ids.begin(), ids.end());
  }



  template <int dim>
  double
  diameter(const Triangulation<dim> &triangulation)
  {
    std::vector<bool> on_boundary(triangulation.n_vertices(), false);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          for (const unsigned int v : face->vertex_indices())
            on_boundary[face->vertex_index(v)] = true;
    std::vector<Point<dim>> points;
    for (unsigned int v = 0; v < on_boundary.size(); ++v)
      if (on_boundary[v])
        points.push_back(triangulation.get_vertices()[v]);
    // The largest distance over all pairs, as the plain double loop finds
    // it, but a point is paired only if its distance to the farthest
    // corner of the bounding box could beat the largest so far: no other
    // point is farther from it than that corner, in floating point too
    // (differences and sums round monotonically). On a block whose corners
    // are mesh vertices this leaves a few points, not N^2 / 2 pairs (some
    // 0.5 s a call on a beam of 25920 cells).
    if (points.empty())
      return 0.;
    const auto [low, high] = BoundingBox<dim>(points).get_boundary_points();
    std::vector<std::pair<double, unsigned int>> bound(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        Point<dim> corner;
        for (unsigned int d = 0; d < dim; ++d)
          corner[d] =
            std::abs(points[i][d] - low[d]) > std::abs(points[i][d] - high[d]) ?
              low[d] :
              high[d];
        bound[i] = {points[i].distance_square(corner), i};
      }
    std::sort(bound.begin(), bound.end(), std::greater<>());
    double largest = 0.;
    for (const auto &[reach, i] : bound)
      {
        if (reach <= largest)
          break; // the rest reach no farther
        for (unsigned int j = 0; j < points.size(); ++j)
          largest = std::max(largest, points[i].distance_square(points[j]));
      }
    return std::sqrt(largest);
  }



  template void
  create_mesh(const MeshParameters &, Triangulation<2> &, JointFaces<2> *);
  template void
  create_mesh(const MeshParameters &, Triangulation<3> &, JointFaces<3> *);
  template std::vector<types::material_id>
  block_ids(const Triangulation<2> &);
  template std::vector<types::material_id>
  block_ids(const Triangulation<3> &);
  template void
  extract_block(const Triangulation<2> &,
                types::material_id,
                Triangulation<2> &);
  template void
  extract_block(const Triangulation<3> &,
                types::material_id,
                Triangulation<3> &);
  template std::set<types::boundary_id>
  boundary_ids_of(const Triangulation<2> &);
  template std::set<types::boundary_id>
  boundary_ids_of(const Triangulation<3> &);
  template double
  diameter(const Triangulation<2> &);
  template double
  diameter(const Triangulation<3> &);
} // namespace mbfem

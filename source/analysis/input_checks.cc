#include <mbfem/analysis/input_checks.h>
#include <mbfem/mesh/mesh.h>

#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <regex>
#include <set>
#include <sstream>

namespace mbfem
{
  namespace
  {
    template <int dim>
    std::string
    point_text(const Point<dim> &p)
    {
      std::ostringstream out;
      out << "(";
      for (unsigned int d = 0; d < dim; ++d)
        out << (d > 0 ? ", " : "") << p[d];
      out << ")";
      return out.str();
    }

    std::string
    number_text(const double x)
    {
      std::ostringstream out;
      out << x;
      return out.str();
    }

    /** The function at every point and time, or an error naming @p where. */
    template <int dim>
    void
    check_finite(Function<dim>                 &function,
                 const std::vector<Point<dim>> &points,
                 const std::vector<double>     &times,
                 const std::string             &where)
    {
      Vector<double> value(function.n_components);
      for (const double t : times)
        {
          function.set_time(t);
          for (const auto &point : points)
            {
              function.vector_value(point, value);
              for (unsigned int c = 0; c < value.size(); ++c)
                AssertThrow(std::isfinite(value[c]),
                            ExcMessage("The function in subsection '" + where +
                                       "' is not finite: component " +
                                       std::to_string(c + 1) + " is " +
                                       number_text(value[c]) + " at " +
                                       point_text(point) +
                                       ", t = " + number_text(t) + "."));
            }
        }
      function.set_time(0.);
    }

    /**
     * Vertices of the boundary faces of @p tria whose id is in @p ids
     * (every vertex and cell centre if @p ids is null).
     */
    template <int dim>
    void
    collect_points(const Triangulation<dim>           &tria,
                   const std::set<types::boundary_id> *ids,
                   std::vector<Point<dim>>            &points)
    {
      for (const auto &cell : tria.active_cell_iterators())
        {
          if (ids == nullptr)
            {
              points.push_back(cell->center());
              for (const unsigned int v : cell->vertex_indices())
                points.push_back(cell->vertex(v));
              continue;
            }
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && ids->count(face->boundary_id()) == 1)
              for (const unsigned int v : face->vertex_indices())
                points.push_back(face->vertex(v));
        }
    }
  } // namespace



  template <int dim>
  void
  check_functions_are_finite(
    Parameters<dim>                                &parameters,
    const std::vector<std::unique_ptr<Block<dim>>> &blocks)
  {
    const LoadHistory &history = parameters.load_history;
    // t = 0 and the increments' times, at most max_times of them evenly
    // spread (the displacement of every increment is checked after its
    // solve as well).
    constexpr unsigned int max_times = 100;
    const unsigned int  stride = std::max(1u, history.n_increments / max_times);
    std::vector<double> times  = {0.};
    for (unsigned int k = stride; k <= history.n_increments; k += stride)
      times.push_back(history.time(k));
    times.push_back(history.time(history.n_increments));

    auto                        &bc = parameters.boundary_conditions;
    std::set<types::boundary_id> supported, loaded;
    for (const auto &[id, mask] : bc.dirichlet)
      supported.insert(id);
    loaded.insert(bc.traction_boundaries.begin(), bc.traction_boundaries.end());
    for (const auto &[id, component] : bc.rigid_platens)
      loaded.insert(id);

    std::vector<Point<dim>> on_supports, on_loads, everywhere;
    for (const auto &block : blocks)
      {
        collect_points(block->get_triangulation(), &supported, on_supports);
        collect_points(block->get_triangulation(), &loaded, on_loads);
        collect_points<dim>(block->get_triangulation(), nullptr, everywhere);
      }
    const std::string bcs = "Boundary conditions/";
    check_finite(*bc.prescribed_displacement,
                 on_supports,
                 times,
                 bcs + "Prescribed displacement");
    check_finite(*bc.traction, on_loads, times, bcs + "Traction");
    check_finite(*bc.body_force, everywhere, times, bcs + "Body force");
    bc.set_time(0.);

    ExactSolution<dim> &exact = parameters.exact_solution;
    if (exact.enabled)
      {
        check_finite(*exact.displacement,
                     everywhere,
                     times,
                     "Exact solution/Displacement");
        check_finite(*exact.stress, everywhere, times, "Exact solution/Stress");
      }
  }



  namespace
  {
    template <typename Container>
    std::string
    list_text(const Container &ids)
    {
      std::string text;
      for (const auto id : ids)
        text += (text.empty() ? "" : ", ") + std::to_string(id);
      return text;
    }

    /** Boundary ids of the blocks @p mesh will be split into. */
    template <int dim>
    std::set<types::boundary_id>
    block_boundary_ids(const Triangulation<dim>              &mesh,
                       const std::vector<types::material_id> &excavated)
    {
      const auto is_excavated = [&](const types::material_id id) {
        return std::find(excavated.begin(), excavated.end(), id) !=
               excavated.end();
      };
      std::set<types::boundary_id> ids;
      for (const auto &cell : mesh.active_cell_iterators())
        {
          if (is_excavated(cell->material_id()))
            continue;
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              ids.insert(cell->face(f)->boundary_id());
            else if (cell->neighbor(f)->material_id() != cell->material_id())
              ids.insert(
                interface_boundary_id(cell->neighbor(f)->material_id()));
        }
      return ids;
    }

    template <int dim>
    void
    check_interfaces(
      const ContactParameters            &contact,
      const Triangulation<dim>           &mesh,
      const std::set<types::material_id> &blocks,
      const std::function<void(types::boundary_id, const std::string &)> &check)
    {
      std::set<std::pair<unsigned int, unsigned int>> touching;
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (!cell->face(f)->at_boundary())
            touching.emplace(cell->material_id(),
                             cell->neighbor(f)->material_id());

      for (const auto &declaration : contact.interfaces)
        {
          const std::string where =
            "Contact/Interfaces, '" + declaration.description + "'";
          if (!declaration.by_blocks)
            {
              check(declaration.side_a, where);
              check(declaration.side_b, where);
              continue;
            }
          for (const unsigned int side :
               {declaration.side_a, declaration.side_b})
            AssertThrow(blocks.count(side) == 1,
                        ExcMessage(where + ": " + std::to_string(side) +
                                   " is not a block of the mesh, whose "
                                   "blocks are: " +
                                   list_text(blocks) + "."));
          AssertThrow(touching.count(
                        {declaration.side_a, declaration.side_b}) == 1,
                      ExcMessage(where + ": blocks " +
                                 std::to_string(declaration.side_a) + " and " +
                                 std::to_string(declaration.side_b) +
                                 " share no face in the mesh."));
        }
    }
  } // namespace



  template <int dim>
  void
  check_ids_against_mesh(const Parameters<dim>    &parameters,
                         const Triangulation<dim> &mesh)
  {
    const auto &excavated = parameters.excavation.excavated_ids;
    const auto  ids       = block_ids(mesh);
    for (const auto id : excavated)
      AssertThrow(std::find(ids.begin(), ids.end(), id) != ids.end(),
                  ExcMessage("Excavation/Excavated material ids lists " +
                             std::to_string(id) +
                             ", which is not a material id of the mesh."));
    std::set<types::material_id> blocks;
    for (const auto id : ids)
      if (std::find(excavated.begin(), excavated.end(), id) == excavated.end())
        blocks.insert(id);

    const auto &materials = parameters.block_materials;
    for (const auto &[id, material] : materials)
      AssertThrow(blocks.count(id) == 1,
                  ExcMessage("Material/Block materials lists block " +
                             std::to_string(id) +
                             ", which is not a material id of the mesh."));
    for (const auto id : blocks)
      AssertThrow(materials.empty() || materials.count(id) == 1,
                  ExcMessage("Block " + std::to_string(id) + " (material id " +
                             std::to_string(id) +
                             " in the mesh) has no material: list it "
                             "in 'Material/Block materials'."));

    for (const auto &[entry, ids] :
         {std::make_pair(std::string("Finite element/Block degrees"),
                         &parameters.discretisation.block_degrees),
          std::make_pair(std::string("Mesh/Block refinements"),
                         &parameters.mesh.block_refinements)})
      for (const auto &[id, value] : *ids)
        AssertThrow(blocks.count(id) == 1,
                    ExcMessage(entry + " lists block " + std::to_string(id) +
                               ", which is not a block of the mesh, whose "
                               "blocks are: " +
                               list_text(blocks) + "."));

    const std::set<types::boundary_id> present =
      block_boundary_ids(mesh, excavated);
    const auto check = [&](const types::boundary_id id,
                           const std::string       &entry) {
      check_boundary_id(id, entry, present);
    };
    parameters.boundary_conditions.check_boundary_ids(present);
    for (const auto id : parameters.in_situ_stress.stress_boundaries)
      check(id, "In-situ stress/Stress boundary ids");
    // Ids from 10000 on are the faces of the excavated material ids.
    for (const auto id : parameters.excavation.released_boundaries)
      if (id < interface_boundary_id(0))
        check(id, "Excavation/Released boundary ids");
    check_interfaces(parameters.contact, mesh, blocks, check);
  }



  template <int dim>
  void
  check_point_supports(const BoundaryConditions<dim>                  &bc,
                       const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                       std::ostream                                   &out)
  {
    if (bc.point_supports.empty())
      return;
    std::vector<std::vector<Point<dim>>> points(blocks.size());
    std::vector<double>                  tolerance(blocks.size());
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        DoFHandler<dim> dof_handler(blocks[b]->get_triangulation());
        dof_handler.distribute_dofs(blocks[b]->get_fe());
        points[b].resize(dof_handler.n_dofs());
        DoFTools::map_dofs_to_support_points(blocks[b]->get_mapping(),
                                             dof_handler,
                                             points[b]);
        tolerance[b] = 1e-6 * diameter(blocks[b]->get_triangulation());
      }

    for (const auto &[point, mask] : bc.point_supports)
      {
        std::vector<std::string> held;
        double                   nearest = std::numeric_limits<double>::max();
        Point<dim>               nearest_point;
        std::string              nearest_block;
        for (unsigned int b = 0; b < blocks.size(); ++b)
          {
            bool holds = false;
            for (const auto &p : points[b])
              {
                const double distance = p.distance(point);
                holds                 = holds || distance < tolerance[b];
                if (distance < nearest)
                  {
                    nearest       = distance;
                    nearest_point = p;
                    nearest_block = blocks[b]->name();
                  }
              }
            if (holds)
              held.push_back(blocks[b]->name());
          }
        AssertThrow(!held.empty(),
                    ExcMessage("Boundary conditions/Point supports: no "
                               "support point of the mesh lies at " +
                               point_text(point) + "; the nearest is " +
                               point_text(nearest_point) + " of " +
                               nearest_block + ", at a distance of " +
                               number_text(nearest) + "."));
        if (held.size() > 1)
          {
            out << "  point support at " << point_text(point) << " holds "
                << held[0];
            for (unsigned int i = 1; i < held.size(); ++i)
              out << (i + 1 == held.size() ? " and " : ", ") << held[i];
            out << " (they meet there)\n";
          }
      }
  }



  template void
  check_functions_are_finite(Parameters<2> &,
                             const std::vector<std::unique_ptr<Block<2>>> &);
  template void
  check_functions_are_finite(Parameters<3> &,
                             const std::vector<std::unique_ptr<Block<3>>> &);
  template void
  check_ids_against_mesh(const Parameters<2> &, const Triangulation<2> &);
  template void
  check_ids_against_mesh(const Parameters<3> &, const Triangulation<3> &);
  template void
  check_point_supports(const BoundaryConditions<2> &,
                       const std::vector<std::unique_ptr<Block<2>>> &,
                       std::ostream &);
  template void
  check_point_supports(const BoundaryConditions<3> &,
                       const std::vector<std::unique_ptr<Block<3>>> &,
                       std::ostream &);
} // namespace mbfem

#include <mbfem/mesh/mesh_checks.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <sstream>
#include <vector>

namespace mbfem
{
  namespace
  {
    /** Gauss points and Gauss-Lobatto (support) points in one rule. */
    template <int dim>
    Quadrature<dim>
    check_points(const unsigned int degree)
    {
      const QGauss<dim>        gauss(degree + 1);
      const QGaussLobatto<dim> lobatto(std::max(degree + 1, 2u));
      std::vector<Point<dim>>  points = gauss.get_points();
      points.insert(points.end(),
                    lobatto.get_points().begin(),
                    lobatto.get_points().end());
      return Quadrature<dim>(points, std::vector<double>(points.size(), 1.));
    }
  } // namespace



  template <int dim>
  void
  check_cell_geometry(const Triangulation<dim> &triangulation,
                      const Mapping<dim>       &mapping,
                      const unsigned int        degree,
                      const std::string        &block_name)
  {
    const FE_Nothing<dim> fe;
    FEValues<dim>         values(mapping,
                         fe,
                         check_points<dim>(degree),
                         update_jacobians);
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        values.reinit(cell);
        // Not through JxW, which a Debug build asserts positive. A
        // determinant that is zero to rounding is a collapsed corner.
        const double size  = std::pow(cell->diameter(), dim);
        bool         valid = std::isfinite(size) && size > 0.;
        for (const unsigned int q : values.quadrature_point_indices())
          valid = valid && values.jacobian(q).determinant() > 1e-12 * size;
        if (valid)
          continue;
        std::ostringstream vertices;
        for (const unsigned int v : cell->vertex_indices())
          {
            vertices << (v > 0 ? ", (" : "(");
            for (unsigned int d = 0; d < dim; ++d)
              vertices << (d > 0 ? ", " : "") << cell->vertex(v)[d];
            vertices << ")";
          }
        AssertThrow(false,
                    ExcMessage("Cell " +
                               std::to_string(cell->active_cell_index()) +
                               " of " + block_name +
                               " is inverted, twisted (a bow-tie) or "
                               "collapsed: the Jacobian determinant of its "
                               "mapping is not positive everywhere in it. "
                               "Its vertices, in deal.II's order: " +
                               vertices.str() +
                               ". Correct the node order or positions of "
                               "that element in the mesh."));
      }
  }



  template void
  check_cell_geometry(const Triangulation<2> &,
                      const Mapping<2> &,
                      const unsigned int,
                      const std::string &);
  template void
  check_cell_geometry(const Triangulation<3> &,
                      const Mapping<3> &,
                      const unsigned int,
                      const std::string &);
} // namespace mbfem

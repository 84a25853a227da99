// The plastic stress at VTU output points is interpolated from a cell's
// Gauss points (StressPostprocessor::interpolated_plastic_stress). What
// must hold: the interpolation reproduces every polynomial of degree p in
// each unit coordinate exactly, at the Gauss points and anywhere else in
// the cell, in 2D and 3D, for p = 1, 2, 3, also on a cell that MappingQ(p)
// bends (a quarter of a ring). An ordering mistake between the Gauss points
// and the Lagrange nodes, or a wrong real-to-unit map, breaks it.

#include <mbfem/material/material.h>
#include <mbfem/output/output.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace dealii;

// A polynomial of degree p in each unit coordinate, one per component.
template <int dim>
double
field(const Point<dim> &x, const unsigned int p, const unsigned int component)
{
  double value = 1. + component;
  for (unsigned int d = 0; d < dim; ++d)
    value *= 0.5 + std::pow(x[d], p) + (component + d + 1) * 0.3 * x[d];
  return value;
}

template <int dim>
void
check(const unsigned int p, const bool curved)
{
  Triangulation<dim> triangulation;
  if (curved)
    GridGenerator::hyper_shell(triangulation, Point<dim>(), 1., 2., 0);
  else
    GridGenerator::hyper_rectangle(triangulation,
                                   Point<dim>(),
                                   (dim == 2 ? Point<dim>(2., 1.) :
                                               Point<dim>(2., 1., 3.)));
  const FESystem<dim> fe(FE_Q<dim>(p), dim);
  DoFHandler<dim>     dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);
  const MappingQ<dim> mapping(p);

  // D eps_p at each cell's Gauss points: the field of the unit coordinates.
  const QGauss<dim>                  gauss(p + 1);
  std::vector<SymmetricTensor<2, 3>> values;
  for (const auto &cell : dof_handler.active_cell_iterators())
    for (const Point<dim> &x : gauss.get_points())
      {
        (void)cell;
        SymmetricTensor<2, 3> s;
        for (unsigned int c = 0; c < 6; ++c)
          s[SymmetricTensor<2, 3>::unrolled_to_component_indices(c)] =
            field(x, p, c);
        values.push_back(s);
      }
  const mbfem::Material                 material(20e9, 0.25);
  const mbfem::StressPostprocessor<dim> stress(
    material, nullptr, values, &mapping, p);
  std::mt19937                           random(3);
  std::uniform_real_distribution<double> uniform(0., 1.);
  double                                 largest = 0.;
  unsigned int                           n       = 0;
  for (const auto &cell : dof_handler.active_cell_iterators())
    {
      std::vector<Point<dim>> unit_points = gauss.get_points();
      for (unsigned int k = 0; k < 20; ++k)
        {
          Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = uniform(random);
          unit_points.push_back(x);
        }
      unit_points.push_back(Point<dim>()); // a vertex
      for (const Point<dim> &unit : unit_points)
        {
          const Point<dim> real =
            mapping.transform_unit_to_real_cell(cell, unit);
          const SymmetricTensor<2, 3> s =
            stress.interpolated_plastic_stress(cell, real);
          for (unsigned int c = 0; c < 6; ++c)
            largest = std::max(
              largest,
              std::abs(
                s[SymmetricTensor<2, 3>::unrolled_to_component_indices(c)] -
                field(unit, p, c)) /
                std::abs(field(unit, p, c)));
          ++n;
        }
    }
  std::printf("%dD, p = %u, %s cells: %u points, exact to 1e-9: %s\n",
              dim,
              p,
              curved ? "curved" : "straight",
              n,
              largest < 1e-9 ? "yes" : "NO");
}

int
main()
{
  for (unsigned int p = 1; p <= 3; ++p)
    for (const bool curved : {false, true})
      {
        check<2>(p, curved);
        check<3>(p, curved);
      }
}

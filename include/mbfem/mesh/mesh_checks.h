#ifndef mbfem_mesh_mesh_checks_h
#define mbfem_mesh_mesh_checks_h

#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <string>

namespace mbfem
{
  using namespace dealii;

  /**
   * Every cell of @p triangulation, mapped by @p mapping, has a positive
   * Jacobian determinant at the Gauss points of a degree @p degree element
   * and at the element's (Gauss-Lobatto) support points. An inverted,
   * bow-tie or collapsed cell gives a finite but wrong stiffness, or
   * non-finite stresses where the determinant vanishes, and the solve does
   * not notice. The error names the cell, @p block_name and the vertices.
   * This is the one check of cell geometry; every block goes through it.
   */
  template <int dim>
  void
  check_cell_geometry(const Triangulation<dim> &triangulation,
                      const Mapping<dim>       &mapping,
                      const unsigned int        degree,
                      const std::string        &block_name);
} // namespace mbfem

#endif

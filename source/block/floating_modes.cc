#include <mbfem/block/floating_modes.h>
#include <mbfem/mesh/mesh.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cstdio>

namespace mbfem
{
  template <int dim>
  void
  FloatingModes<dim>::compute(
    const DoFHandler<dim>           &dof_handler,
    const Mapping<dim>              &mapping,
    const AffineConstraints<double> &physical_constraints,
    const std::string               &block_name)
  {
    const std::vector<Vector<double>> all =
      rigid_body_modes(dof_handler, mapping, &mode_centre, &mode_size);
    free_coefficients = free_combinations(all, physical_constraints);
    free_modes.clear();
    for (const auto &coefficients : free_coefficients)
      {
        Vector<double> mode(dof_handler.n_dofs());
        for (unsigned int a = 0; a < all.size(); ++a)
          mode.add(coefficients(a), all[a]);
        free_modes.push_back(mode);
      }
    choose_pins(physical_constraints, block_name);
  }



  template <int dim>
  const std::vector<Vector<double>> &
  FloatingModes<dim>::coefficients() const
  {
    return free_coefficients;
  }



  template <int dim>
  const std::vector<Vector<double>> &
  FloatingModes<dim>::modes() const
  {
    return free_modes;
  }



  template <int dim>
  const std::vector<types::global_dof_index> &
  FloatingModes<dim>::pins() const
  {
    return pinned;
  }



  template <int dim>
  const Point<dim> &
  FloatingModes<dim>::centre() const
  {
    return mode_centre;
  }



  template <int dim>
  double
  FloatingModes<dim>::size() const
  {
    return mode_size;
  }



  template <int dim>
  void
  FloatingModes<dim>::choose_pins(
    const AffineConstraints<double> &physical_constraints,
    const std::string               &block_name)
  {
    // Greedy column pivoting on the free modes: pick the DoF where the
    // (remaining) modes move most, then remove that direction. q picks give
    // a nonsingular q x q system, i.e. a statically determinate support.
    pinned.clear();
    const unsigned int          q        = free_modes.size();
    const unsigned int          n_dofs   = (q > 0 ? free_modes[0].size() : 0);
    std::vector<Vector<double>> residual = free_modes;
    for (unsigned int pick = 0; pick < q; ++pick)
      {
        types::global_dof_index best       = numbers::invalid_dof_index;
        double                  best_norm2 = 0.;
        for (types::global_dof_index i = 0; i < n_dofs; ++i)
          if (!physical_constraints.is_constrained(i))
            {
              double norm2 = 0.;
              for (const auto &r : residual)
                norm2 += r(i) * r(i);
              if (norm2 > best_norm2 * (1. + 1e-12))
                {
                  best_norm2 = norm2;
                  best       = i;
                }
            }
        AssertThrow(best != numbers::invalid_dof_index && best_norm2 > 1e-20,
                    ExcMessage(block_name + ": cannot pin its free modes."));
        pinned.push_back(best);

        // residual <- residual (I - v v^T), v = residual row at best
        std::vector<double> v(q);
        for (unsigned int a = 0; a < q; ++a)
          v[a] = residual[a](best) / std::sqrt(best_norm2);
        Vector<double> combination(n_dofs);
        for (unsigned int a = 0; a < q; ++a)
          combination.add(v[a], residual[a]);
        for (unsigned int a = 0; a < q; ++a)
          residual[a].add(-v[a], combination);
      }
  }


  template <int dim>
  std::vector<Vector<double>>
  FloatingModes<dim>::rigid_body_modes(const DoFHandler<dim> &dof_handler,
                                       const Mapping<dim>    &mapping,
                                       Point<dim>            *centre_out,
                                       double                *size_out)
  {
    const auto             &fe = dof_handler.get_fe();
    std::vector<Point<dim>> points(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    std::vector<unsigned int>            component(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < dof_indices.size(); ++i)
          component[dof_indices[i]] = fe.system_to_component_index(i).first;
      }

    // Rotations about the centre, lengths in units of the block's size:
    // this keeps the modes of unit order whatever the units of the model.
    Point<dim> centre;
    for (const auto &p : points)
      centre += p / static_cast<double>(points.size());
    const double size = diameter(dof_handler.get_triangulation());
    if (centre_out != nullptr)
      *centre_out = centre;
    if (size_out != nullptr)
      *size_out = size;

    const unsigned int          n_modes = (dim == 2 ? 3 : 6);
    std::vector<Vector<double>> modes(n_modes, Vector<double>(points.size()));
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        const Tensor<1, dim> x = (points[i] - centre) / size;
        const unsigned int   c = component[i];
        modes[c](i)            = 1.;
        if (dim == 2)
          modes[2](i) = (c == 0 ? -x[1] : x[0]); // rotation about z
        else
          for (unsigned int axis = 0; axis < 3; ++axis)
            {
              // (e_axis x x)_c: rotation about the coordinate axis
              Tensor<1, dim> e;
              e[axis]                   = 1.;
              const Tensor<1, dim> curl = cross_product_3d(e, x);
              modes[dim + axis](i)      = curl[c];
            }
      }
    return modes;
  }


  template <int dim>
  std::vector<Vector<double>>
  FloatingModes<dim>::free_combinations(
    const std::vector<Vector<double>> &modes,
    const AffineConstraints<double>   &physical_constraints)
  {
    const unsigned int n_modes = modes.size();

    // G = A^T A, with A the constraint equations of the supports applied to
    // the modes (a prescribed DoF: m_i = 0; a platen node: m_i - m_master =
    // 0): the free modes are G's null space.
    LAPACKFullMatrix<double> gram(n_modes, n_modes);
    std::vector<double>      equation(n_modes);
    for (const auto &line : physical_constraints.get_lines())
      {
        for (unsigned int a = 0; a < n_modes; ++a)
          {
            equation[a] = modes[a](line.index);
            for (const auto &[j, weight] : line.entries)
              equation[a] -= weight * modes[a](j);
          }
        for (unsigned int a = 0; a < n_modes; ++a)
          for (unsigned int b = 0; b < n_modes; ++b)
            gram(a, b) += equation[a] * equation[b];
      }

    // Mode values are of unit order, so a held mode has an eigenvalue of
    // order one or more (one prescribed DoF at distance 1e-4 of the block
    // size from the centre still gives 1e-8); a free one has round-off.
    Vector<double>     eigenvalues;
    FullMatrix<double> eigenvectors;
    gram.compute_eigenvalues_symmetric(
      -1., 1e-10, 1e-14, eigenvalues, eigenvectors);

    // The null space has no preferred basis (LAPACK may return any
    // rotation of it): row_echelon() makes it unique and readable.
    const unsigned int n_free = eigenvalues.size();
    FullMatrix<double> basis(n_free, n_modes);
    for (unsigned int k = 0; k < n_free; ++k)
      for (unsigned int a = 0; a < n_modes; ++a)
        basis(k, a) = eigenvectors(a, k);
    return row_echelon(basis);
  }



  template <int dim>
  std::vector<Vector<double>>
  FloatingModes<dim>::row_echelon(FullMatrix<double> basis)
  {
    const unsigned int n_free = basis.m(), n_modes = basis.n();
    unsigned int       row = 0;
    for (unsigned int column = 0; column < n_modes && row < n_free; ++column)
      {
        unsigned int pivot = row;
        for (unsigned int k = row + 1; k < n_free; ++k)
          if (std::abs(basis(k, column)) > std::abs(basis(pivot, column)))
            pivot = k;
        if (std::abs(basis(pivot, column)) < 1e-8)
          continue;
        basis.swap_row(row, pivot);
        const double scale = basis(row, column);
        for (unsigned int a = 0; a < n_modes; ++a)
          basis(row, a) /= scale;
        for (unsigned int k = 0; k < n_free; ++k)
          if (k != row)
            {
              const double factor = basis(k, column);
              for (unsigned int a = 0; a < n_modes; ++a)
                basis(k, a) -= factor * basis(row, a);
            }
        ++row;
      }

    std::vector<Vector<double>> free_modes(n_free, Vector<double>(n_modes));
    for (unsigned int k = 0; k < n_free; ++k)
      for (unsigned int a = 0; a < n_modes; ++a)
        free_modes[k](a) = (std::abs(basis(k, a)) < 1e-12 ? 0. : basis(k, a));
    return free_modes;
  }



  namespace
  {
    /**
     * The coefficients, in the rigid-body modes of a block (centre
     * @p block_centre, size @p block_size), of each rigid-body mode about
     * @p centre scaled by @p size (one column each): a rotation about
     * another point is the same rotation about the block's centre plus a
     * translation.
     */
    template <int dim>
    FullMatrix<double>
    modes_in_block_frame(const Point<dim> &centre,
                         const double      size,
                         const Point<dim> &block_centre,
                         const double      block_size)
    {
      const unsigned int   n = (dim == 2 ? 3 : 6);
      FullMatrix<double>   m(n, n);
      const Tensor<1, dim> r = (block_centre - centre) / size;
      for (unsigned int d = 0; d < dim; ++d)
        m(d, d) = 1.;
      if (dim == 2)
        {
          m(0, 2) = -r[1];
          m(1, 2) = r[0];
          m(2, 2) = block_size / size;
        }
      else
        for (unsigned int axis = 0; axis < 3; ++axis)
          {
            Tensor<1, dim> e;
            e[axis]                   = 1.;
            const Tensor<1, dim> curl = cross_product_3d(e, r);
            for (unsigned int c = 0; c < dim; ++c)
              m(c, dim + axis) = curl[c];
            m(dim + axis, dim + axis) = block_size / size;
          }
      return m;
    }



    /** An orthonormal basis of the span of @p vectors (Gram-Schmidt). */
    std::vector<Vector<double>>
    orthonormal(const std::vector<Vector<double>> &vectors)
    {
      std::vector<Vector<double>> basis;
      for (Vector<double> v : vectors)
        {
          for (const auto &q : basis)
            v.add(-(q * v), q);
          const double norm = v.l2_norm();
          if (norm > 1e-10)
            {
              v /= norm;
              basis.push_back(v);
            }
        }
      return basis;
    }
  } // namespace



  template <int dim>
  std::vector<Vector<double>>
  FloatingModes<dim>::free_group_motions(
    const std::vector<const FloatingModes<dim> *> &group,
    Point<dim>                                    &centre,
    double                                        &size)
  {
    centre = Point<dim>();
    for (const auto *block : group)
      centre += block->mode_centre / static_cast<double>(group.size());
    size = 0.;
    for (const auto *block : group)
      size = std::max(
        {size, block->mode_size, (block->mode_centre - centre).norm()});

    // G = sum over blocks of (P_b M_b)^T (P_b M_b): M_b the group's modes
    // in the block's, P_b the projector off the block's free modes. A
    // motion is free for the group where every P_b M_b maps it to zero.
    const unsigned int       n = (dim == 2 ? 3 : 6);
    LAPACKFullMatrix<double> gram(n, n);
    for (const auto *block : group)
      {
        FullMatrix<double> held = modes_in_block_frame(centre,
                                                       size,
                                                       block->mode_centre,
                                                       block->mode_size);
        for (const auto &q : orthonormal(block->free_coefficients))
          for (unsigned int j = 0; j < n; ++j)
            {
              double along = 0.;
              for (unsigned int i = 0; i < n; ++i)
                along += q(i) * held(i, j);
              for (unsigned int i = 0; i < n; ++i)
                held(i, j) -= along * q(i);
            }
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            for (unsigned int i = 0; i < n; ++i)
              gram(a, b) += held(i, a) * held(i, b);
      }

    // Of unit order as in free_combinations(): a held motion has an
    // eigenvalue of order (block size / group size)^2 or more.
    Vector<double>     eigenvalues;
    FullMatrix<double> eigenvectors;
    gram.compute_eigenvalues_symmetric(
      -1., 1e-10, 1e-14, eigenvalues, eigenvectors);
    FullMatrix<double> basis(eigenvalues.size(), n);
    for (unsigned int k = 0; k < eigenvalues.size(); ++k)
      for (unsigned int a = 0; a < n; ++a)
        basis(k, a) = eigenvectors(a, k);
    return row_echelon(basis);
  }



  template <int dim>
  std::string
  FloatingModes<dim>::describe(const Vector<double> &coefficients)
  {
    static const char *names_2d[] = {"translation x",
                                     "translation y",
                                     "rotation about z"};
    static const char *names_3d[] = {"translation x",
                                     "translation y",
                                     "translation z",
                                     "rotation about x",
                                     "rotation about y",
                                     "rotation about z"};
    std::string        description;
    for (unsigned int a = 0; a < coefficients.size(); ++a)
      if (std::abs(coefficients(a)) > 1e-3)
        {
          description += (description.empty() ? "" : " + ");
          if (std::abs(std::abs(coefficients(a)) - 1.) > 1e-3)
            {
              char factor[32];
              std::snprintf(factor, sizeof(factor), "%.2f ", coefficients(a));
              description += factor;
            }
          description += (dim == 2 ? names_2d[a] : names_3d[a]);
        }
    return description;
  }


  template class FloatingModes<2>;
  template class FloatingModes<3>;
} // namespace mbfem

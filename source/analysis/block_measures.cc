#include <mbfem/analysis/block_measures.h>
#include <mbfem/material/material.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <cmath>

namespace mbfem
{
  namespace
  {
    /** Adds sum_i (a_i - b_i)^2 JxW to @p error2 and b_i^2 JxW to @p norm2. */
    template <typename A, typename B>
    void
    add_squares(const A           &a,
                const B           &b,
                const unsigned int n,
                const double       JxW,
                double            &error2,
                double            &norm2)
    {
      for (unsigned int i = 0; i < n; ++i)
        {
          error2 += (a[i] - b[i]) * (a[i] - b[i]) * JxW;
          norm2 += b[i] * b[i] * JxW;
        }
    }
  } // namespace



  namespace
  {
    /**
     * ErrorNorms from the squared L2 errors and exact norms: relative to
     * the norm, or absolute where the exact field is zero.
     */
    ErrorNorms
    error_norms(const double u_error2,
                const double u_norm2,
                const double s_error2,
                const double s_norm2)
    {
      ErrorNorms errors;
      errors.displacement      = std::sqrt(u_error2);
      errors.stress            = std::sqrt(s_error2);
      errors.displacement_norm = std::sqrt(u_norm2);
      errors.stress_norm       = std::sqrt(s_norm2);
      errors.displacement_relative =
        u_norm2 > 0. ? std::sqrt(u_error2 / u_norm2) : errors.displacement;
      errors.stress_relative =
        s_norm2 > 0. ? std::sqrt(s_error2 / s_norm2) : errors.stress;
      return errors;
    }
  } // namespace



  template <int dim>
  ErrorNorms
  compute_errors(const Block<dim>    &block,
                 const Function<dim> &exact_displacement,
                 const Function<dim> &exact_stress)
  {
    AssertDimension(exact_displacement.n_components, dim);
    AssertDimension(exact_stress.n_components, dim * dim);
    const Quadrature<dim> quadrature =
      (block.is_plastic() ? block.state_quadrature() :
                            QGauss<dim>(block.get_fe().degree + 3));
    FEValues<dim>                        fe_values(block.get_mapping(),
                            block.get_fe(),
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<Tensor<1, dim>>          u(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> eps(quadrature.size());
    Vector<double>                       u_exact(dim), s_exact(dim * dim);

    double u_error2 = 0., u_norm2 = 0., s_error2 = 0., s_norm2 = 0.;
    for (const auto &cell : block.get_dof_handler().active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_values(block.get_solution(), u);
        fe_values[displacement].get_function_symmetric_gradients(
          block.get_solution(), eps);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const Point<dim> &x = fe_values.quadrature_point(q);
            exact_displacement.vector_value(x, u_exact);
            exact_stress.vector_value(x, s_exact);
            const SymmetricTensor<2, 3> s3 =
              block.stress(eps[q], x, cell->active_cell_index(), q);
            Vector<double> sigma(dim * dim);
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                sigma[i * dim + j] = s3[i][j];
            add_squares(
              u[q], u_exact, dim, fe_values.JxW(q), u_error2, u_norm2);
            add_squares(
              sigma, s_exact, dim * dim, fe_values.JxW(q), s_error2, s_norm2);
          }
      }

    return error_norms(u_error2, u_norm2, s_error2, s_norm2);
  }



  ErrorNorms
  combine_errors(const std::vector<ErrorNorms> &blocks)
  {
    double u_error2 = 0., u_norm2 = 0., s_error2 = 0., s_norm2 = 0.;
    for (const ErrorNorms &e : blocks)
      {
        u_error2 += e.displacement * e.displacement;
        s_error2 += e.stress * e.stress;
        u_norm2 += e.displacement_norm * e.displacement_norm;
        s_norm2 += e.stress_norm * e.stress_norm;
      }
    return error_norms(u_error2, u_norm2, s_error2, s_norm2);
  }



  template <int dim>
  double
  max_displacement(const Block<dim> &block)
  {
    const auto                          &fe   = block.get_fe();
    double                               max2 = 0.;
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : block.get_dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(dof_indices);
        for (unsigned int v = 0; v < fe.base_element(0).n_dofs_per_cell(); ++v)
          {
            double norm2 = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              norm2 += Utilities::fixed_power<2>(block.get_solution()(
                dof_indices[fe.component_to_system_index(d, v)]));
            max2 = std::max(max2, norm2);
          }
      }
    return std::sqrt(max2);
  }



  template <int dim>
  double
  max_von_mises_stress(const Block<dim> &block)
  {
    FEValues<dim>                        fe_values(block.get_mapping(),
                            block.get_fe(),
                            block.state_quadrature(),
                            update_gradients | update_quadrature_points);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> eps(fe_values.n_quadrature_points);
    double                               result = 0.;
    for (const auto &cell : block.get_dof_handler().active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_symmetric_gradients(
          block.get_solution(), eps);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          result = std::max(result,
                            von_mises_stress(
                              block.stress(eps[q],
                                           fe_values.quadrature_point(q),
                                           cell->active_cell_index(),
                                           q)));
      }
    return result;
  }



  template ErrorNorms
  compute_errors(const Block<2> &, const Function<2> &, const Function<2> &);
  template ErrorNorms
  compute_errors(const Block<3> &, const Function<3> &, const Function<3> &);
  template <int dim>
  double
  max_slip(const ContactSolver<dim> &solver)
  {
    double largest = 0.;
    for (unsigned int k = 0; k < solver.pairs().size(); ++k)
      largest = std::max(largest, solver.slip(k).norm());
    return largest;
  }



  template double
  max_displacement(const Block<2> &);
  template double
  max_displacement(const Block<3> &);
  template double
  max_von_mises_stress(const Block<2> &);
  template double
  max_von_mises_stress(const Block<3> &);
  template double
  max_slip(const ContactSolver<2> &);
  template double
  max_slip(const ContactSolver<3> &);
} // namespace mbfem

#include <mbfem/block/block.h>
#include <mbfem/block/plastic_state.h>

#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>

namespace mbfem
{
  namespace
  {
    /** eps : eps */
    template <int n>
    double
    squared(const SymmetricTensor<2, n> &t)
    {
      return t * t;
    }
  } // namespace



  PlasticUpdate &
  PlasticUpdate::operator+=(const PlasticUpdate &other)
  {
    change2 += other.change2;
    norm2 += other.norm2;
    aitken_numerator += other.aitken_numerator;
    aitken_denominator += other.aitken_denominator;
    n_yielded += other.n_yielded;
    n_points += other.n_points;
    yielded_measure += other.yielded_measure;
    max_equivalent = std::max(max_equivalent, other.max_equivalent);
    return *this;
  }



  template <int dim>
  void
  PlasticState<dim>::initialize(const PlasticityParameters &parameters,
                                const Block<dim>           &block)
  {
    if (!parameters.enabled)
      return;
    mohr_coulomb =
      std::make_unique<MohrCoulomb>(parameters, block.get_material());
    two_mu              = 2. * block.get_material().mu();
    n_points_per_cell   = block.state_quadrature().size();
    const std::size_t n = block.get_triangulation().n_active_cells() *
                          std::size_t(n_points_per_cell);
    plastic_strain_committed.assign(n, SymmetricTensor<2, 3>());
    plastic_strain.assign(n, SymmetricTensor<2, 3>());
    plastic_strain_load.assign(n, SymmetricTensor<2, 3>());
    plastic_residual.assign(n, SymmetricTensor<2, 3>());
    plastic_residual_previous.assign(n, SymmetricTensor<2, 3>());
    yielded.assign(n, false);
    newton = parameters.newton;
    if (newton)
      {
        elastic_tangent = mohr_coulomb->elastic_tangent<dim>();
        linearisation.tangent.assign(n, elastic_tangent);
        linearisation.plastic.assign(n, false);
        linearisation.strain.assign(n, SymmetricTensor<2, dim>());
        linearisation.stress.assign(n, SymmetricTensor<2, dim>());
        linearisation_committed = linearisation;
      }
  }



  template <int dim>
  bool
  PlasticState<dim>::enabled() const
  {
    return mohr_coulomb != nullptr;
  }



  template <int dim>
  bool
  PlasticState<dim>::uses_newton() const
  {
    return newton;
  }



  template <int dim>
  SymmetricTensor<2, 3>
  PlasticState<dim>::plastic_stress(const unsigned int cell,
                                    const unsigned int q) const
  {
    return mohr_coulomb->elastic_stress(
      plastic_strain_load[cell * n_points_per_cell + q]);
  }



  template <int dim>
  SymmetricTensor<2, dim>
  PlasticState<dim>::load_stress(const unsigned int cell,
                                 const unsigned int q) const
  {
    const SymmetricTensor<2, 3> s3 = plastic_stress(cell, q);
    SymmetricTensor<2, dim>     s;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        s[i][j] = s3[i][j];
    // Newton: + (C_t - D) eps(u_j), the part of K_t u_j that the elastic
    // stiffness does not give.
    if (newton)
      {
        const std::size_t index = cell * n_points_per_cell + q;
        if (linearisation.plastic[index])
          s += (linearisation.tangent[index] - elastic_tangent) *
               linearisation.strain[index];
      }
    return s;
  }



  template <int dim>
  const SymmetricTensor<4, dim> &
  PlasticState<dim>::tangent(const std::size_t index) const
  {
    return linearisation.tangent[index];
  }



  template <int dim>
  void
  PlasticState<dim>::tangent_assembled()
  {
    tangent_is_stale = false;
    assembled_plastic_tangent =
      newton && std::find(linearisation.plastic.begin(),
                          linearisation.plastic.end(),
                          true) != linearisation.plastic.end();
  }



  template <int dim>
  PlasticUpdate
  PlasticState<dim>::update(const Block<dim> &block)
  {
    PlasticUpdate result;
    if (!mohr_coulomb)
      return result;
    FEValues<dim>                        fe_values(block.get_mapping(),
                            block.get_fe(),
                            block.state_quadrature(),
                            update_gradients | update_quadrature_points |
                              update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    const InSituStress                  *in_situ = block.get_in_situ_stress();
    std::vector<SymmetricTensor<2, dim>> eps(fe_values.n_quadrature_points);
    for (const auto &cell : block.get_dof_handler().active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_symmetric_gradients(
          block.get_solution(), eps);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const std::size_t index =
              cell->active_cell_index() * fe_values.n_quadrature_points + q;
            SymmetricTensor<2, 3> strain; // plane strain: eps_zz = 0
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                strain[i][j] = eps[q][i][j];
            SymmetricTensor<2, 3> trial = mohr_coulomb->elastic_stress(
              strain - plastic_strain_committed[index]);
            if (in_situ)
              trial += in_situ->stress_3d(fe_values.quadrature_point(q));
            SymmetricTensor<2, 3> stress, increment;
            yielded[index] = mohr_coulomb->return_map(trial, stress, increment);
            const SymmetricTensor<2, 3> updated =
              plastic_strain_committed[index] + increment;
            const double JxW = fe_values.JxW(q);
            if (newton && !newton_suspended)
              {
                update_newton_point(index, eps[q], trial, stress, JxW, result);
                plastic_strain_load[index] = updated;
              }
            else
              update_fixed_point(index, updated, JxW, result);
            plastic_strain[index] = updated;
            result.norm2 += squared(updated) * JxW;
            ++result.n_points;
            if (yielded[index])
              {
                ++result.n_yielded;
                result.yielded_measure += JxW;
              }
            result.max_equivalent =
              std::max(result.max_equivalent,
                       std::sqrt(2. / 3. * squared(updated)));
          }
      }
    return result;
  }



  template <int dim>
  void
  PlasticState<dim>::update_fixed_point(const std::size_t            index,
                                        const SymmetricTensor<2, 3> &updated,
                                        const double                 JxW,
                                        PlasticUpdate               &result)
  {
    const SymmetricTensor<2, 3> residual = updated - plastic_strain_load[index];
    result.change2 += squared(residual) * JxW;
    if (have_previous_residual)
      {
        const SymmetricTensor<2, 3> &previous =
          plastic_residual_previous[index];
        result.aitken_numerator += (previous * (residual - previous)) * JxW;
        result.aitken_denominator += squared(residual - previous) * JxW;
      }
    plastic_residual[index] = residual;
  }



  template <int dim>
  void
  PlasticState<dim>::update_newton_point(const std::size_t              index,
                                         const SymmetricTensor<2, dim> &strain,
                                         const SymmetricTensor<2, 3>   &trial,
                                         const SymmetricTensor<2, 3>   &stress,
                                         const double                   JxW,
                                         PlasticUpdate                 &result)
  {
    SymmetricTensor<2, dim> returned, trial_in_plane;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        {
          returned[i][j]       = stress[i][j];
          trial_in_plane[i][j] = trial[i][j];
        }
    // The residual: the returned stress against the one the linearisation
    // at u_j predicted (an elastic tangent predicts the trial stress), in
    // strain units like the initial-stress residual. A point elastic at
    // both u_j and u_{j+1} has none.
    if (linearisation.plastic[index] || yielded[index])
      {
        const SymmetricTensor<2, dim> predicted =
          linearisation.plastic[index] ?
            linearisation.stress[index] +
              linearisation.tangent[index] *
                (strain - linearisation.strain[index]) :
            trial_in_plane;
        result.change2 += squared(returned - predicted) /
                          Utilities::fixed_power<2>(two_mu) * JxW;
        tangent_is_stale = true;
      }
    linearisation.tangent[index] =
      yielded[index] ? mohr_coulomb->tangent<dim>(trial) : elastic_tangent;
    linearisation.plastic[index] = yielded[index];
    linearisation.strain[index]  = strain;
    linearisation.stress[index]  = returned;
  }



  template <int dim>
  bool
  PlasticState<dim>::tangent_changed() const
  {
    return tangent_is_stale;
  }



  template <int dim>
  bool
  PlasticState<dim>::suspend_newton(const bool suspend)
  {
    if (!newton)
      return false;
    newton_suspended = suspend;
    if (!suspend)
      return false;
    // The elastic tangent everywhere: the load then carries D eps_p alone,
    // as in the initial-stress method, and the residual below is measured
    // as there (the change of the plastic strain).
    for (std::size_t i = 0; i < linearisation.tangent.size(); ++i)
      if (linearisation.plastic[i])
        {
          linearisation.tangent[i] = elastic_tangent;
          linearisation.plastic[i] = false;
        }
    tangent_is_stale = assembled_plastic_tangent;
    return assembled_plastic_tangent;
  }



  template <int dim>
  void
  PlasticState<dim>::relax(const double omega)
  {
    for (std::size_t i = 0; i < plastic_strain_load.size(); ++i)
      plastic_strain_load[i] += omega * plastic_residual[i];
    plastic_residual_previous = plastic_residual;
    have_previous_residual    = true;
  }



  template <int dim>
  void
  PlasticState<dim>::commit()
  {
    plastic_strain_committed = plastic_strain;
    plastic_strain_load      = plastic_strain;
    have_previous_residual   = false;
    if (newton)
      linearisation_committed = linearisation;
  }



  template <int dim>
  void
  PlasticState<dim>::restore()
  {
    if (!mohr_coulomb)
      return;
    plastic_strain         = plastic_strain_committed;
    plastic_strain_load    = plastic_strain_committed;
    have_previous_residual = false;
    if (newton)
      {
        linearisation    = linearisation_committed;
        tangent_is_stale = true;
      }
  }



  template <int dim>
  void
  PlasticState<dim>::cell_fields(const unsigned int                  n_cells,
                                 std::vector<SymmetricTensor<2, 3>> &stress,
                                 std::vector<double> &yielded_fraction,
                                 std::vector<double> &equivalent_strain) const
  {
    stress.clear();
    yielded_fraction.assign(n_cells, 0.);
    equivalent_strain.assign(n_cells, 0.);
    if (!mohr_coulomb)
      return;
    const unsigned int n_q = n_points_per_cell;
    stress.reserve(std::size_t(n_cells) * n_q);
    for (unsigned int c = 0; c < n_cells; ++c)
      for (unsigned int q = 0; q < n_q; ++q)
        {
          stress.push_back(plastic_stress(c, q));
          yielded_fraction[c] += (yielded[c * n_q + q] ? 1. : 0.) / n_q;
          equivalent_strain[c] =
            std::max(equivalent_strain[c],
                     std::sqrt(2. / 3. * squared(plastic_strain[c * n_q + q])));
        }
  }



  template class PlasticState<2>;
  template class PlasticState<3>;
} // namespace mbfem

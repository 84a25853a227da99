#include <mbfem/base/exceptions.h>
#include <mbfem/block/block.h>
#include <mbfem/block/flexibility.h>
#include <mbfem/block/floating_modes.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>

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

  void
  DiscretisationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    {
      prm.declare_entry("Polynomial degree",
                        "2",
                        Patterns::Integer(1, 4),
                        "Degree p of the FE_Q(p) Lagrange elements of every "
                        "block's displacement (1 to 4).");
      prm.declare_entry(
        "Mapping degree",
        "0",
        Patterns::Integer(0, 4),
        "Degree of the MappingQ that maps cells to their curved shape. 0 "
        "means the same as the polynomial degree, which keeps the optimal "
        "convergence rates on curved boundaries.");
    }
    prm.leave_subsection();
  }



  void
  DiscretisationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    {
      degree         = prm.get_integer("Polynomial degree");
      mapping_degree = prm.get_integer("Mapping degree");
      if (mapping_degree == 0)
        mapping_degree = degree;
    }
    prm.leave_subsection();
  }



  template <int dim>
  Block<dim>::Block(const Material                 &material,
                    const DiscretisationParameters &discretisation,
                    const std::string              &solver_package,
                    const types::material_id        id)
    : id(id)
    , material(material)
    , fe(FE_Q<dim>(discretisation.degree), dim)
    , mapping(discretisation.mapping_degree)
    , direct_solver(solver_package)
  {}



  template <int dim>
  std::string
  Block<dim>::name() const
  {
    return "block " + std::to_string(id);
  }



  template <int dim>
  void
  Block<dim>::setup_system(const BoundaryConditions<dim> &boundary_conditions)
  {
    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);
    solution.reinit(dof_handler.n_dofs());
    load.reinit(dof_handler.n_dofs());
    external_load.reinit(dof_handler.n_dofs());
    physical_load.reinit(dof_handler.n_dofs());

    // The supports first, then the floating modes they leave free and the
    // pins that remove them, then the constraints again with the pins.
    make_constraints(boundary_conditions, {});
    floating.compute(dof_handler, mapping, physical_constraints, name());
    make_constraints(boundary_conditions, floating.pins());

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    stiffness.reinit(complete_index_set(dof_handler.n_dofs()),
                     complete_index_set(dof_handler.n_dofs()),
                     dsp,
                     MPI_COMM_SELF);
  }



  template <int dim>
  void
  Block<dim>::set_initial_state(const InSituStress *in_situ_stress,
                                const Excavation   *excavation_data)
  {
    in_situ =
      (in_situ_stress != nullptr && in_situ_stress->enabled ? in_situ_stress :
                                                              nullptr);
    excavation = excavation_data;
  }



  template <int dim>
  const InSituStress *
  Block<dim>::get_in_situ_stress() const
  {
    return in_situ;
  }



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
  Block<dim>::set_plasticity(const PlasticityParameters &parameters)
  {
    if (!parameters.enabled)
      return;
    mohr_coulomb = std::make_unique<MohrCoulomb>(parameters, material);
    const std::size_t n =
      triangulation.n_active_cells() * std::size_t(n_plastic_points());
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
  Block<dim>::is_plastic() const
  {
    return mohr_coulomb != nullptr;
  }



  template <int dim>
  unsigned int
  Block<dim>::n_plastic_points() const
  {
    return state_quadrature().size();
  }



  template <int dim>
  SymmetricTensor<2, 3>
  Block<dim>::plastic_stress(const unsigned int cell,
                             const unsigned int q) const
  {
    return mohr_coulomb->elastic_stress(
      plastic_strain_load[cell * n_plastic_points() + q]);
  }



  template <int dim>
  PlasticUpdate
  Block<dim>::update_plastic_strain()
  {
    PlasticUpdate result;
    if (!mohr_coulomb)
      return result;
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            state_quadrature(),
                            update_gradients | update_quadrature_points |
                              update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> eps(fe_values.n_quadrature_points);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values[displacement].get_function_symmetric_gradients(solution, eps);
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
              {
                const SymmetricTensor<2, 3> residual =
                  updated - plastic_strain_load[index];
                result.change2 += squared(residual) * JxW;
                if (have_previous_residual)
                  {
                    const SymmetricTensor<2, 3> &previous =
                      plastic_residual_previous[index];
                    result.aitken_numerator +=
                      (previous * (residual - previous)) * JxW;
                    result.aitken_denominator +=
                      squared(residual - previous) * JxW;
                  }
                plastic_residual[index] = residual;
              }
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
  Block<dim>::update_newton_point(const std::size_t              index,
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
                          Utilities::fixed_power<2>(2. * material.mu()) * JxW;
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
  Block<dim>::tangent_changed() const
  {
    return tangent_is_stale;
  }



  template <int dim>
  bool
  Block<dim>::suspend_newton(const bool suspend)
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
  Block<dim>::relax_plastic_strain(const double omega)
  {
    for (std::size_t i = 0; i < plastic_strain_load.size(); ++i)
      plastic_strain_load[i] += omega * plastic_residual[i];
    plastic_residual_previous = plastic_residual;
    have_previous_residual    = true;
  }



  template <int dim>
  void
  Block<dim>::commit_plastic_strain()
  {
    plastic_strain_committed = plastic_strain;
    plastic_strain_load      = plastic_strain;
    have_previous_residual   = false;
    if (newton)
      linearisation_committed = linearisation;
  }



  template <int dim>
  void
  Block<dim>::restore_plastic_state()
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
  Block<dim>::cell_plastic_fields(std::vector<SymmetricTensor<2, 3>> &stress,
                                  std::vector<double> &yielded_fraction,
                                  std::vector<double> &equivalent_strain) const
  {
    const unsigned int n_cells = triangulation.n_active_cells();
    stress.clear();
    yielded_fraction.assign(n_cells, 0.);
    equivalent_strain.assign(n_cells, 0.);
    if (!mohr_coulomb)
      return;
    const unsigned int n_q = n_plastic_points();
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



  template <int dim>
  SymmetricTensor<2, dim>
  Block<dim>::initial_stress(const Point<dim> &point) const
  {
    return in_situ ? in_situ->stress(point) : SymmetricTensor<2, dim>();
  }



  template <int dim>
  void
  Block<dim>::make_constraints(
    const BoundaryConditions<dim>              &boundary_conditions,
    const std::vector<types::global_dof_index> &pins)
  {
    physical_constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, physical_constraints);
    const std::vector<types::boundary_id> ids =
      triangulation.get_boundary_ids();
    const auto has_id = [&ids](const types::boundary_id id) {
      return std::find(ids.begin(), ids.end(), id) != ids.end();
    };

    for (const auto &[id, mask] : boundary_conditions.dirichlet)
      if (has_id(id))
        VectorTools::interpolate_boundary_values(
          mapping,
          dof_handler,
          id,
          *boundary_conditions.prescribed_displacement,
          physical_constraints,
          mask);

    if (!boundary_conditions.point_supports.empty())
      {
        const std::vector<Point<dim>> points = support_points();
        const double tolerance = 1e-6 * GridTools::diameter(triangulation);
        std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
        for (const auto &[point, mask] : boundary_conditions.point_supports)
          for (const auto &cell : dof_handler.active_cell_iterators())
            {
              cell->get_dof_indices(dof_indices);
              for (unsigned int i = 0; i < dof_indices.size(); ++i)
                if (mask[fe.system_to_component_index(i).first] &&
                    points[dof_indices[i]].distance(point) < tolerance &&
                    !physical_constraints.is_constrained(dof_indices[i]))
                  physical_constraints.add_line(dof_indices[i]);
            }
      }

    for (const auto &[id, component] : boundary_conditions.rigid_platens)
      if (has_id(id))
        {
          std::vector<bool> selected(dim, false);
          selected[component] = true;
          const IndexSet platen_dofs =
            DoFTools::extract_boundary_dofs(dof_handler,
                                            ComponentMask(selected),
                                            {id});
          types::global_dof_index master = numbers::invalid_dof_index;
          for (const auto i : platen_dofs)
            {
              AssertThrow(!physical_constraints.is_constrained(i),
                          ExcMessage(
                            name() + ": the rigid platen on boundary " +
                            std::to_string(id) +
                            " overlaps a prescribed displacement of the same "
                            "component."));
              if (master == numbers::invalid_dof_index)
                master = i;
              else
                {
                  physical_constraints.add_line(i);
                  physical_constraints.add_entry(i, master, 1.);
                }
            }
        }
    physical_constraints.close();

    constraints.clear();
    constraints.merge(physical_constraints);
    for (const auto i : pins)
      if (!constraints.is_constrained(i))
        constraints.add_line(i);
    constraints.close();

    homogeneous_constraints.clear();
    homogeneous_constraints.copy_from(constraints);
    for (const auto &line : homogeneous_constraints.get_lines())
      homogeneous_constraints.set_inhomogeneity(line.index, 0.);
  }



  template <int dim>
  void
  Block<dim>::cell_matrix(const FEValues<dim> &fe_values,
                          FullMatrix<double>  &matrix,
                          const unsigned int   cell_index) const
  {
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n      = fe.n_dofs_per_cell();
    const double                         lambda = material.lambda();
    const double                         mu     = material.mu();
    std::vector<SymmetricTensor<2, dim>> eps(n);
    std::vector<double>                  div(n);

    matrix = 0.;
    if (newton)
      {
        // The consistent tangent at the points of the plastic state (the
        // same QGauss(p + 1)); not symmetric for non-associated flow.
        const unsigned int n_q = fe_values.n_quadrature_points;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const SymmetricTensor<4, dim> &C =
              linearisation.tangent[cell_index * n_q + q];
            for (unsigned int i = 0; i < n; ++i)
              eps[i] = fe_values[displacement].symmetric_gradient(i, q);
            const double JxW = fe_values.JxW(q);
            for (unsigned int j = 0; j < n; ++j)
              {
                const SymmetricTensor<2, dim> C_eps_j = C * eps[j];
                for (unsigned int i = 0; i < n; ++i)
                  matrix(i, j) += (eps[i] * C_eps_j) * JxW;
              }
          }
        return;
      }
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            eps[i] = fe_values[displacement].symmetric_gradient(i, q);
            div[i] = trace(eps[i]);
          }
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = i; j < n; ++j)
            matrix(i, j) +=
              (lambda * div[i] * div[j] + 2. * mu * (eps[i] * eps[j])) * JxW;
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < i; ++j)
        matrix(i, j) = matrix(j, i);
  }



  template <int dim>
  template <typename MatrixType>
  void
  Block<dim>::assemble_matrix(const AffineConstraints<double> &constraints,
                              MatrixType                      &matrix) const
  {
    FEValues<dim>      fe_values(mapping,
                            fe,
                            state_quadrature(),
                            update_gradients | update_JxW_values);
    FullMatrix<double> cell(fe.n_dofs_per_cell(), fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &c : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(c);
        cell_matrix(fe_values, cell, c->active_cell_index());
        c->get_dof_indices(dof_indices);
        constraints.distribute_local_to_global(cell, dof_indices, matrix);
      }
  }



  template <int dim>
  void
  Block<dim>::assemble_stiffness()
  {
    // The matrix alone: its constrained rows and columns do not depend on
    // the prescribed values, so one factorisation serves all times.
    stiffness = 0.;
    assemble_matrix(constraints, stiffness);
    stiffness.compress(VectorOperation::add);
    tangent_is_stale = false;
    assembled_plastic_tangent =
      newton && std::find(linearisation.plastic.begin(),
                          linearisation.plastic.end(),
                          true) != linearisation.plastic.end();
  }



  template <int dim>
  void
  Block<dim>::assemble_unpinned_stiffness(SparsityPattern      &pattern,
                                          SparseMatrix<double> &matrix) const
  {
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    physical_constraints,
                                    false);
    pattern.copy_from(dsp);
    matrix.reinit(pattern);
    assemble_matrix(physical_constraints, matrix);
  }



  template <int dim>
  const AffineConstraints<double> &
  Block<dim>::get_physical_constraints() const
  {
    return physical_constraints;
  }



  template <int dim>
  const Vector<double> &
  Block<dim>::unpinned_load() const
  {
    return physical_load;
  }



  template <int dim>
  void
  Block<dim>::factorize()
  {
    try
      {
        direct_solver.factorize(stiffness);
      }
    catch (const Exceptions::ExcSingularMatrix &e)
      {
        AssertThrow(false,
                    Exceptions::ExcSingularMatrix(name() + ": " +
                                                  message_of(e)));
      }
  }



  template <int dim>
  void
  Block<dim>::assemble_load(BoundaryConditions<dim> &boundary_conditions,
                            const double             time)
  {
    boundary_conditions.set_time(time);
    make_constraints(boundary_conditions, floating.pins());
    load          = 0.;
    external_load = 0.;
    physical_load = 0.;

    const unsigned int                   n = fe.n_dofs_per_cell();
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            QGauss<dim>(fe.degree + 2),
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    FEFaceValues<dim>                    fe_face_values(mapping,
                                     fe,
                                     QGauss<dim - 1>(fe.degree + 2),
                                     update_values | update_quadrature_points |
                                       update_normal_vectors |
                                       update_JxW_values);
    FEValues<dim>                        stiffness_values(mapping,
                                   fe,
                                   state_quadrature(),
                                   update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    FullMatrix<double>                   matrix(n, n);
    Vector<double>                       cell_load(n);
    std::vector<types::global_dof_index> dof_indices(n);
    Vector<double>                       value(dim);

    // Gravity acts in -y (2D) or -z (3D), scaled by the load history if
    // 'Gravity ramp time' says so.
    Tensor<1, dim> weight;
    weight[dim - 1] =
      -material.unit_weight * boundary_conditions.gravity_factor;

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell_load = 0.;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            boundary_conditions.body_force->vector_value(
              fe_values.quadrature_point(q), value);
            Tensor<1, dim> b = weight;
            for (unsigned int d = 0; d < dim; ++d)
              b[d] += value[d];
            for (unsigned int i = 0; i < n; ++i)
              cell_load(i) +=
                fe_values[displacement].value(i, q) * b * fe_values.JxW(q);
            // The initial stress: -int B^T sigma_0, which gravity and the
            // boundaries balance in the geostatic state.
            if (in_situ)
              {
                const SymmetricTensor<2, dim> sigma_0 =
                  initial_stress(fe_values.quadrature_point(q));
                for (unsigned int i = 0; i < n; ++i)
                  cell_load(i) -=
                    (fe_values[displacement].symmetric_gradient(i, q) *
                     sigma_0) *
                    fe_values.JxW(q);
              }
          }

        // The plastic strain as a load, int B^T D eps_p, at the points of
        // the plastic state.
        if (mohr_coulomb)
          {
            stiffness_values.reinit(cell);
            for (const unsigned int q :
                 stiffness_values.quadrature_point_indices())
              {
                const SymmetricTensor<2, 3> s3 =
                  plastic_stress(cell->active_cell_index(), q);
                SymmetricTensor<2, dim> s;
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int j = i; j < dim; ++j)
                    s[i][j] = s3[i][j];
                // Newton: + (C_t - D) eps(u_j), the part of K_t u_j that
                // the elastic stiffness does not give.
                if (newton)
                  {
                    const std::size_t index =
                      cell->active_cell_index() * n_plastic_points() + q;
                    if (linearisation.plastic[index])
                      s += (linearisation.tangent[index] - elastic_tangent) *
                           linearisation.strain[index];
                  }
                for (unsigned int i = 0; i < n; ++i)
                  cell_load(i) +=
                    (stiffness_values[displacement].symmetric_gradient(i, q) *
                     s) *
                    stiffness_values.JxW(q);
              }
          }

        // Far-field boundaries held by the in-situ stress, and the faces
        // of an excavation with the support of the removed rock, released
        // as t goes from 0 to 1.
        if (in_situ)
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                double factor = 0.;
                if (in_situ->stress_boundaries.count(face->boundary_id()) == 1)
                  factor = 1.;
                else if (excavation != nullptr &&
                         excavation->released_boundaries.count(
                           face->boundary_id()) == 1)
                  factor = 1. - Excavation::released(time);
                if (factor == 0.)
                  continue;
                fe_face_values.reinit(cell, face);
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  {
                    const Tensor<1, dim> t =
                      factor *
                      (initial_stress(fe_face_values.quadrature_point(q)) *
                       fe_face_values.normal_vector(q));
                    for (unsigned int i = 0; i < n; ++i)
                      cell_load(i) += fe_face_values[displacement].value(i, q) *
                                      t * fe_face_values.JxW(q);
                  }
              }

        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              boundary_conditions.traction_boundaries.count(
                face->boundary_id()) == 1)
            {
              fe_face_values.reinit(cell, face);
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                {
                  boundary_conditions.traction->vector_value(
                    fe_face_values.quadrature_point(q), value);
                  Tensor<1, dim> t;
                  for (unsigned int d = 0; d < dim; ++d)
                    t[d] = value[d];
                  for (unsigned int i = 0; i < n; ++i)
                    cell_load(i) += fe_face_values[displacement].value(i, q) *
                                    t * fe_face_values.JxW(q);
                }
            }

        cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < n; ++i)
          external_load(dof_indices[i]) += cell_load(i);

        // The cell matrix is needed only where a prescribed displacement
        // enters: it moves -K u_D to the right-hand side.
        bool has_constrained_dof = false;
        for (const auto i : dof_indices)
          if (constraints.is_inhomogeneously_constrained(i))
            has_constrained_dof = true;
        if (has_constrained_dof)
          {
            stiffness_values.reinit(cell);
            cell_matrix(stiffness_values, matrix, cell->active_cell_index());
            constraints.distribute_local_to_global(cell_load,
                                                   dof_indices,
                                                   load,
                                                   matrix);
            physical_constraints.distribute_local_to_global(cell_load,
                                                            dof_indices,
                                                            physical_load,
                                                            matrix);
          }
        else
          {
            constraints.distribute_local_to_global(cell_load,
                                                   dof_indices,
                                                   load);
            physical_constraints.distribute_local_to_global(cell_load,
                                                            dof_indices,
                                                            physical_load);
          }
      }
  }



  template <int dim>
  void
  Block<dim>::add_point_forces(const std::vector<types::global_dof_index> &dofs,
                               const std::vector<double> &forces)
  {
    AssertDimension(dofs.size(), forces.size());
    Vector<double> local(forces.begin(), forces.end());
    homogeneous_constraints.distribute_local_to_global(local, dofs, load);
    for (unsigned int i = 0; i < dofs.size(); ++i)
      external_load(dofs[i]) += forces[i];
  }



  template <int dim>
  void
  Block<dim>::solve(const std::vector<double> &alpha)
  {
    direct_solver.solve(solution, load);
    constraints.distribute(solution);
    AssertThrow(alpha.empty() || alpha.size() == floating.modes().size(),
                ExcInternalError());
    for (unsigned int i = 0; i < alpha.size(); ++i)
      solution.add(alpha[i], floating.modes()[i]);
  }



  template <int dim>
  FullMatrix<double>
  Block<dim>::flexibility(
    const std::vector<types::global_dof_index> &dofs) const
  {
    const unsigned int m = dofs.size();
    // Many contact DoFs: selected entries of K^{-1} from MUMPS
    // (block/flexibility.h), one factorisation instead of m solves; a
    // Newton tangent may be indefinite. Few: the block's own factorisation
    // and unit loads are cheaper (MUMPS's set-up dominates; 74 contact DoFs
    // of a Hertz block: 0.03 s against 0.1 s).
    if (m >= 500)
      return contact_flexibility(stiffness,
                                 homogeneous_constraints,
                                 dofs,
                                 !newton);
    const std::size_t      n = dof_handler.n_dofs();
    FullMatrix<double>     result(m, m);
    constexpr unsigned int chunk = 64; // right-hand sides per solve
    std::vector<double>    rhs, x;
    for (unsigned int first = 0; first < m; first += chunk)
      {
        const unsigned int count = std::min(chunk, m - first);
        rhs.assign(n * count, 0.);
        x.assign(n * count, 0.);
        for (unsigned int k = 0; k < count; ++k)
          {
            // A unit force at a constrained DoF goes where the constraints
            // send it (a platen node loads the platen; a fixed node, none).
            Vector<double> column(n);
            homogeneous_constraints.distribute_local_to_global(
              Vector<double>({1.}),
              std::vector<types::global_dof_index>{dofs[first + k]},
              column);
            std::copy(column.begin(), column.end(), rhs.begin() + k * n);
          }
        direct_solver.solve(x.data(), rhs.data(), count);
        for (unsigned int k = 0; k < count; ++k)
          {
            Vector<double> column(x.begin() + k * n, x.begin() + (k + 1) * n);
            homogeneous_constraints.distribute(column);
            for (unsigned int i = 0; i < m; ++i)
              result(i, first + k) = column(dofs[i]);
          }
      }
    return result;
  }



  template <int dim>
  std::vector<double>
  Block<dim>::external_load_resultant() const
  {
    std::vector<double> result(floating.modes().size());
    for (unsigned int a = 0; a < floating.modes().size(); ++a)
      result[a] = floating.modes()[a] * external_load;
    return result;
  }



  template <int dim>
  const std::vector<Vector<double>> &
  Block<dim>::floating_modes() const
  {
    return floating.modes();
  }



  template <int dim>
  std::vector<Vector<double>>
  Block<dim>::rigid_body_modes() const
  {
    return FloatingModes<dim>::rigid_body_modes(dof_handler, mapping);
  }



  template <int dim>
  std::string
  Block<dim>::describe_rigid_body_mode(const Vector<double> &coefficients)
  {
    return FloatingModes<dim>::describe(coefficients);
  }



  template <int dim>
  std::vector<Point<dim>>
  Block<dim>::support_points() const
  {
    std::vector<Point<dim>> points(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    return points;
  }



  template <int dim>
  const std::vector<Vector<double>> &
  Block<dim>::free_rigid_body_modes() const
  {
    return floating.coefficients();
  }



  template <int dim>
  QGauss<dim>
  Block<dim>::state_quadrature() const
  {
    return QGauss<dim>(fe.degree + 1);
  }



  template <int dim>
  SymmetricTensor<2, 3>
  Block<dim>::stress(const SymmetricTensor<2, dim> &strain,
                     const Point<dim>              &point,
                     const unsigned int             cell,
                     const unsigned int             q) const
  {
    SymmetricTensor<2, 3> sigma = material.stress_3d<dim>(strain);
    if (in_situ)
      sigma += in_situ->stress_3d(point);
    if (mohr_coulomb)
      sigma -= plastic_stress(cell, q);
    return sigma;
  }



  template <int dim>
  types::global_dof_index
  Block<dim>::n_dofs() const
  {
    return dof_handler.n_dofs();
  }



  template class Block<2>;
  template class Block<3>;
} // namespace mbfem

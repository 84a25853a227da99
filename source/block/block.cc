#include <mbfem/base/exceptions.h>
#include <mbfem/base/parallel.h>
#include <mbfem/base/text_input.h>
#include <mbfem/block/block.h>
#include <mbfem/block/flexibility.h>
#include <mbfem/block/floating_modes.h>
#include <mbfem/linear_algebra/mumps_solver.h>
#include <mbfem/mesh/mesh.h>

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
#include <utility>

namespace mbfem
{
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
      prm.declare_entry(
        "Block degrees",
        "",
        Patterns::Anything(),
        "Degrees of single blocks that differ from 'Polynomial degree', "
        "'id: p' separated by ';' (e.g. '1: 1; 2: 3'). With 'Mapping "
        "degree = 0' each block's mapping follows its own degree. Blocks of "
        "different degrees do not share nodes at their common faces: "
        "declare those interfaces 'mortar' (Contact/Interfaces).");
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
      mapping_follows_degree = (prm.get_integer("Mapping degree") == 0);
      block_degrees          = parse_id_values(prm.get("Block degrees"),
                                      "Finite element/Block degrees",
                                      1,
                                      4);
    }
    prm.leave_subsection();
  }



  unsigned int
  DiscretisationParameters::degree_of(const types::material_id id) const
  {
    const auto entry = block_degrees.find(id);
    return entry == block_degrees.end() ? degree : entry->second;
  }



  unsigned int
  DiscretisationParameters::mapping_degree_of(const types::material_id id) const
  {
    return mapping_follows_degree ? degree_of(id) : mapping_degree;
  }



  template <int dim>
  Block<dim>::Block(const Material                 &material,
                    const DiscretisationParameters &discretisation,
                    const std::string              &solver_package,
                    const types::material_id        id)
    : id(id)
    , material(material)
    , fe(FE_Q<dim>(discretisation.degree_of(id)), dim)
    , mapping(discretisation.mapping_degree_of(id))
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
  Block<dim>::extract_mesh(const Triangulation<dim> &mesh)
  {
    extract_block(mesh, id, triangulation);
  }



  template <int dim>
  void
  Block<dim>::refine_mesh(const unsigned int times)
  {
    // Children keep their parent's boundary ids, so the faces shared with
    // other blocks stay marked.
    triangulation.refine_global(times);
  }



  template <int dim>
  void
  Block<dim>::create_mesh(const MeshParameters &parameters)
  {
    mbfem::create_mesh(parameters, triangulation);
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

    if (!local)
      return; // another rank's block: no stiffness here
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    stiffness.reinit(complete_index_set(dof_handler.n_dofs()),
                     complete_index_set(dof_handler.n_dofs()),
                     dsp,
                     MPI_COMM_SELF);
  }



  template <int dim>
  void
  Block<dim>::set_owner(const MPI_Comm comm, const unsigned int owner_rank)
  {
    communicator = comm;
    owner        = owner_rank;
    local        = Utilities::MPI::this_mpi_process(comm) == owner_rank;
  }



  template <int dim>
  bool
  Block<dim>::is_local() const
  {
    return local;
  }



  template <int dim>
  MPI_Comm
  Block<dim>::get_communicator() const
  {
    return communicator;
  }



  template <int dim>
  unsigned int
  Block<dim>::get_owner() const
  {
    return owner;
  }



  template <int dim>
  double
  Block<dim>::cost() const
  {
    return static_cast<double>(triangulation.n_active_cells()) *
           fe.n_dofs_per_cell();
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



  template <int dim>
  PlasticState<dim> &
  Block<dim>::plastic_state()
  {
    return plastic;
  }



  template <int dim>
  const PlasticState<dim> &
  Block<dim>::plastic_state() const
  {
    return plastic;
  }



  template <int dim>
  bool
  Block<dim>::is_plastic() const
  {
    return plastic.enabled();
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
        const double tolerance               = 1e-6 * diameter(triangulation);
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
    if (plastic.uses_newton())
      {
        // The consistent tangent at the points of the plastic state (the
        // same QGauss(p + 1)); not symmetric for non-associated flow.
        const unsigned int n_q = fe_values.n_quadrature_points;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const SymmetricTensor<4, dim> &C =
              plastic.tangent(cell_index * n_q + q);
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
    if (local)
      {
        stiffness = 0.;
        assemble_matrix(constraints, stiffness);
        stiffness.compress(VectorOperation::add);
      }
    plastic.tangent_assembled();
  }



  template <int dim>
  const AffineConstraints<double> &
  Block<dim>::get_physical_constraints() const
  {
    return physical_constraints;
  }



  template <int dim>
  const Vector<double> &
  Block<dim>::get_physical_load() const
  {
    return physical_load;
  }



  template <int dim>
  void
  Block<dim>::factorize()
  {
    if (!local)
      return; // another rank's block
    try
      {
        if (mumps_solver)
          mumps_solver->factorize(stiffness, !plastic.uses_newton());
        else
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
  Block<dim>::set_added(const double start, const double end)
  {
    Assert(end > start, ExcInternalError());
    added_from  = start;
    added_until = end;
  }



  template <int dim>
  void
  Block<dim>::set_removed(const double start)
  {
    removed_after = start;
  }



  template <int dim>
  double
  Block<dim>::presence(const double time) const
  {
    if (time > removed_after)
      return 0.;
    if (added_until <= added_from)
      return 1.;
    return std::clamp((time - added_from) / (added_until - added_from), 0., 1.);
  }



  template <int dim>
  void
  Block<dim>::assemble_load(BoundaryConditions<dim> &boundary_conditions,
                            const double             time,
                            const bool               on_every_rank)
  {
    boundary_conditions.set_time(time);
    make_constraints(boundary_conditions, floating.pins());
    external_load = 0.;
    physical_load = 0.;
    load          = 0.;
    if (!local && !on_every_rank)
      return; // the owner's work: share_load_resultant() brings F_e

    const unsigned int n = fe.n_dofs_per_cell();
    FEValues<dim>      fe_values(mapping,
                            fe,
                            QGauss<dim>(fe.degree + 2),
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    FEFaceValues<dim>  fe_face_values(mapping,
                                     fe,
                                     QGauss<dim - 1>(fe.degree + 2),
                                     update_values | update_quadrature_points |
                                       update_normal_vectors |
                                       update_JxW_values);
    FEValues<dim>      state_values(mapping,
                               fe,
                               state_quadrature(),
                               update_gradients | update_JxW_values);
    Vector<double>     cell_load(n);
    // A block a stage adds: its weight and loads come on over the stage.
    const double fraction = presence(time);

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell_load = 0.;
        add_volume_load(fe_values, boundary_conditions, cell_load);
        if (plastic.enabled())
          add_plastic_load(cell, state_values, cell_load);
        if (in_situ)
          add_in_situ_boundary_load(cell, time, fe_face_values, cell_load);
        add_traction_load(cell, boundary_conditions, fe_face_values, cell_load);
        cell_load *= fraction;
        distribute_cell_load(cell, cell_load, state_values);
      }

    // The pinned system's load is the physical one with nothing at the
    // pins: distributing through the pins' empty constraint lines would
    // give the same at every other DoF (they only drop what reaches a pin).
    load = physical_load;
    for (const auto i : floating.pins())
      load(i) = 0.;
  }



  template <int dim>
  void
  Block<dim>::add_volume_load(
    const FEValues<dim>           &fe_values,
    const BoundaryConditions<dim> &boundary_conditions,
    Vector<double>                &cell_load) const
  {
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               n = fe.n_dofs_per_cell();
    Vector<double>                   value(dim);
    // Gravity acts in -y (2D) or -z (3D), scaled by the load history if
    // 'Gravity ramp time' says so.
    Tensor<1, dim> weight;
    weight[dim - 1] =
      -material.unit_weight * boundary_conditions.gravity_factor;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        Tensor<1, dim> b = weight;
        if (!boundary_conditions.body_force_is_zero)
          {
            boundary_conditions.body_force->vector_value(
              fe_values.quadrature_point(q), value);
            for (unsigned int d = 0; d < dim; ++d)
              b[d] += value[d];
          }
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
                (fe_values[displacement].symmetric_gradient(i, q) * sigma_0) *
                fe_values.JxW(q);
          }
      }
  }



  template <int dim>
  void
  Block<dim>::add_plastic_load(const cell_iterator &cell,
                               FEValues<dim>       &state_values,
                               Vector<double>      &cell_load) const
  {
    // The plastic strain as a load, int B^T D eps_p, at the points of the
    // plastic state.
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               n = fe.n_dofs_per_cell();
    state_values.reinit(cell);
    for (const unsigned int q : state_values.quadrature_point_indices())
      {
        const SymmetricTensor<2, dim> s =
          plastic.load_stress(cell->active_cell_index(), q);
        for (unsigned int i = 0; i < n; ++i)
          cell_load(i) +=
            (state_values[displacement].symmetric_gradient(i, q) * s) *
            state_values.JxW(q);
      }
  }



  template <int dim>
  void
  Block<dim>::add_in_situ_boundary_load(const cell_iterator &cell,
                                        const double         time,
                                        FEFaceValues<dim>   &fe_face_values,
                                        Vector<double>      &cell_load) const
  {
    // Far-field boundaries held by the in-situ stress, and the faces of an
    // excavation with the support of the removed rock, released as t goes
    // from 0 to 1.
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               n = fe.n_dofs_per_cell();
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary())
        {
          double factor = 0.;
          if (in_situ->stress_boundaries.count(face->boundary_id()) == 1)
            factor = 1.;
          else if (excavation != nullptr &&
                   excavation->released_boundaries.count(face->boundary_id()) ==
                     1)
            factor = 1. - Excavation::released(time);
          if (factor == 0.)
            continue;
          fe_face_values.reinit(cell, face);
          for (const unsigned int q : fe_face_values.quadrature_point_indices())
            {
              const Tensor<1, dim> t =
                factor * (initial_stress(fe_face_values.quadrature_point(q)) *
                          fe_face_values.normal_vector(q));
              for (unsigned int i = 0; i < n; ++i)
                cell_load(i) += fe_face_values[displacement].value(i, q) * t *
                                fe_face_values.JxW(q);
            }
        }
  }



  template <int dim>
  void
  Block<dim>::add_traction_load(
    const cell_iterator           &cell,
    const BoundaryConditions<dim> &boundary_conditions,
    FEFaceValues<dim>             &fe_face_values,
    Vector<double>                &cell_load) const
  {
    const FEValuesExtractors::Vector displacement(0);
    const unsigned int               n = fe.n_dofs_per_cell();
    Vector<double>                   value(dim);
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() && boundary_conditions.traction_boundaries.count(
                                   face->boundary_id()) == 1)
        {
          fe_face_values.reinit(cell, face);
          for (const unsigned int q : fe_face_values.quadrature_point_indices())
            {
              boundary_conditions.traction->vector_value(
                fe_face_values.quadrature_point(q), value);
              Tensor<1, dim> t;
              for (unsigned int d = 0; d < dim; ++d)
                t[d] = value[d];
              for (unsigned int i = 0; i < n; ++i)
                cell_load(i) += fe_face_values[displacement].value(i, q) * t *
                                fe_face_values.JxW(q);
            }
        }
  }



  template <int dim>
  void
  Block<dim>::distribute_cell_load(const cell_iterator  &cell,
                                   const Vector<double> &cell_load,
                                   FEValues<dim>        &state_values)
  {
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dof_indices(n);
    cell->get_dof_indices(dof_indices);
    for (unsigned int i = 0; i < n; ++i)
      external_load(dof_indices[i]) += cell_load(i);

    // The cell matrix is needed only where a prescribed displacement
    // enters: it moves -K u_D to the right-hand side.
    bool has_constrained_dof = false;
    for (const auto i : dof_indices)
      if (physical_constraints.is_inhomogeneously_constrained(i))
        has_constrained_dof = true;
    if (has_constrained_dof)
      {
        FullMatrix<double> matrix(n, n);
        state_values.reinit(cell);
        cell_matrix(state_values, matrix, cell->active_cell_index());
        physical_constraints.distribute_local_to_global(cell_load,
                                                        dof_indices,
                                                        physical_load,
                                                        matrix);
      }
    else
      physical_constraints.distribute_local_to_global(cell_load,
                                                      dof_indices,
                                                      physical_load);
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
  Block<dim>::add_external_point_forces(
    const std::vector<types::global_dof_index> &dofs,
    const std::vector<double>                  &forces)
  {
    AssertDimension(dofs.size(), forces.size());
    Vector<double> local(forces.begin(), forces.end());
    // At a prescribed DoF the support takes the force: no lifting term.
    physical_constraints.distribute_local_to_global(local, dofs, physical_load);
    add_point_forces(dofs, forces);
  }



  template <int dim>
  void
  Block<dim>::solve(const std::vector<double> &alpha)
  {
    if (!local)
      return; // share_solution() brings it
    AssertDimension(solution.size(), load.size());
    solve_stiffness(solution.data(), load.data(), 1);
    constraints.distribute(solution);
    AssertThrow(alpha.empty() || alpha.size() == floating.modes().size(),
                ExcInternalError());
    for (unsigned int i = 0; i < alpha.size(); ++i)
      solution.add(alpha[i], floating.modes()[i]);
  }



  template <int dim>
  void
  Block<dim>::share_solution()
  {
    Parallel::broadcast(communicator, owner, solution);
  }



  template <int dim>
  void
  Block<dim>::set_solution(Vector<double> &&displacement)
  {
    AssertDimension(displacement.size(), dof_handler.n_dofs());
    solution = std::move(displacement);
  }



  template <int dim>
  FullMatrix<double>
  Block<dim>::flexibility(
    const std::vector<types::global_dof_index> &dofs) const
  {
    Assert(local, ExcMessage("The flexibility of another rank's block."));
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
                                 !plastic.uses_newton());
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
        solve_stiffness(x.data(), rhs.data(), count);
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
  bool
  Block<dim>::has_fixed_stiffness() const
  {
    return !plastic.uses_newton();
  }



  template <int dim>
  void
  Block<dim>::set_flexibility_on_demand()
  {
    Assert(has_fixed_stiffness(),
           ExcMessage("A flexibility on demand needs a fixed stiffness."));
    if (local && !mumps_solver)
      {
        direct_solver.clear();
        mumps_solver = std::make_shared<MumpsSolver>();
      }
  }



  template <int dim>
  std::unique_ptr<ContactFlexibility>
  Block<dim>::on_demand_flexibility(
    const std::vector<types::global_dof_index> &dofs)
  {
    set_flexibility_on_demand();
    if (local && mumps_solver->size() == 0)
      factorize();
    return std::make_unique<ContactFlexibility>(mumps_solver,
                                                homogeneous_constraints,
                                                dofs);
  }



  template <int dim>
  void
  Block<dim>::solve_stiffness(double            *x,
                              const double      *b,
                              const unsigned int n_vectors) const
  {
    if (mumps_solver)
      mumps_solver->solve(x, b, n_vectors);
    else
      direct_solver.solve(x, b, n_vectors);
  }



  template <int dim>
  void
  Block<dim>::share_load_resultant()
  {
    shared_load_resultant.assign(floating.modes().size(), 0.);
    if (local)
      shared_load_resultant = external_load_resultant();
    if (!shared_load_resultant.empty())
      Parallel::broadcast(communicator,
                          owner,
                          shared_load_resultant.data(),
                          shared_load_resultant.size());
  }



  template <int dim>
  std::vector<double>
  Block<dim>::external_load_resultant() const
  {
    if (!local)
      {
        AssertDimension(shared_load_resultant.size(), floating.modes().size());
        return shared_load_resultant;
      }
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
    if (plastic.enabled())
      sigma -= plastic.plastic_stress(cell, q);
    return sigma;
  }



  template <int dim>
  types::global_dof_index
  Block<dim>::n_dofs() const
  {
    return dof_handler.n_dofs();
  }



  template <int dim>
  types::material_id
  Block<dim>::get_id() const
  {
    return id;
  }



  template <int dim>
  const Triangulation<dim> &
  Block<dim>::get_triangulation() const
  {
    return triangulation;
  }



  template <int dim>
  const Material &
  Block<dim>::get_material() const
  {
    return material;
  }



  template <int dim>
  const FESystem<dim> &
  Block<dim>::get_fe() const
  {
    return fe;
  }



  template <int dim>
  const MappingQ<dim> &
  Block<dim>::get_mapping() const
  {
    return mapping;
  }



  template <int dim>
  const DoFHandler<dim> &
  Block<dim>::get_dof_handler() const
  {
    return dof_handler;
  }



  template <int dim>
  const Vector<double> &
  Block<dim>::get_solution() const
  {
    return solution;
  }



  template class Block<2>;
  template class Block<3>;
  template void
  Block<2>::assemble_matrix(const AffineConstraints<double> &,
                            TrilinosWrappers::SparseMatrix &) const;
  template void
  Block<2>::assemble_matrix(const AffineConstraints<double> &,
                            SparseMatrix<double> &) const;
  template void
  Block<3>::assemble_matrix(const AffineConstraints<double> &,
                            TrilinosWrappers::SparseMatrix &) const;
  template void
  Block<3>::assemble_matrix(const AffineConstraints<double> &,
                            SparseMatrix<double> &) const;
} // namespace mbfem

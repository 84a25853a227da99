#include <mbfem/base/exceptions.h>
#include <mbfem/contact/contact_solver.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace mbfem
{
  std::string
  to_string(const ContactState state)
  {
    switch (state)
      {
        case ContactState::stick:
          return "stick";
        case ContactState::slip:
          return "slip";
        default:
          return "open";
      }
  }



  std::string
  to_string(const ContactFormulation formulation)
  {
    return formulation == ContactFormulation::condensed ? "condensed" :
                                                          "monolithic";
  }



  template <int dim>
  ContactSolver<dim>::ContactSolver(
    std::vector<ContactPair<dim>>        pairs,
    const unsigned int                   max_iterations,
    const ContactFormulation             formulation,
    const std::string                   &solver_package,
    const ContactParameters::StateSystem state_system)
    : contact_pairs(std::move(pairs))
    , max_iterations(max_iterations)
    , n_pairs(contact_pairs.size())
    , contact_formulation(formulation)
    , state_system(state_system)
  {
    if (formulation == ContactFormulation::monolithic)
      monolithic = std::make_unique<MonolithicSystem<dim>>(solver_package);
    committed.state.resize(n_pairs);
    committed.broken.assign(n_pairs, false);
    committed.tensile_slip.assign(n_pairs, false);
    committed.slip_direction.assign(n_pairs, Tensor<1, dim>());
    committed.direction_stiffness.assign(n_pairs, 0.);
    for (unsigned int k = 0; k < n_pairs; ++k)
      committed.state[k] =
        (contact_pairs[k].initial_gap > 0. ? ContactState::open :
                                             ContactState::stick);
    committed_displacement.assign(n_pairs, Tensor<1, dim>());
    current              = committed;
    current_displacement = committed_displacement;
    initial              = committed;
    for (const auto &pair : contact_pairs)
      nominal_joints.push_back(pair.joint);
  }



  template <int dim>
  void
  ContactSolver<dim>::report_progress(std::ostream *out, const double seconds)
  {
    progress.out      = out;
    progress.interval = seconds;
  }



  template <int dim>
  void
  ContactSolver<dim>::start_progress(const unsigned int increment)
  {
    progress.start(increment);
  }



  template <int dim>
  std::string
  ContactSolver<dim>::count_states(const Trial &trial) const
  {
    std::array<unsigned int, 3> n = {{0, 0, 0}};
    for (const auto state : trial.state)
      ++n[static_cast<unsigned int>(state)];
    return "stick/slip/open " + std::to_string(n[0]) + "/" +
           std::to_string(n[1]) + "/" + std::to_string(n[2]);
  }



  void
  StateProgress::start(const unsigned int k)
  {
    increment = k;
    solves    = 0;
    clock.restart();
    next = interval;
  }



  void
  StateProgress::step(const std::string &method, const std::string &states)
  {
    ++solves;
    if (out == nullptr || clock.wall_time() < next)
      return;
    next = clock.wall_time() + interval;
    *out << "    ... increment " << increment << ": " << solves
         << " state solves in " << static_cast<int>(clock.wall_time()) << " s, "
         << method << ", now " << states << std::endl;
  }



  template <int dim>
  void
  ContactSolver<dim>::restart(const double strength_factor,
                              const bool   reduce_tension)
  {
    AssertThrow(strength_factor > 0., ExcInternalError());
    for (unsigned int k = 0; k < n_pairs; ++k)
      contact_pairs[k].joint =
        nominal_joints[k].reduced(strength_factor, reduce_tension);
    committed = initial;
    committed_displacement.assign(n_pairs, Tensor<1, dim>());
    committed_solution.reinit(0);
    current              = committed;
    current_displacement = committed_displacement;
    current_solution.reinit(0);
    method          = StateMethod::fast;
    fast_iterations = 0;
    path_switches   = 0;
  }



  template <int dim>
  ContactFormulation
  ContactSolver<dim>::formulation() const
  {
    return contact_formulation;
  }



  namespace
  {
    /**
     * H = S C S^T for a block: C its flexibility over its contact DoFs, S
     * the (sides x dim) x (contact DoFs) map of signed, weighted nodes
     * rotated into each side's pair frame (@p rows: per row of S, its
     * (DoF index, coefficient) entries). Two sparse-times-dense passes;
     * C is released after the first.
     */
    FullMatrix<double>
    project(
      FullMatrix<double>                                              &c,
      const std::vector<std::vector<std::pair<unsigned int, double>>> &rows)
    {
      const unsigned int m = c.m(), n = rows.size();
      // T = C S^T (m x n), then H = S T, both along contiguous rows.
      FullMatrix<double> t(m, n);
      for (unsigned int q = 0; q < m; ++q)
        for (unsigned int r = 0; r < n; ++r)
          {
            double value = 0.;
            for (const auto &[p, weight] : rows[r])
              value += weight * c(q, p);
            t(q, r) = value;
          }
      c.reinit(0, 0);
      FullMatrix<double> h(n, n);
      for (unsigned int r = 0; r < n; ++r)
        for (const auto &[q, weight] : rows[r])
          for (unsigned int s = 0; s < n; ++s)
            h(r, s) += weight * t(q, s);
      return h;
    }
  } // namespace



  template <int dim>
  void
  ContactSolver<dim>::setup(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks)
  {
    const unsigned int n_r = n_pairs * dim;

    number_floating_modes(blocks);

    // Per block: H_b (condensed) and the block's part of P.
    block_flexibility.clear();
    pair_sides.assign(n_pairs, {});
    condensed_system = CondensedSystem();
    FullMatrix<double> p_global(n_r, n_alpha_total);
    for (unsigned int b = 0; b < blocks.size(); ++b)
      add_block_flexibility(*blocks[b], b, p_global);

    rotate_coupling(p_global);

    if (monolithic)
      {
        monolithic->setup(blocks, contact_pairs);
        held = monolithic->held();
        return;
      }

    find_held_directions();
  }



  template <int dim>
  void
  ContactSolver<dim>::number_floating_modes(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks)
  {
    alpha_offset.assign(blocks.size(), 0);
    n_alpha.assign(blocks.size(), 0);
    n_alpha_total = 0;
    block_names.clear();
    mode_coefficients.clear();
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        alpha_offset[b] = n_alpha_total;
        n_alpha[b]      = blocks[b]->floating_modes().size();
        n_alpha_total += n_alpha[b];
        block_names.push_back(blocks[b]->name());
        mode_coefficients.push_back(blocks[b]->free_rigid_body_modes());
      }
  }



  template <int dim>
  void
  ContactSolver<dim>::add_block_flexibility(Block<dim>         &block,
                                            const unsigned int  b,
                                            FullMatrix<double> &p_global)
  {
    // The pair sides on this block: (pair, sign); b gets +r, a gets -r.
    std::vector<std::pair<unsigned int, double>>    sides;
    std::vector<types::global_dof_index>            dofs;
    std::map<types::global_dof_index, unsigned int> index_of;
    for (unsigned int k = 0; k < n_pairs; ++k)
      for (const int sign : {-1, 1})
        {
          const auto &side = contact_pairs[k].side(sign);
          if (side.block != b)
            continue;
          sides.emplace_back(k, sign);
          for (const auto &node : side.nodes)
            for (const auto dof : node.dofs)
              if (index_of.emplace(dof, dofs.size()).second)
                dofs.push_back(dof);
        }
    if (dofs.empty())
      return;

    const auto &modes = block.floating_modes();
    // A side's displacement is sum_i w_i u(node_i), in its pair's
    // frame: the rows of S (see project()) and P take the same weights.
    std::vector<std::vector<std::pair<unsigned int, double>>> rows(
      sides.size() * dim);
    BlockFlexibility flexibility;
    for (unsigned int s = 0; s < sides.size(); ++s)
      {
        const auto &[k, sign]       = sides[s];
        const Tensor<2, dim> &frame = contact_pairs[k].frame;
        flexibility.pairs.push_back(k);
        pair_sides[k].emplace_back(block_flexibility.size(), s);
        for (const auto &node : contact_pairs[k].side(sign).nodes)
          {
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int c = 0; c < dim; ++c)
                if (frame[i][c] != 0.)
                  rows[s * dim + i].emplace_back(index_of[node.dofs[c]],
                                                 sign * node.weight *
                                                   frame[i][c]);
            for (unsigned int a = 0; a < modes.size(); ++a)
              for (unsigned int c = 0; c < dim; ++c)
                p_global(k * dim + c, alpha_offset[b] + a) +=
                  sign * node.weight * modes[a](node.dofs[c]);
          }
      }
    // The monolithic system needs no flexibility; the free modes at
    // the pairs (P) it still needs to name a block it cannot hold.
    if (!monolithic)
      {
        FullMatrix<double> c_block = block.flexibility(dofs);
        flexibility.matrix         = project(c_block, rows);
      }
    block_flexibility.push_back(std::move(flexibility));
  }



  template <int dim>
  void
  ContactSolver<dim>::rotate_coupling(const FullMatrix<double> &p_global)
  {
    const unsigned int n_r = n_pairs * dim;
    // P into the pairs' frames.
    coupling.reinit(n_r, n_alpha_total);
    for (unsigned int k = 0; k < n_pairs; ++k)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int a = 0; a < n_alpha_total; ++a)
          {
            double value = 0.;
            for (unsigned int c = 0; c < dim; ++c)
              value += contact_pairs[k].frame[i][c] * p_global(k * dim + c, a);
            coupling(k * dim + i, a) = value;
          }
  }



  template <int dim>
  void
  ContactSolver<dim>::find_held_directions()
  {
    const unsigned int  n_r = n_pairs * dim;
    std::vector<double> diagonal(n_r);
    for (unsigned int i = 0; i < n_r; ++i)
      diagonal[i] = flexibility_entry(i, i);
    const double trace = std::accumulate(diagonal.begin(), diagonal.end(), 0.);
    flexibility_scale  = (n_r > 0 && trace > 0. ? trace / n_r : 1.);

    // A direction in which neither node can move (both on supports) carries
    // no contact force: the supports take it.
    const double max_diagonal =
      n_r > 0 ? *std::max_element(diagonal.begin(), diagonal.end()) : 0.;
    held.assign(n_pairs, std::array<bool, dim>());
    for (unsigned int k = 0; k < n_pairs; ++k)
      for (unsigned int d = 0; d < dim; ++d)
        {
          double mobility = 0.;
          for (unsigned int a = 0; a < n_alpha_total; ++a)
            mobility = std::max(mobility, std::abs(coupling(k * dim + d, a)));
          held[k][d] =
            diagonal[k * dim + d] < 1e-12 * max_diagonal && mobility < 1e-12;
        }
  }



  template <int dim>
  double
  ContactSolver<dim>::flexibility_entry(const unsigned int row,
                                        const unsigned int column) const
  {
    const unsigned int k = row / dim, l = column / dim;
    double             value = 0.;
    for (const auto &[b, s] : pair_sides[k])
      for (const auto &[c, t] : pair_sides[l])
        if (b == c)
          value += block_flexibility[b].matrix(s * dim + row % dim,
                                               t * dim + column % dim);
    return value;
  }



  template <int dim>
  std::vector<PairEquation<dim>>
  ContactSolver<dim>::pair_equations(const Trial &trial) const
  {
    std::vector<PairEquation<dim>> equations(n_pairs * dim);
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const auto        &pair  = contact_pairs[k];
        const ContactState state = trial.state[k];
        // Slip: |r_T| = c A + mu r_N, as the coefficients of r_N and 1.
        const double mu =
          trial.tensile_slip[k] ? 0. : pair.joint.friction_coefficient;
        const double strength_0 =
          pair.joint.shear_strength(0., pair.area, trial.broken[k]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            PairEquation<dim> &eq = equations[k * dim + d];
            if (held[k][d] || state == ContactState::open)
              eq.force_coefficients[d] = 1.; // no force
            else if (d == 0 || state == ContactState::stick)
              {
                // Closed: gap zero (normal); stuck: no tangential increment.
                eq.displacement_coefficients[d] = 1.;
                eq.value =
                  (d == 0 ? -pair.initial_gap : committed_displacement[k][d]);
              }
            else
              {
                // Slip: r_T = -(c A + mu r_N) s. In 3D s = v/|v|, v the
                // slip increment, linearised about the last iterate (Newton
                // on the direction):
                //   r_T + mu s r_N + beta (I - s s^T) v = -c A s,
                // which is the slip law itself once (I - s s^T) v = 0.
                const double s           = trial.slip_direction[k][d];
                eq.force_coefficients[d] = 1.;
                eq.force_coefficients[0] += mu * s;
                eq.value          = -strength_0 * s;
                const double beta = trial.direction_stiffness[k];
                for (unsigned int e = 1; e < dim && beta > 0.; ++e)
                  {
                    const double m =
                      (d == e ? 1. : 0.) - s * trial.slip_direction[k][e];
                    eq.displacement_coefficients[e] = beta * m;
                    eq.value += beta * m * committed_displacement[k][e];
                  }
              }
          }
      }
    return equations;
  }



  template <int dim>
  bool
  ContactSolver<dim>::solve_trial(const Trial    &trial,
                                  Vector<double> &solution,
                                  Vector<double> &displacement)
  {
    const std::vector<PairEquation<dim>> equations = pair_equations(trial);
    progress.step(to_string(method), count_states(trial));
    if (monolithic)
      {
        // A block the states cannot hold makes the whole system singular;
        // say so before a sparse LU returns noise.
        if (!unheld_blocks(trial).empty())
          return false;
        return monolithic->solve(equations, solution, displacement);
      }
    if (!solve_condensed(equations, solution))
      return false;
    displacement = relative_displacement(solution);
    return true;
  }



  template <int dim>
  bool
  ContactSolver<dim>::solve_condensed(
    const std::vector<PairEquation<dim>> &equations,
    Vector<double>                       &solution) const
  {
    const unsigned int n_r = n_pairs * dim;
    // Unknowns: rho * scale (a displacement) and alpha, so that all entries
    // are of unit order whatever the units of the model; the singularity
    // test below then means the same for a rubber and a rock model. A row
    // with force terms is multiplied by scale.
    const double scale = flexibility_scale;

    // A row that says rho_i = 0 (open pairs, held directions) removes its
    // unknown: only the directions of the other pairs and the floating
    // modes remain, some 250 of 4131 unknowns on the 1377-pair model.
    std::vector<double>       key;
    std::vector<unsigned int> unknowns;
    key.reserve(n_r * (2 * dim + 1));
    for (unsigned int row = 0; row < n_r; ++row)
      {
        const PairEquation<dim> &eq   = equations[row];
        bool                     zero = eq.value == 0.;
        for (unsigned int e = 0; e < dim; ++e)
          {
            key.push_back(eq.force_coefficients[e]);
            key.push_back(eq.displacement_coefficients[e]);
            zero = zero && eq.displacement_coefficients[e] == 0. &&
                   (eq.force_coefficients[e] == 0.) == (e != row % dim);
          }
        key.push_back(zero ? 1. : 0.);
        if (!zero)
          unknowns.push_back(row);
      }
    const unsigned int n_rho = unknowns.size();
    const unsigned int n     = n_rho + n_alpha_total;
    if (n == 0)
      {
        // Every pair open and no floating block: all forces are zero (LAPACK
        // refuses a 0 x 0 factorisation).
        solution.reinit(n_r);
        return true;
      }

    CondensedSystem &system = condensed_system;
    if (system.coefficients != key || system.size != n)
      {
        system.coefficients = key;
        system.unknowns     = unknowns;
        assemble_condensed(equations, system);
      }
    if (!system.regular)
      return false;

    Vector<double> rhs(n);
    for (unsigned int i = 0; i < n_rho; ++i)
      {
        const unsigned int       row   = unknowns[i];
        const PairEquation<dim> &eq    = equations[row];
        double                   value = eq.value;
        for (unsigned int e = 0; e < dim; ++e)
          value -= eq.displacement_coefficients[e] *
                   external_displacement((row / dim) * dim + e);
        rhs(i) = (eq.has_force_terms() ? scale : 1.) * value;
      }
    for (unsigned int a = 0; a < n_alpha_total; ++a)
      rhs(n_rho + a) = -external_resultant[a] * scale;
    system.solve(rhs);

    solution.reinit(n_r + n_alpha_total);
    for (unsigned int i = 0; i < n_rho; ++i)
      solution(unknowns[i]) = rhs(i) / scale;
    for (unsigned int a = 0; a < n_alpha_total; ++a)
      solution(n_r + a) = rhs(n_rho + a);
    return true;
  }



  template <int dim>
  void
  ContactSolver<dim>::assemble_condensed(
    const std::vector<PairEquation<dim>> &equations,
    CondensedSystem                      &system) const
  {
    const unsigned int               n_r      = n_pairs * dim;
    const std::vector<unsigned int> &unknowns = system.unknowns;
    const unsigned int               n_rho    = unknowns.size();
    const unsigned int               n        = n_rho + n_alpha_total;
    const double                     scale    = flexibility_scale;

    // Not regular until factorised: a throw below must not leave the
    // cache (keyed already) saying otherwise.
    system.regular = false;
    system.size    = n;
    system.sparse_lu.reset();
    if (use_sparse(unknowns))
      {
        system.matrix.reinit(0, 0);
        assemble_condensed_sparse(equations, system);
        return;
      }
    std::vector<int> column_of(n_r, -1);
    for (unsigned int i = 0; i < n_rho; ++i)
      column_of[unknowns[i]] = i;
    LAPACKFullMatrix<double> &matrix = system.matrix;
    matrix.reinit(n, n);
    for (unsigned int i = 0; i < n_rho; ++i)
      {
        const unsigned int       row       = unknowns[i];
        const unsigned int       k         = row / dim;
        const PairEquation<dim> &eq        = equations[row];
        const double             row_scale = eq.has_force_terms() ? scale : 1.;
        // d_e = C_hat rho + P_hat alpha + Delta_F, with rho = x / scale.
        for (unsigned int e = 0; e < dim; ++e)
          {
            const double a = eq.displacement_coefficients[e];
            if (a != 0.)
              {
                const unsigned int source = k * dim + e;
                for (unsigned int j = 0; j < n_rho; ++j)
                  matrix(i, j) += row_scale * a *
                                  flexibility_entry(source, unknowns[j]) /
                                  scale;
                for (unsigned int b = 0; b < n_alpha_total; ++b)
                  matrix(i, n_rho + b) += row_scale * a * coupling(source, b);
              }
            if (eq.force_coefficients[e] != 0. && column_of[k * dim + e] >= 0)
              matrix(i, column_of[k * dim + e]) += eq.force_coefficients[e];
          }
      }
    // Equilibrium of the floating blocks: P^T r = -F_e.
    for (unsigned int a = 0; a < n_alpha_total; ++a)
      for (unsigned int j = 0; j < n_rho; ++j)
        matrix(n_rho + a, j) = coupling(unknowns[j], a);

    const double norm = matrix.l1_norm();
    try
      {
        matrix.compute_lu_factorization();
      }
    catch (const LACExceptions::ExcSingular &)
      {
        return; // an exactly zero pivot
      }
    estimate_condition(system, norm);
  }



  template <int dim>
  void
  ContactSolver<dim>::estimate_condition(CondensedSystem &system,
                                         const double     norm) const
  {
    // Condition estimate ||A||_1 ||A^{-1}||_1 from two pseudo-random
    // right-hand sides (LAPACKFullMatrix's own estimate is for Cholesky).
    const unsigned int n            = system.size;
    double             inverse_norm = 0.;
    for (unsigned int trial = 0; trial < 2; ++trial)
      {
        Vector<double> probe(n);
        for (unsigned int i = 0; i < n; ++i)
          probe(i) = std::sin(1.3 + 0.7 * i * (trial + 1)) + 0.1;
        const double probe_norm = probe.l1_norm();
        system.solve(probe);
        const double ratio = probe.l1_norm() / probe_norm;
        // Overflow past a tiny pivot (std::max would drop a NaN).
        if (!std::isfinite(ratio))
          return;
        inverse_norm = std::max(inverse_norm, ratio);
      }
    system.regular = std::isfinite(norm) && norm * inverse_norm < 1e12;
  }



  template <int dim>
  void
  ContactSolver<dim>::CondensedSystem::solve(Vector<double> &x) const
  {
    if (sparse_lu)
      sparse_lu->solve(x);
    else
      matrix.solve(x);
  }



  template <int dim>
  bool
  ContactSolver<dim>::use_sparse(
    const std::vector<unsigned int> &unknowns) const
  {
    if (state_system != ContactParameters::StateSystem::automatic)
      return state_system == ContactParameters::StateSystem::sparse;
    const double n = unknowns.size() + n_alpha_total;
    if (n < 1000)
      return false;
    // At most how many entries a row of pair k can have: the pair
    // directions of every side on the blocks k touches, and twice their
    // modes (P_hat's columns and, transposed, the equilibrium rows).
    double entries = 0.;
    for (const unsigned int row : unknowns)
      for (const auto &[b, s] : pair_sides[row / dim])
        entries += dim * block_flexibility[b].pairs.size() + dim * (dim + 1);
    return entries <= 0.1 * n * n;
  }



  template <int dim>
  void
  ContactSolver<dim>::assemble_condensed_sparse(
    const std::vector<PairEquation<dim>> &equations,
    CondensedSystem                      &system) const
  {
    const std::vector<unsigned int> &unknowns = system.unknowns;
    const unsigned int               n_rho    = unknowns.size();
    const unsigned int               n        = system.size;
    const double                     scale    = flexibility_scale;
    std::vector<int>                 column_of(n_pairs * dim, -1);
    for (unsigned int i = 0; i < n_rho; ++i)
      column_of[unknowns[i]] = i;

    // The rows of assemble_condensed(), with C_hat's entries only where
    // two pairs share a block (H_b of that block), each gathered through
    // entry_of (a row's entry of each column, -1 for none) in the order
    // the terms come, so that every sum is that of the dense assembly.
    std::vector<SparseRow> rows(n);
    std::vector<int>       entry_of(n, -1);
    const auto             add =
      [&](SparseRow &row, const unsigned int column, const double value) {
        if (entry_of[column] < 0)
          {
            entry_of[column] = row.size();
            row.emplace_back(column, 0.);
          }
        row[entry_of[column]].second += value;
      };
    // P_hat's non-zero entries in the unknowns' rows.
    std::vector<SparseRow> coupling_of(n_rho);
    for (unsigned int j = 0; j < n_rho; ++j)
      for (unsigned int a = 0; a < n_alpha_total; ++a)
        if (coupling(unknowns[j], a) != 0.)
          coupling_of[j].emplace_back(a, coupling(unknowns[j], a));
    for (unsigned int i = 0; i < n_rho; ++i)
      {
        const unsigned int       row       = unknowns[i];
        const unsigned int       k         = row / dim;
        const PairEquation<dim> &eq        = equations[row];
        const double             row_scale = eq.has_force_terms() ? scale : 1.;
        for (unsigned int e = 0; e < dim; ++e)
          {
            const double a = eq.displacement_coefficients[e];
            if (a != 0.)
              {
                add_flexibility_row(k,
                                    e,
                                    row_scale * a,
                                    column_of,
                                    [&](unsigned int c, double v) {
                                      add(rows[i], c, v);
                                    });
                for (unsigned int b = 0; b < n_alpha_total; ++b)
                  if (coupling(k * dim + e, b) != 0.)
                    add(rows[i],
                        n_rho + b,
                        row_scale * a * coupling(k * dim + e, b));
              }
            if (eq.force_coefficients[e] != 0. && column_of[k * dim + e] >= 0)
              add(rows[i], column_of[k * dim + e], eq.force_coefficients[e]);
          }
        for (const auto &[column, value] : rows[i])
          entry_of[column] = -1;
      }
    // Equilibrium of the floating blocks: P^T r = -F_e.
    for (unsigned int j = 0; j < n_rho; ++j)
      for (const auto &[a, value] : coupling_of[j])
        rows[n_rho + a].emplace_back(j, value);

    DynamicSparsityPattern               dsp(n, n);
    std::vector<types::global_dof_index> columns;
    for (unsigned int i = 0; i < n; ++i)
      {
        columns.clear();
        for (const auto &[j, value] : rows[i])
          columns.push_back(j);
        dsp.add_entries(i, columns.begin(), columns.end());
      }
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> matrix(pattern);
    for (unsigned int i = 0; i < n; ++i)
      for (const auto &[j, value] : rows[i])
        matrix.set(i, j, value);

    system.sparse_lu = std::make_unique<SparseDirectUMFPACK>();
    try
      {
        system.sparse_lu->factorize(matrix);
      }
    catch (const SparseDirectUMFPACK::ExcUMFPACKError &)
      {
        // A zero pivot (UMFPACK's warning status 1, thrown by deal.II);
        // running out of memory and the like pass on.
        system.sparse_lu.reset();
        return;
      }
    estimate_condition(system, matrix.l1_norm());
  }



  template <int dim>
  void
  ContactSolver<dim>::add_flexibility_row(
    const unsigned int                                           k,
    const unsigned int                                           e,
    const double                                                 factor,
    const std::vector<int>                                      &column_of,
    const std::function<void(const unsigned int, const double)> &add) const
  {
    // (C_hat rho)_(k, e) / scale = sum over the blocks b of pair k's
    // sides s, and every side t on b: H_b(s e, t f) x_(t f) / scale.
    for (const auto &[b, s] : pair_sides[k])
      {
        const BlockFlexibility &flexibility = block_flexibility[b];
        for (unsigned int t = 0; t < flexibility.pairs.size(); ++t)
          for (unsigned int f = 0; f < dim; ++f)
            {
              const int column = column_of[flexibility.pairs[t] * dim + f];
              if (column >= 0)
                add(column,
                    factor * flexibility.matrix(s * dim + e, t * dim + f) /
                      flexibility_scale);
            }
      }
  }



  template <int dim>
  typename ContactSolver<dim>::Trial
  ContactSolver<dim>::check(const Trial          &trial,
                            const Vector<double> &solution,
                            const Vector<double> &displacement,
                            std::vector<double>  &violation,
                            double               &direction_change) const
  {
    const CheckScales scales = check_scales(solution, displacement);
    Trial             next   = trial;
    violation.assign(n_pairs, 0.);
    direction_change = 0.;
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        if (std::all_of(held[k].begin(), held[k].end(), [](bool h) {
              return h;
            }))
          continue;
        if (contact_pairs[k].tied)
          continue; // stays stuck
        switch (trial.state[k])
          {
            case ContactState::stick:
              check_stick(k, trial, solution, scales, next, violation[k]);
              break;
            case ContactState::slip:
              check_slip(k,
                         trial,
                         solution,
                         displacement,
                         scales,
                         next,
                         violation[k],
                         direction_change);
              break;
            case ContactState::open:
              check_open(k, displacement, scales, next, violation[k]);
              break;
          }
      }
    return next;
  }



  template <int dim>
  typename ContactSolver<dim>::CheckScales
  ContactSolver<dim>::check_scales(const Vector<double> &solution,
                                   const Vector<double> &displacement) const
  {
    const unsigned int n_r = n_pairs * dim;

    // Scales of the tolerances: what both formulations know (not Delta_F,
    // which only the condensed one computes), so that they decide alike.
    double force_scale = 1e-300, displacement_scale = 1e-300;
    for (unsigned int i = 0; i < n_r; ++i)
      {
        force_scale = std::max(force_scale, std::abs(solution(i)));
        displacement_scale =
          std::max(displacement_scale, std::abs(displacement(i)));
      }
    for (const double f : external_resultant)
      force_scale = std::max(force_scale, std::abs(f));
    for (const auto &pair : contact_pairs)
      displacement_scale = std::max(displacement_scale, pair.initial_gap);
    CheckScales scales;
    scales.force                  = force_scale;
    scales.displacement           = displacement_scale;
    scales.force_tolerance        = 1e-9 * force_scale;
    scales.displacement_tolerance = 1e-9 * displacement_scale;
    return scales;
  }



  template <int dim>
  void
  ContactSolver<dim>::break_open(const unsigned int k,
                                 const Trial       &trial,
                                 const double       r_n,
                                 const double       tension_limit,
                                 const CheckScales &scales,
                                 Trial             &next,
                                 double            &violation) const
  {
    const auto &pair = contact_pairs[k];
    next.state[k]    = ContactState::open;
    if (!trial.broken[k] && pair.joint.has_strength())
      next.broken[k] = true;
    next.tensile_slip[k] = false;
    violation            = (-tension_limit - r_n) / scales.force;
  }



  template <int dim>
  void
  ContactSolver<dim>::check_stick(const unsigned int    k,
                                  const Trial          &trial,
                                  const Vector<double> &solution,
                                  const CheckScales    &scales,
                                  Trial                &next,
                                  double               &violation) const
  {
    const auto  &pair = contact_pairs[k];
    const double tension_limit =
      pair.joint.tensile_limit(pair.area, trial.broken[k]);
    const double   r_n = solution(k * dim);
    Tensor<1, dim> r_t;
    for (unsigned int d = 1; d < dim; ++d)
      r_t[d] = solution(k * dim + d);
    const double limit =
      pair.joint.shear_strength(r_n, pair.area, trial.broken[k]);
    if (r_n < -tension_limit - scales.force_tolerance)
      break_open(k, trial, r_n, tension_limit, scales, next, violation);
    else if (r_t.norm() > limit + scales.force_tolerance)
      {
        next.state[k]               = ContactState::slip;
        next.slip_direction[k]      = -r_t / r_t.norm();
        next.direction_stiffness[k] = 0.;
        next.tensile_slip[k]        = r_n < 0.;
        violation                   = (r_t.norm() - limit) / scales.force;
      }
  }



  template <int dim>
  void
  ContactSolver<dim>::check_slip(const unsigned int    k,
                                 const Trial          &trial,
                                 const Vector<double> &solution,
                                 const Vector<double> &displacement,
                                 const CheckScales    &scales,
                                 Trial                &next,
                                 double               &violation,
                                 double               &direction_change) const
  {
    const auto  &pair = contact_pairs[k];
    const double tension_limit =
      pair.joint.tensile_limit(pair.area, trial.broken[k]);
    const double   r_n = solution(k * dim);
    Tensor<1, dim> d_t, increment_t;
    for (unsigned int d = 1; d < dim; ++d)
      {
        d_t[d]         = displacement(k * dim + d);
        increment_t[d] = d_t[d] - committed_displacement[k][d];
      }
    const double along = increment_t * trial.slip_direction[k];
    // A slip increment against the assumed direction (2D: a reversed sign;
    // 3D: more than 90 degrees off) or none at all means the pair sticks.
    const bool sticks =
      along < -scales.displacement_tolerance ||
      (dim == 3 && increment_t.norm() < scales.displacement_tolerance);
    if (r_n < -tension_limit - scales.force_tolerance)
      break_open(k, trial, r_n, tension_limit, scales, next, violation);
    else if (sticks)
      {
        next.state[k] = ContactState::stick;
        violation     = std::abs(along) / scales.displacement;
      }
    else
      {
        if (dim == 3)
          {
            // Next Newton step about this slip increment.
            const Tensor<1, dim> s = increment_t / increment_t.norm();
            direction_change =
              std::max(direction_change, (s - trial.slip_direction[k]).norm());
            next.slip_direction[k] = s;
            next.direction_stiffness[k] =
              pair.joint.shear_strength(r_n,
                                        pair.area,
                                        trial.broken[k],
                                        trial.tensile_slip[k]) /
              increment_t.norm();
          }
        const bool tensile = r_n < -scales.force_tolerance;
        if (tensile != trial.tensile_slip[k])
          {
            next.tensile_slip[k] = tensile;
            violation            = std::abs(r_n) / scales.force;
          }
      }
  }



  template <int dim>
  void
  ContactSolver<dim>::check_open(const unsigned int    k,
                                 const Vector<double> &displacement,
                                 const CheckScales    &scales,
                                 Trial                &next,
                                 double               &violation) const
  {
    const double gap = contact_pairs[k].initial_gap + displacement(k * dim);
    if (gap < -scales.displacement_tolerance)
      {
        next.state[k] = ContactState::stick;
        violation     = -gap / scales.displacement;
      }
  }



  template <int dim>
  Vector<double>
  ContactSolver<dim>::relative_displacement(
    const Vector<double> &solution) const
  {
    const unsigned int n_r = n_pairs * dim;
    Vector<double>     d(external_displacement);
    for (unsigned int i = 0; i < n_r; ++i)
      for (unsigned int a = 0; a < n_alpha_total; ++a)
        d(i) += coupling(i, a) * solution(n_r + a);
    // C_hat rho block by block, over the sides whose force is not zero.
    for (const auto &flexibility : block_flexibility)
      {
        const unsigned int        n_sides = flexibility.pairs.size();
        std::vector<unsigned int> columns;
        std::vector<double>       forces;
        for (unsigned int t = 0; t < n_sides; ++t)
          for (unsigned int j = 0; j < dim; ++j)
            if (solution(flexibility.pairs[t] * dim + j) != 0.)
              {
                columns.push_back(t * dim + j);
                forces.push_back(solution(flexibility.pairs[t] * dim + j));
              }
        for (unsigned int s = 0; s < n_sides; ++s)
          for (unsigned int i = 0; i < dim; ++i)
            {
              double value = 0.;
              for (unsigned int c = 0; c < columns.size(); ++c)
                value +=
                  flexibility.matrix(s * dim + i, columns[c]) * forces[c];
              d(flexibility.pairs[s] * dim + i) += value;
            }
      }
    return d;
  }



  template <int dim>
  std::string
  ContactSolver<dim>::signature(const Trial &trial) const
  {
    std::string s(n_pairs, ' ');
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        // In 2D the slip sign is part of the state; in 3D the direction is
        // a continuous unknown, iterated separately.
        char c = (trial.state[k] == ContactState::stick ? 'k' :
                  trial.state[k] == ContactState::open  ? 'o' :
                  dim == 3                              ? 's' :
                  trial.slip_direction[k][1] > 0        ? '+' :
                                                          '-');
        if (trial.broken[k])
          c = static_cast<char>(std::toupper(c));
        if (trial.tensile_slip[k])
          c = 't';
        s[k] = c;
      }
    return s;
  }



  template <int dim>
  std::string
  ContactSolver<dim>::diagnose_singular(const Trial &trial) const
  {
    const std::string message = unheld_blocks(trial);
    if (!message.empty())
      return message;
    return "\n    The interface system is singular, and no floating "
           "block is to blame: check for pairs whose nodes are both "
           "fixed in some direction.";
  }



  template <int dim>
  std::string
  ContactSolver<dim>::unheld_blocks(const Trial &trial) const
  {
    std::ostringstream message;
    for (unsigned int b = 0; b < n_alpha.size(); ++b)
      {
        const unsigned int q = n_alpha[b];
        if (q == 0)
          continue;
        // The directions in which the block's pairs can push, given their
        // states; the block is held iff they span its q free modes.
        std::vector<std::vector<double>> columns;
        unsigned int                     counts[3] = {0, 0, 0};
        for (unsigned int k = 0; k < n_pairs; ++k)
          {
            bool touches = false;
            for (unsigned int a = 0; a < q; ++a)
              for (unsigned int d = 0; d < dim; ++d)
                if (std::abs(coupling(k * dim + d, alpha_offset[b] + a)) > 0.)
                  touches = true;
            if (!touches)
              continue;
            ++counts[static_cast<int>(trial.state[k])];
            if (trial.state[k] == ContactState::open)
              continue;
            const double mu = trial.tensile_slip[k] ?
                                0. :
                                contact_pairs[k].joint.friction_coefficient;
            for (unsigned int d = 0; d < dim; ++d)
              {
                if (held[k][d] ||
                    (trial.state[k] == ContactState::slip && d > 0))
                  continue;
                std::vector<double> column(q);
                for (unsigned int a = 0; a < q; ++a)
                  {
                    column[a] = coupling(k * dim + d, alpha_offset[b] + a);
                    if (trial.state[k] == ContactState::slip)
                      for (unsigned int e = 1; e < dim; ++e)
                        column[a] -= mu * trial.slip_direction[k][e] *
                                     coupling(k * dim + e, alpha_offset[b] + a);
                  }
                columns.push_back(column);
              }
          }
        LAPACKFullMatrix<double> gram(q, q);
        for (const auto &column : columns)
          for (unsigned int a = 0; a < q; ++a)
            for (unsigned int c = 0; c < q; ++c)
              gram(a, c) += column[a] * column[c];
        double largest = 1.;
        for (unsigned int a = 0; a < q; ++a)
          largest = std::max(largest, gram(a, a));
        Vector<double>     eigenvalues;
        FullMatrix<double> eigenvectors;
        gram.compute_eigenvalues_symmetric(
          -1., 1e-10 * largest, 1e-14, eigenvalues, eigenvectors);
        if (eigenvalues.size() == 0)
          continue;
        message << "\n    " << block_names[b]
                << " cannot be in equilibrium: its contact pairs (" << counts[0]
                << " stick, " << counts[1] << " slip, " << counts[2]
                << " open) cannot hold its rigid-body motion";
        for (unsigned int v = 0; v < eigenvalues.size(); ++v)
          {
            Vector<double> combination(mode_coefficients[b][0].size());
            for (unsigned int a = 0; a < q; ++a)
              combination.add(eigenvectors(a, v), mode_coefficients[b][a]);
            combination /= combination.linfty_norm();
            message << " [" << Block<dim>::describe_rigid_body_mode(combination)
                    << "]";
          }
        message << ": the loads exceed what friction and cohesion can carry, "
                   "or the block has lost contact.";
      }
    return message.str();
  }



  template <int dim>
  void
  ContactSolver<dim>::set_increment_data(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks)
  {
    // Data of this increment: Delta_F in the frames (condensed) or the
    // loads of the monolithic system, and F_e.
    external_displacement.reinit(n_pairs * dim);
    if (monolithic)
      monolithic->set_load(blocks);
    for (unsigned int k = 0; k < n_pairs && !monolithic; ++k)
      {
        const auto    &pair = contact_pairs[k];
        Tensor<1, dim> d;
        for (const int sign : {-1, 1})
          {
            const auto &side = pair.side(sign);
            for (const auto &node : side.nodes)
              for (unsigned int c = 0; c < dim; ++c)
                d[c] += sign * node.weight *
                        blocks[side.block]->get_solution()(node.dofs[c]);
          }
        for (unsigned int i = 0; i < dim; ++i)
          external_displacement(k * dim + i) = pair.frame[i] * d;
      }
    external_resultant.assign(n_alpha_total, 0.);
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        const auto resultant = blocks[b]->external_load_resultant();
        for (unsigned int a = 0; a < resultant.size(); ++a)
          external_resultant[alpha_offset[b] + a] = resultant[a];
      }
  }



  template <int dim>
  void
  ContactSolver<dim>::set_state_methods(const std::vector<StateMethod> &methods)
  {
    Assert(!methods.empty(), ExcInternalError());
    state_methods = methods;
  }



  template <int dim>
  unsigned int
  ContactSolver<dim>::solve_increment(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    const unsigned int                              increment,
    const bool                                      from_last_solve)
  {
    set_increment_data(blocks);

    // The methods in their order until one concludes (by default the fast
    // iteration, which concludes nearly every increment in a few solves,
    // then the load path, the semismooth Newton method and the load
    // continuation). The verdict where none does: "no equilibrium" if a
    // method met one (the last such), else the last failure of the fast
    // iteration or the load path, else the others'.
    // The monolithic formulation has the fast iteration only: the others
    // need C_hat and P_hat.
    const std::vector<StateMethod> methods =
      monolithic ? std::vector<StateMethod>{StateMethod::fast} : state_methods;
    method          = methods.front();
    fast_iterations = 0;
    path_switches   = 0;
    MethodOutcome verdict;
    bool          verdict_is_primary = false;
    for (const StateMethod m : methods)
      {
        method = m; // the one running, for the progress line
        const MethodOutcome outcome = run_method(m, increment, from_last_solve);
        if (m == StateMethod::fast)
          fast_iterations = outcome.iterations;
        if (outcome.converged)
          {
            path_switches = (m == StateMethod::fast ? 0 : outcome.iterations);
            return fast_iterations + path_switches;
          }
        const bool primary =
          m == StateMethod::fast || m == StateMethod::load_path;
        if (outcome.no_equilibrium ||
            (!verdict.no_equilibrium && (primary || !verdict_is_primary)))
          {
            verdict            = outcome;
            verdict_is_primary = verdict_is_primary || primary;
          }
      }
    AssertThrow(!verdict.no_equilibrium,
                Exceptions::ExcNoEquilibrium(verdict.failure));
    AssertThrow(false, Exceptions::ExcIncrementNotConverged(verdict.failure));
    return 0;
  }



  template <int dim>
  typename ContactSolver<dim>::MethodOutcome
  ContactSolver<dim>::run_method(const StateMethod  m,
                                 const unsigned int increment,
                                 const bool         from_last_solve)
  {
    MethodOutcome     outcome;
    const std::string head = "Load increment " + std::to_string(increment);
    if (m == StateMethod::fast)
      {
        // Its answer is refused where the states leave a mechanism (every
        // pair that could resist a rigid motion slips): such an equilibrium
        // exists only exactly at a limit, and in 3D the linearised slip
        // direction can make the system regular with an unbounded slip
        // instead.
        const auto fast =
          fast_iteration(from_last_solve ? current : committed, increment);
        outcome.iterations = fast.iterations;
        outcome.converged =
          fast.converged && (monolithic || mechanism(current).empty());
        outcome.no_equilibrium = fast.no_equilibrium;
        outcome.failure        = fast.failure;
        if (fast.converged && !outcome.converged)
          outcome.failure = head +
                            ": the fast iteration's states leave a "
                            "mechanism:" +
                            mechanism(current);
        return outcome;
      }
    if (m == StateMethod::load_path)
      return run_load_path(increment);

    // The semismooth Newton method and the load continuation: where they
    // fail, the states stay as the methods before them left them. The
    // continuation scales the increment's load from the path's start (set
    // again, as the same, if the path ran).
    set_path_start();
    set_load_fraction(1.);
    const Trial                       trial        = current;
    const Vector<double>              solution     = current_solution;
    const std::vector<Tensor<1, dim>> displacement = current_displacement;
    if (m == StateMethod::semismooth_newton)
      {
        outcome.converged = semismooth_newton(increment, outcome.iterations);
        outcome.failure   = head + ": the semismooth Newton method did not "
                                   "converge.";
      }
    else
      {
        outcome.converged = load_continuation(increment, outcome.iterations);
        outcome.failure   = head + ": the load continuation did not "
                                   "conclude.";
      }
    if (!outcome.converged)
      {
        current              = trial;
        current_solution     = solution;
        current_displacement = displacement;
      }
    return outcome;
  }



  template <int dim>
  typename ContactSolver<dim>::MethodOutcome
  ContactSolver<dim>::run_load_path(const unsigned int increment)
  {
    // The path did not conclude where it throws: in 3D it can pivot in a
    // cycle at one load, from zero load every event is at s = 0+, or it
    // stops at a mechanism (below a limit it can take a branch that ends
    // there, doc/state_iteration.md). It may stop part way: the next
    // method starts from the increment's full load.
    MethodOutcome outcome;
    const auto    text_of = [](const ExceptionBase &e) {
      std::string text = message_of(e);
      return text.substr(0, text.find_last_not_of(" \n") + 1);
    };
    path_switches = 0;
    try
      {
        outcome.iterations = load_path(increment);
        outcome.converged  = true;
      }
    catch (const Exceptions::ExcIncrementNotConverged &e)
      {
        outcome.iterations = path_switches;
        outcome.failure    = text_of(e);
      }
    catch (const Exceptions::ExcNoEquilibrium &e)
      {
        outcome.iterations     = path_switches;
        outcome.no_equilibrium = true;
        outcome.failure        = text_of(e);
      }
    set_load_fraction(1.);
    return outcome;
  }



  template <int dim>
  typename ContactSolver<dim>::Trial
  ContactSolver<dim>::single_change(const Trial               &from,
                                    const Trial               &to,
                                    const std::vector<double> &violation)
  {
    Trial              result = from;
    const unsigned int worst =
      std::distance(violation.begin(),
                    std::max_element(violation.begin(), violation.end()));
    result.state[worst]        = to.state[worst];
    result.broken[worst]       = to.broken[worst];
    result.tensile_slip[worst] = to.tensile_slip[worst];
    result.slip_direction      = to.slip_direction;
    result.direction_stiffness = to.direction_stiffness;
    return result;
  }



  template <int dim>
  std::string
  ContactSolver<dim>::describe_cycle(const std::string &head,
                                     const unsigned int iteration,
                                     const Trial       &trial,
                                     const Trial       &next) const
  {
    std::ostringstream pairs;
    unsigned int       n_listed = 0;
    for (unsigned int k = 0; k < n_pairs && n_listed < 10; ++k)
      if (next.state[k] != trial.state[k])
        {
          pairs << "\n      pair " << k << " at (" << contact_pairs[k].a.point
                << "): " << to_string(trial.state[k]) << " <-> "
                << to_string(next.state[k]);
          ++n_listed;
        }
    return head + ": the contact states cycle after " +
           std::to_string(iteration) +
           " iterations, even switching one pair at a time. Pairs "
           "that keep switching:" +
           pairs.str() + "\n    Use more load increments.";
  }



  template <int dim>
  typename ContactSolver<dim>::FastOutcome
  ContactSolver<dim>::fast_iteration(Trial trial, const unsigned int increment)
  {
    const std::string head = "Load increment " + std::to_string(increment);

    FastOutcome           outcome;
    bool                  damped = false;
    std::set<std::string> seen{signature(trial)};
    Trial                 last_good, last_good_next;
    std::vector<double>   last_good_violation;
    bool                  have_good = false;

    for (unsigned int iteration = 1; iteration <= max_iterations; ++iteration)
      {
        outcome.iterations = iteration;
        Vector<double> solution, displacement;
        if (!solve_trial(trial, solution, displacement))
          {
            if (!damped && have_good)
              {
                // Too many switches at once can lose a block's support;
                // go back and switch one pair at a time.
                damped = true;
                seen.clear();
                trial =
                  single_change(last_good, last_good_next, last_good_violation);
                seen.insert(signature(trial));
                continue;
              }
            outcome.no_equilibrium = true;
            outcome.failure =
              head + ": no equilibrium." + diagnose_singular(trial);
            return outcome;
          }

        std::vector<double> violation;
        double              direction_change;
        Trial               next =
          check(trial, solution, displacement, violation, direction_change);

        if (signature(next) == signature(trial) && direction_change < 1e-6)
          {
            // The directions the solve used, for condensed_problem(); the
            // trial keeps the updated ones (the next increment's guess).
            const auto solved    = trial.slip_direction;
            trial.slip_direction = next.slip_direction;
            accept(trial, solution, displacement);
            solved_slip_direction = solved;
            outcome.converged     = true;
            return outcome;
          }
        have_good           = true;
        last_good           = trial;
        last_good_next      = next;
        last_good_violation = violation;

        if (damped && signature(next) != signature(trial))
          next = single_change(trial, next, violation);
        if (signature(next) != signature(trial) &&
            seen.count(signature(next)) == 1)
          {
            if (!damped)
              {
                damped = true;
                seen.clear();
                next = single_change(trial, next, violation);
              }
            else
              {
                outcome.failure = describe_cycle(head, iteration, trial, next);
                return outcome;
              }
          }
        seen.insert(signature(next));
        trial = next;
      }
    outcome.failure = head + ": the contact states did not settle in " +
                      std::to_string(max_iterations) +
                      " iterations ('Contact/Maximum iterations'). Use more "
                      "load increments.";
    return outcome;
  }



  template <int dim>
  void
  ContactSolver<dim>::accept(const Trial          &trial,
                             const Vector<double> &solution,
                             const Vector<double> &displacement)
  {
    current               = trial;
    current_solution      = solution;
    solved_slip_direction = trial.slip_direction;
    current_displacement.assign(n_pairs, Tensor<1, dim>());
    for (unsigned int k = 0; k < n_pairs; ++k)
      for (unsigned int i = 0; i < dim; ++i)
        current_displacement[k][i] = displacement(k * dim + i);
  }



  template <int dim>
  Vector<double>
  ContactSolver<dim>::mechanism_motion(const Trial &trial) const
  {
    if (n_alpha_total == 0)
      return Vector<double>();
    // The rows that fix a rigid motion: normal at a closed pair,
    // tangential at a stuck one.
    std::vector<unsigned int> rows;
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const bool stuck =
          trial.state[k] == ContactState::stick || contact_pairs[k].tied;
        if (trial.state[k] == ContactState::open && !contact_pairs[k].tied)
          continue;
        for (unsigned int d = 0; d < dim; ++d)
          if (!held[k][d] && (d == 0 || stuck))
            rows.push_back(k * dim + d);
      }
    const unsigned int       q = n_alpha_total;
    LAPACKFullMatrix<double> gram(q, q);
    // A row of P_hat couples the modes of the (at most two) blocks of its
    // pair only: add the products of its non-zero entries.
    std::vector<std::pair<unsigned int, double>> entries;
    for (const unsigned int row : rows)
      {
        entries.clear();
        for (unsigned int a = 0; a < q; ++a)
          if (coupling(row, a) != 0.)
            entries.emplace_back(a, coupling(row, a));
        for (const auto &[a, x] : entries)
          for (const auto &[c, y] : entries)
            gram(a, c) += x * y;
      }
    double largest = 0.;
    for (unsigned int a = 0; a < q; ++a)
      largest = std::max(largest, gram(a, a));
    Vector<double>     eigenvalues;
    FullMatrix<double> null_space;
    gram.compute_eigenvalues_symmetric(
      -1., 1e-10 * std::max(largest, 1e-300), 1e-14, eigenvalues, null_space);
    if (eigenvalues.size() == 0)
      return Vector<double>();

    // Of the free motions, the one the loads drive (their work on the
    // modes, projected on the free space); a free motion they do no work
    // on is named as it is.
    Vector<double> motion(q);
    for (unsigned int v = 0; v < eigenvalues.size(); ++v)
      {
        double work = 0.;
        for (unsigned int a = 0; a < q; ++a)
          work += external_resultant[a] * null_space(a, v);
        for (unsigned int a = 0; a < q; ++a)
          motion(a) += work * null_space(a, v);
      }
    if (motion.l2_norm() < 1e-8 * std::max(1e-300, [&] {
                             double f = 0.;
                             for (const double x : external_resultant)
                               f += x * x;
                             return std::sqrt(f);
                           }()))
      for (unsigned int a = 0; a < q; ++a)
        motion(a) = null_space(a, 0);
    return motion;
  }



  template <int dim>
  std::string
  ContactSolver<dim>::mechanism(const Trial &trial) const
  {
    const Vector<double> motion = mechanism_motion(trial);
    if (motion.size() == 0)
      return "";
    std::ostringstream message;
    for (unsigned int b = 0; b < n_alpha.size(); ++b)
      {
        Vector<double> combination(
          n_alpha[b] > 0 ? mode_coefficients[b][0].size() : 0);
        for (unsigned int a = 0; a < n_alpha[b]; ++a)
          combination.add(motion(alpha_offset[b] + a), mode_coefficients[b][a]);
        if (n_alpha[b] == 0 ||
            combination.linfty_norm() < 1e-6 * motion.linfty_norm())
          continue;
        combination /= combination.linfty_norm();
        unsigned int counts[3] = {0, 0, 0};
        for (unsigned int k = 0; k < n_pairs; ++k)
          {
            bool touches = false;
            for (unsigned int a = 0; a < n_alpha[b]; ++a)
              for (unsigned int d = 0; d < dim; ++d)
                if (coupling(k * dim + d, alpha_offset[b] + a) != 0.)
                  touches = true;
            if (touches)
              ++counts[static_cast<int>(trial.state[k])];
          }
        message << "\n    " << block_names[b]
                << " cannot be in equilibrium: its contact pairs (" << counts[0]
                << " stick, " << counts[1] << " slip, " << counts[2]
                << " open) cannot hold its rigid-body motion ["
                << Block<dim>::describe_rigid_body_mode(combination)
                << "]: the loads exceed what friction and cohesion can carry, "
                   "or the block has lost contact.";
      }
    return message.str();
  }



  template <int dim>
  void
  ContactSolver<dim>::commit()
  {
    // 3D: the direction a pair just slipped in is the first guess of the
    // next increment's Newton iteration on the direction.
    if (dim == 3)
      for (unsigned int k = 0; k < n_pairs; ++k)
        if (current.state[k] == ContactState::slip)
          {
            const Tensor<1, dim> v = slip_increment(k);
            if (v.norm() > 0.)
              current.slip_direction[k] = v / v.norm();
          }
    committed              = current;
    committed_displacement = current_displacement;
    committed_solution     = current_solution;
  }



  template <int dim>
  Tensor<1, dim>
  ContactSolver<dim>::slip_increment(const unsigned int k) const
  {
    Tensor<1, dim> v = current_displacement[k] - committed_displacement[k];
    v[0]             = 0.;
    return v;
  }



  template <int dim>
  double
  ContactSolver<dim>::misalignment() const
  {
    double largest = 0.;
    for (unsigned int k = 0; k < n_pairs; ++k)
      if (current.state[k] == ContactState::slip)
        {
          const Tensor<1, dim> v = slip_increment(k);
          if (v.norm() == 0.)
            continue;
          const double cosine =
            std::min(1.,
                     std::max(-1., v * current.slip_direction[k] / v.norm()));
          largest = std::max(largest, std::acos(cosine) * 180. / numbers::PI);
        }
    return largest;
  }



  template <int dim>
  void
  ContactSolver<dim>::forces_on_block(
    const unsigned int                    b,
    std::vector<types::global_dof_index> &dofs,
    std::vector<double>                  &forces) const
  {
    dofs.clear();
    forces.clear();
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const Tensor<1, dim> r = force(k);
        for (const int sign : {-1, 1})
          {
            const auto &side = contact_pairs[k].side(sign);
            if (side.block != b)
              continue;
            for (const auto &node : side.nodes)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  dofs.push_back(node.dofs[c]);
                  forces.push_back(sign * node.weight * r[c]);
                }
          }
      }
  }



  template <int dim>
  std::vector<double>
  ContactSolver<dim>::floating_amplitudes(const unsigned int b) const
  {
    std::vector<double> alpha(n_alpha[b]);
    for (unsigned int a = 0; a < n_alpha[b]; ++a)
      alpha[a] = current_solution(n_pairs * dim + alpha_offset[b] + a);
    return alpha;
  }



  template <int dim>
  void
  ContactSolver<dim>::block_solution(const unsigned int b,
                                     const Block<dim>  &block,
                                     Vector<double>    &solution) const
  {
    Assert(monolithic, ExcInternalError());
    monolithic->block_solution(b, block, solution);
  }



  template <int dim>
  const std::vector<ContactPair<dim>> &
  ContactSolver<dim>::pairs() const
  {
    return contact_pairs;
  }



  template <int dim>
  Tensor<1, dim>
  ContactSolver<dim>::local_force(const unsigned int k) const
  {
    Tensor<1, dim> rho;
    if (current_solution.size() > 0)
      for (unsigned int d = 0; d < dim; ++d)
        rho[d] = current_solution(k * dim + d);
    return rho;
  }



  template <int dim>
  Tensor<1, dim>
  ContactSolver<dim>::force(const unsigned int k) const
  {
    // r = R^T rho
    const Tensor<1, dim> rho = local_force(k);
    Tensor<1, dim>       r;
    for (unsigned int i = 0; i < dim; ++i)
      r += rho[i] * contact_pairs[k].frame[i];
    return r;
  }



  template <int dim>
  double
  ContactSolver<dim>::gap(const unsigned int k) const
  {
    return contact_pairs[k].initial_gap + current_displacement[k][0];
  }



  template <int dim>
  Tensor<1, dim>
  ContactSolver<dim>::slip(const unsigned int k) const
  {
    Tensor<1, dim> s = current_displacement[k];
    s[0]             = 0.;
    return s;
  }



  template <int dim>
  ContactState
  ContactSolver<dim>::state(const unsigned int k) const
  {
    return current.state[k];
  }



  template <int dim>
  bool
  ContactSolver<dim>::broken(const unsigned int k) const
  {
    return current.broken[k];
  }



  template <int dim>
  unsigned int
  ContactSolver<dim>::count(const ContactState state) const
  {
    return std::count(current.state.begin(), current.state.end(), state);
  }



  template <int dim>
  typename StaticAdmissibility<dim>::Result
  ContactSolver<dim>::certify(const bool with_mechanism_factor,
                              const bool unbroken) const
  {
    using Certificate = StaticAdmissibility<dim>;
    std::vector<typename Certificate::Candidate> candidates(n_pairs);
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        candidates[k].joint  = contact_pairs[k].joint;
        candidates[k].area   = contact_pairs[k].area;
        candidates[k].broken = !unbroken && current.broken[k];
        candidates[k].tied   = contact_pairs[k].tied;
        if (k < held.size())
          candidates[k].held = held[k];
      }
    std::vector<double> resultant = external_resultant;
    resultant.resize(n_alpha_total, 0.);
    const Certificate certificate(std::move(candidates), coupling, resultant);
    typename Certificate::Result result =
      certificate.solve(with_mechanism_factor);

    std::ostringstream text;
    text << std::fixed << std::setprecision(6);
    const std::string lp = "a rigid-block linear program over the " +
                           std::to_string(result.n_candidates) +
                           " candidate pairs of the floating blocks" +
                           (dim == 3 ? " (cones as polygons of 64 sides)" : "");
    const std::string factor =
      (result.strength_factor_bounded ?
         (result.strength_factor > 1. ? "above 1000" : "below 0.001") :
         std::to_string(result.strength_factor));
    switch (result.verdict)
      {
        case Certificate::Verdict::admissible:
          text << "statically admissible contact forces exist (" << lp
               << "): the joints' strength could be divided by up to " << factor
               << " (strength factor).";
          break;
        case Certificate::Verdict::undecided:
          text << "the statics certificate cannot decide: forces exist in "
                  "the circumscribed cones but not in the inscribed ones ("
               << lp << "); strength factor at most " << factor << ".";
          break;
        case Certificate::Verdict::none:
          text << "no statically admissible contact forces exist (" << lp
               << "): no forces within the pairs' Mohr-Coulomb cones "
                  "balance the floating blocks' loads; strength factor "
               << factor
               << ": admissible forces exist only with the joints' strength "
                  "multiplied by "
               << (result.strength_factor > 0. ?
                     std::to_string(1. / result.strength_factor) :
                     std::string("more than 1000"))
               << ". Mechanism (a virtual velocity along which the loads "
                  "do more work than the joints can dissipate):";
          text << describe_mechanism(result.mechanism);
          break;
      }
    text << describe_mechanism_factor(result);
    result.description = text.str();
    return result;
  }



  template <int dim>
  std::string
  ContactSolver<dim>::describe_mechanism_factor(
    const typename StaticAdmissibility<dim>::Result &result) const
  {
    if (result.limit_mechanism.empty())
      return "";
    std::ostringstream text;
    text << std::fixed << std::setprecision(6) << "\n    Limit equilibrium";
    if (result.verdict == StaticAdmissibility<dim>::Verdict::none)
      text << " along that mechanism,";
    else
      text << " along the mechanism of the statics limit"
           << describe_mechanism(result.limit_mechanism) << ",";
    text << " with the shear of every sliding pair against its slip (at "
            "most c A + mu N, N >= 0, with tensile strength sigma_t: at most "
            "c A + mu (N + sigma_t A)), open pairs carrying nothing and those "
            "at rest anything in their cone: the joints' strength could be "
            "divided by "
         << (result.mechanism_factor_bounded ?
               (result.mechanism_factor > 1. ?
                  std::string("above 1000") :
                  std::string("not even 0.001 (no strength up to 1000 "
                              "times the given one holds the loads)")) :
               "up to " + std::to_string(result.mechanism_factor))
         << " (mechanism factor"
         << (dim == 3 && result.limit_mechanism_freedom != 1 ?
               "; shear within pi/64 of the mechanism's slip, as the LP "
               "fixes its direction to that" :
               "")
         << ").";
    return text.str();
  }



  template <int dim>
  StateMethod
  ContactSolver<dim>::last_method() const
  {
    return method;
  }



  template <int dim>
  std::string
  ContactSolver<dim>::describe_mechanism(
    const std::vector<double> &mechanism) const
  {
    // Each block's motion as a combination of its rigid-body modes
    // (translations, then rotations in units of the block's diameter).
    std::vector<Vector<double>> motion(n_alpha.size());
    double                      largest = 0.;
    for (unsigned int b = 0; b < n_alpha.size(); ++b)
      {
        if (n_alpha[b] == 0)
          continue;
        motion[b].reinit(mode_coefficients[b][0].size());
        for (unsigned int a = 0; a < n_alpha[b]; ++a)
          motion[b].add(mechanism[alpha_offset[b] + a],
                        mode_coefficients[b][a]);
        largest = std::max(largest, motion[b].linfty_norm());
      }
    std::ostringstream text;
    text << std::fixed << std::setprecision(4);
    for (unsigned int b = 0; b < n_alpha.size(); ++b)
      {
        if (n_alpha[b] == 0 || motion[b].linfty_norm() <= 1e-6 * largest)
          continue;
        Tensor<1, dim> translation;
        for (unsigned int d = 0; d < dim; ++d)
          translation[d] = motion[b](d);
        // Rotation per unit translation, or the rotation alone.
        const double length = translation.norm();
        text << "\n      " << block_names[b] << ": ";
        if (length > 1e-6 * motion[b].linfty_norm())
          text << "translation along (" << translation / length << "), "
               << "rotation per unit translation ";
        else
          text << "no translation, rotation ";
        text << (dim == 2 ? "about z " : "(");
        for (unsigned int d = dim; d < motion[b].size(); ++d)
          text << (d > dim ? " " : "")
               << motion[b](d) / (length > 1e-6 * motion[b].linfty_norm() ?
                                    length :
                                    motion[b].linfty_norm());
        text << (dim == 2 ? "" : ")")
             << " (rotations in units of the block's diameter)";
      }
    return text.str();
  }



  template <int dim>
  std::vector<std::string>
  ContactSolver<dim>::blocks_without_stuck_pairs() const
  {
    std::vector<std::string> names;
    for (unsigned int b = 0; b < n_alpha.size(); ++b)
      {
        if (n_alpha[b] == 0)
          continue;
        bool touched = false, stuck = false;
        for (unsigned int k = 0; k < n_pairs; ++k)
          if (contact_pairs[k].a.block == b || contact_pairs[k].b.block == b)
            {
              touched = true;
              stuck   = stuck || current.state[k] == ContactState::stick;
            }
        if (touched && !stuck)
          names.push_back(block_names[b]);
      }
    return names;
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  ContactSolver<dim>::last_iterations() const
  {
    return {fast_iterations, path_switches};
  }



  template class ContactSolver<2>;
  template class ContactSolver<3>;
} // namespace mbfem

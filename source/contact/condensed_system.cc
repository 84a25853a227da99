#include <mbfem/base/parallel.h>
#include <mbfem/contact/condensed_system.h>
#include <mbfem/linear_algebra/inverse_norm.h>

#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

namespace mbfem
{
  template <int dim>
  CondensedSystem<dim>::CondensedSystem(
    const std::vector<ContactPair<dim>>       &pairs,
    const RigidCoupling<dim>                  &coupling,
    const ContactSolverParameters::StateSystem state_system)
    : pairs(pairs)
    , coupling(coupling)
    , n_pairs(pairs.size())
    , state_system(state_system)
  {}



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
  CondensedSystem<dim>::setup(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks)
  {
    block_flexibility.clear();
    pair_sides.assign(n_pairs, {});
    factorisation = Factorisation();
    // Each rank computes its blocks' H_b, then they exchange them.
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (unsigned int b = 0; b < blocks.size(); ++b)
        add_block(*blocks[b], b);
    });
    share_blocks();
    find_held_directions();

    // P_hat's non-zero entries by rows and by columns: a pair moves with
    // the modes of its two blocks only.
    coupling_rows.assign(n_pairs * dim, {});
    coupling_columns.assign(coupling.n_modes(), {});
    for (unsigned int i = 0; i < n_pairs * dim; ++i)
      for (const auto &[a, value] : coupling.row(i))
        if (value != 0.)
          {
            coupling_rows[i].emplace_back(a, value);
            coupling_columns[a].emplace_back(i, value);
          }
  }



  template <int dim>
  void
  CondensedSystem<dim>::add_block(Block<dim> &block, const unsigned int b)
  {
    const std::vector<types::global_dof_index> dofs = contact_dofs(pairs, b);
    if (dofs.empty())
      return;
    std::map<types::global_dof_index, unsigned int> index_of;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      index_of.emplace(dofs[i], i);
    // The pair sides on this block: (pair, sign); b gets +r, a gets -r.
    std::vector<std::pair<unsigned int, double>> sides;
    for (unsigned int k = 0; k < n_pairs; ++k)
      for (const int sign : {-1, 1})
        if (pairs[k].side(sign).block == b)
          sides.emplace_back(k, sign);

    // A side's displacement is sum_i w_i u(node_i), in its pair's
    // frame: the rows of S (see project()).
    std::vector<std::vector<std::pair<unsigned int, double>>> rows(
      sides.size() * dim);
    BlockFlexibility flexibility;
    flexibility.communicator = block.get_communicator();
    flexibility.owner        = block.get_owner();
    flexibility.local        = block.is_local();
    for (unsigned int s = 0; s < sides.size(); ++s)
      {
        const auto &[k, sign]       = sides[s];
        const Tensor<2, dim> &frame = pairs[k].frame;
        flexibility.pairs.push_back(k);
        pair_sides[k].emplace_back(block_flexibility.size(), s);
        for (const auto &node : pairs[k].side(sign).nodes)
          {
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int c = 0; c < dim; ++c)
                if (frame[i][c] != 0.)
                  rows[s * dim + i].emplace_back(index_of[node.dofs[c]],
                                                 sign * node.weight *
                                                   frame[i][c]);
          }
      }
    if (is_on_demand(block, dofs.size(), flexibility_columns))
      {
        flexibility.on_demand = block.on_demand_flexibility(dofs);
        flexibility.diagonal.assign(rows.size(), 0.);
        if (flexibility.local)
          flexibility.diagonal = sampled_diagonal(*flexibility.on_demand, rows);
        flexibility.rows = std::move(rows);
        flexibility.columns.resize(flexibility.rows.size());
        flexibility.compact = !flexibility.local;
      }
    else if (flexibility.local)
      {
        FullMatrix<double> c_block = block.flexibility(dofs);
        flexibility.matrix         = project(c_block, rows);
      }
    else
      flexibility.matrix.reinit(rows.size(), rows.size());
    block_flexibility.push_back(std::move(flexibility));
  }



  template <int dim>
  std::vector<types::global_dof_index>
  CondensedSystem<dim>::contact_dofs(const std::vector<ContactPair<dim>> &pairs,
                                     const unsigned int                   b)
  {
    std::vector<types::global_dof_index> dofs;
    std::set<types::global_dof_index>    seen;
    for (const auto &pair : pairs)
      for (const int sign : {-1, 1})
        if (pair.side(sign).block == b)
          for (const auto &node : pair.side(sign).nodes)
            for (const auto dof : node.dofs)
              if (seen.insert(dof).second)
                dofs.push_back(dof);
    return dofs;
  }



  template <int dim>
  bool
  CondensedSystem<dim>::is_on_demand(
    const Block<dim>                                 &block,
    const std::size_t                                 n_contact_dofs,
    const ContactSolverParameters::FlexibilityColumns columns)
  {
    using Columns = ContactSolverParameters::FlexibilityColumns;
    return n_contact_dofs > 0 && block.has_fixed_stiffness() &&
           (columns == Columns::on_demand ||
            (columns == Columns::automatic && n_contact_dofs >= 500));
  }



  template <int dim>
  void
  CondensedSystem<dim>::share_blocks()
  {
    for (auto &flexibility : block_flexibility)
      if (flexibility.on_demand)
        Parallel::broadcast(flexibility.communicator,
                            flexibility.owner,
                            flexibility.diagonal.data(),
                            flexibility.diagonal.size());
      else
        Parallel::broadcast(flexibility.communicator,
                            flexibility.owner,
                            flexibility.matrix);
  }


  template <int dim>
  std::vector<double>
  CondensedSystem<dim>::sampled_diagonal(const ContactFlexibility &flexibility,
                                         const std::vector<ContactLoad> &rows)
  {
    // The whole diagonal is costly (the 1377-pair stacked beams'
    // flexibility step: 4.6 s with it, 1.2 s with this sample): for scale() and
    // the held directions, a sample per pair direction (normal, tangential:
    // their flexibilities differ) and its mean do.
    std::vector<double> diagonal(rows.size(), 0.);
    for (unsigned int direction = 0; direction < dim; ++direction)
      {
        std::vector<unsigned int> moving;
        for (unsigned int r = direction; r < rows.size(); r += dim)
          if (flexibility.moves(rows[r]))
            moving.push_back(r);
        if (moving.empty())
          continue;
        const std::size_t        n = std::min<std::size_t>(32, moving.size());
        std::vector<ContactLoad> sample;
        for (std::size_t i = 0; i < n; ++i)
          sample.push_back(rows[moving[i * moving.size() / n]]);
        const std::vector<double> values = flexibility.forms(sample);
        const double              mean =
          std::accumulate(values.begin(), values.end(), 0.) / n;
        for (const unsigned int r : moving)
          diagonal[r] = mean;
        for (std::size_t i = 0; i < n; ++i)
          diagonal[moving[i * moving.size() / n]] = values[i];
      }
    return diagonal;
  }



  template <int dim>
  void
  CondensedSystem<dim>::find_held_directions()
  {
    const unsigned int  n_r = n_pairs * dim;
    std::vector<double> diagonal(n_r);
    for (unsigned int i = 0; i < n_r; ++i)
      diagonal[i] = diagonal_entry(i);
    const double trace = std::accumulate(diagonal.begin(), diagonal.end(), 0.);
    flexibility_scale  = (n_r > 0 && trace > 0. ? trace / n_r : 1.);

    // A direction in which neither node can move (both on supports) carries
    // no contact force: the supports take it.
    const double max_diagonal =
      n_r > 0 ? *std::max_element(diagonal.begin(), diagonal.end()) : 0.;
    held_directions.assign(n_pairs, std::array<bool, dim>());
    for (unsigned int k = 0; k < n_pairs; ++k)
      for (unsigned int d = 0; d < dim; ++d)
        {
          double mobility = 0.;
          for (const auto &[a, value] : coupling.row(k * dim + d))
            mobility = std::max(mobility, std::abs(value));
          held_directions[k][d] =
            diagonal[k * dim + d] < 1e-12 * max_diagonal && mobility < 1e-12;
        }
  }


  template <int dim>
  double
  CondensedSystem<dim>::entry(const unsigned int row,
                              const unsigned int column) const
  {
    const unsigned int k = row / dim, l = column / dim;
    double             value = 0.;
    for (const auto &[b, s] : pair_sides[k])
      for (const auto &[c, t] : pair_sides[l])
        if (b == c)
          value +=
            block_flexibility[b](s * dim + row % dim, t * dim + column % dim);
    return value;
  }


  template <int dim>
  double
  CondensedSystem<dim>::diagonal_entry(const unsigned int row) const
  {
    const unsigned int k = row / dim, i = row % dim;
    double             value = 0.;
    for (const auto &[b, s] : pair_sides[k])
      {
        const BlockFlexibility &flexibility = block_flexibility[b];
        value += !flexibility.on_demand ?
                   flexibility.matrix(s * dim + i, s * dim + i) :
                   flexibility.diagonal[s * dim + i];
      }
    return value;
  }


  template <int dim>
  void
  CondensedSystem<dim>::request_columns(
    const std::vector<unsigned int> &rows) const
  {
    std::vector<std::vector<unsigned int>> missing(block_flexibility.size());
    for (const unsigned int row : rows)
      for (const auto &[b, s] : pair_sides[row / dim])
        {
          const BlockFlexibility &flexibility = block_flexibility[b];
          const unsigned int      column      = s * dim + row % dim;
          if (flexibility.on_demand && flexibility.columns[column].empty())
            missing[b].push_back(column);
        }
    for (auto &columns : missing)
      {
        std::sort(columns.begin(), columns.end());
        columns.erase(std::unique(columns.begin(), columns.end()),
                      columns.end());
      }
    if (Parallel::n_ranks() > 1)
      {
        // Ranks whose iterations took different states would ask for
        // different columns and wait for each other below: an error
        // instead.
        std::vector<unsigned long long> requests;
        for (const auto &columns : missing)
          {
            requests.push_back(columns.size());
            requests.insert(requests.end(), columns.begin(), columns.end());
          }
        Parallel::check_same_on_all_ranks(
          requests, "the flexibility columns their contact iterations ask for");
      }
    if (std::all_of(missing.begin(), missing.end(), [](const auto &columns) {
          return columns.empty();
        }))
      return; // the same on every rank
    if (Parallel::n_ranks() == 1)
      {
        for (unsigned int b = 0; b < block_flexibility.size(); ++b)
          if (!missing[b].empty())
            compute_columns(block_flexibility[b], missing[b]);
        return;
      }
    // Each rank computes its blocks' columns and makes room for what it
    // receives of the others', then the owners send them.
    const unsigned int                     n_blocks = block_flexibility.size();
    std::vector<std::vector<unsigned int>> old(n_blocks);
    std::vector<unsigned int>              n_kept_before(n_blocks);
    std::vector<std::vector<double>>       messages(n_blocks);
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (unsigned int b = 0; b < n_blocks; ++b)
        if (!missing[b].empty())
          {
            const BlockFlexibility &flexibility = block_flexibility[b];
            n_kept_before[b]                    = flexibility.kept_rows.size();
            old[b] = keep_rows(flexibility, missing[b], messages[b]);
            if (flexibility.local)
              compute_columns(flexibility, missing[b]);
          }
    });
    for (unsigned int b = 0; b < n_blocks; ++b)
      if (!missing[b].empty())
        share_columns(block_flexibility[b],
                      missing[b],
                      old[b],
                      n_kept_before[b],
                      messages[b]);
  }



  template <int dim>
  std::vector<unsigned int>
  CondensedSystem<dim>::keep_rows(const BlockFlexibility          &flexibility,
                                  const std::vector<unsigned int> &columns,
                                  std::vector<double> &message) const
  {
    // Every direction of a side with a computed column: the rows that
    // assemble(), sparse_row() and add_row() read are those of pairs with
    // an unknown, whose own columns they request.
    std::vector<unsigned int> old;
    for (unsigned int c = 0; c < flexibility.columns.size(); ++c)
      if (!flexibility.columns[c].empty())
        old.push_back(c);
    if (flexibility.kept_position.empty())
      flexibility.kept_position.assign(flexibility.rows.size(), -1);
    const std::size_t n_before = flexibility.kept_rows.size();
    for (const unsigned int c : columns)
      if (flexibility.kept_position[c] < 0)
        for (unsigned int i = 0; i < dim; ++i)
          {
            const unsigned int r         = (c / dim) * dim + i;
            flexibility.kept_position[r] = flexibility.kept_rows.size();
            flexibility.kept_rows.push_back(r);
          }
    const std::size_t n_kept = flexibility.kept_rows.size();
    // share_columns() sends some 8 MB at a time.
    const std::size_t n_values =
      columns.size() * n_kept + old.size() * (n_kept - n_before);
    message.assign(std::min<std::size_t>(n_values, std::size_t(1) << 20), 0.);
    if (flexibility.compact)
      {
        // Exactly n_kept each: resize() would double a column's capacity.
        for (const unsigned int c : old)
          {
            std::vector<double> grown(n_kept, 0.);
            std::copy(flexibility.columns[c].begin(),
                      flexibility.columns[c].end(),
                      grown.begin());
            flexibility.columns[c].swap(grown);
          }
        for (const unsigned int c : columns)
          flexibility.columns[c].assign(n_kept, 0.);
      }
    return old;
  }



  template <int dim>
  void
  CondensedSystem<dim>::share_columns(const BlockFlexibility &flexibility,
                                      const std::vector<unsigned int> &columns,
                                      const std::vector<unsigned int> &old,
                                      const unsigned int   n_kept_before,
                                      std::vector<double> &message) const
  {
    // In messages of message.size() values, into the room keep_rows()
    // made: no allocation here, where a failure would not reach the other
    // ranks. The owner's numbers, so that every rank holds the same: the
    // owner fills a message and then sends it, the others receive one
    // before they read it.
    const auto       &kept   = flexibility.kept_rows;
    const std::size_t n_kept = kept.size();
    const std::size_t n_values =
      columns.size() * n_kept + old.size() * (n_kept - n_kept_before);
    std::size_t sent = 0, p = 0;
    const auto  exchange = [&]() {
      Parallel::broadcast(flexibility.communicator,
                          flexibility.owner,
                          message.data(),
                          std::min(message.size(), n_values - sent));
    };
    const auto visit = [&](const unsigned int c, const std::size_t i) {
      if (!flexibility.local && p == 0)
        exchange();
      if (flexibility.local)
        message[p] = flexibility.columns[c][kept[i]];
      else
        flexibility.columns[c][i] = message[p];
      if (++p == std::min(message.size(), n_values - sent))
        {
          if (flexibility.local)
            exchange();
          sent += p;
          p = 0;
        }
    };
    for (const unsigned int c : columns)
      for (std::size_t i = 0; i < n_kept; ++i)
        visit(c, i);
    for (const unsigned int c : old)
      for (std::size_t i = n_kept_before; i < n_kept; ++i)
        visit(c, i);
    std::vector<double>().swap(message);
  }


  template <int dim>
  void
  CondensedSystem<dim>::compute_columns(
    const BlockFlexibility          &flexibility,
    const std::vector<unsigned int> &columns) const
  {
    // H_b(., c) = S C s_c: the displacements at the contact DoFs under
    // the load pattern of row c of S, then S applied to them. In batches
    // of some 4 million entries: the solver's request and answer and x
    // hold a batch, not every column at once (on the stacked beams of
    // 6697 pairs, 1395 columns of 20091 entries would be 0.8 GB more).
    const unsigned int n_rows = flexibility.rows.size();
    const std::size_t  batch =
      std::max<std::size_t>(1, (std::size_t(1) << 22) / std::max(1u, n_rows));
    for (std::size_t first = 0; first < columns.size(); first += batch)
      {
        const std::size_t        end = std::min(columns.size(), first + batch);
        std::vector<ContactLoad> loads;
        for (std::size_t l = first; l < end; ++l)
          loads.push_back(flexibility.rows[columns[l]]);
        const FullMatrix<double> x = flexibility.on_demand->columns(loads);
        for (std::size_t l = first; l < end; ++l)
          {
            std::vector<double> &column = flexibility.columns[columns[l]];
            column.assign(n_rows, 0.);
            for (unsigned int r = 0; r < n_rows; ++r)
              for (const auto &[q, weight] : flexibility.rows[r])
                column[r] += weight * x(q, l - first);
          }
      }
  }


  template <int dim>
  void
  CondensedSystem<dim>::set_flexibility_columns(
    const ContactSolverParameters::FlexibilityColumns columns)
  {
    flexibility_columns = columns;
  }



  template <int dim>
  bool
  CondensedSystem<dim>::on_demand(const unsigned int k) const
  {
    return !pair_sides[k].empty() &&
           std::all_of(pair_sides[k].begin(),
                       pair_sides[k].end(),
                       [this](const auto &side) {
                         return block_flexibility[side.first].on_demand !=
                                nullptr;
                       });
  }



  template <int dim>
  std::pair<std::size_t, std::size_t>
  CondensedSystem<dim>::columns_on_demand() const
  {
    std::size_t computed = 0, all = 0;
    for (const auto &flexibility : block_flexibility)
      if (flexibility.on_demand)
        for (const auto &column : flexibility.columns)
          {
            ++all;
            computed += column.empty() ? 0 : 1;
          }
    return {computed, all};
  }


  template <int dim>
  void
  CondensedSystem<dim>::set_load(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    IncrementLoads                                 &loads)
  {
    loads.displacement.reinit(n_pairs * dim);
    for (unsigned int k = 0; k < n_pairs; ++k)
      {
        const auto    &pair = pairs[k];
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
          loads.displacement(k * dim + i) = pair.frame[i] * d;
      }
  }



  template <int dim>
  std::vector<std::array<bool, dim>>
  CondensedSystem<dim>::held() const
  {
    return held_directions;
  }



  template <int dim>
  double
  CondensedSystem<dim>::scale() const
  {
    return flexibility_scale;
  }



  template <int dim>
  void
  CondensedSystem<dim>::add_entries(
    std::map<std::pair<unsigned int, unsigned int>, double> &matrix) const
  {
    std::vector<unsigned int> every_row(n_pairs * dim);
    std::iota(every_row.begin(), every_row.end(), 0);
    request_columns(every_row);
    for (const auto &block : block_flexibility)
      for (unsigned int s = 0; s < block.pairs.size(); ++s)
        for (unsigned int t = 0; t < block.pairs.size(); ++t)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              matrix[{block.pairs[s] * dim + i, block.pairs[t] * dim + j}] +=
                block(s * dim + i, t * dim + j);
  }



  template <int dim>
  bool
  CondensedSystem<dim>::solve(const std::vector<PairEquation<dim>> &equations,
                              const IncrementLoads                 &loads,
                              Vector<double>                       &solution,
                              Vector<double> &displacement)
  {
    if (!solve_forces(equations, loads, solution))
      return false;
    displacement = relative_displacement(solution, loads);
    return true;
  }



  template <int dim>
  bool
  CondensedSystem<dim>::solve_forces(
    const std::vector<PairEquation<dim>> &equations,
    const IncrementLoads                 &loads,
    Vector<double>                       &solution)
  {
    const unsigned int        n_r = n_pairs * dim;
    std::vector<double>       key;
    std::vector<unsigned int> unknowns;
    set_unknowns(equations, key, unknowns);
    const unsigned int n_rho = unknowns.size();
    if (n_rho + coupling.n_modes() == 0)
      {
        // Every pair open and no floating block: all forces are zero (LAPACK
        // refuses a 0 x 0 factorisation).
        solution.reinit(n_r);
        return true;
      }

    // The key decides the unknowns and so whether the system is sparse
    // (then over every pair direction and floating mode).
    Factorisation &system = factorisation;
    if (system.coefficients != key)
      set_system(equations, key, unknowns);
    if (!system.regular)
      return false;

    Vector<double> rhs = right_hand_side(equations, loads);
    if (system.dense)
      system.matrix.solve(rhs);
    else if (!solve_sparse(equations, system, rhs))
      return false;

    // Where unknown i and floating mode a are in the system.
    const auto index = [&](const unsigned int i) {
      return system.dense ? i : unknowns[i];
    };
    const unsigned int first_mode = system.dense ? n_rho : n_r;
    solution.reinit(n_r + coupling.n_modes());
    for (unsigned int i = 0; i < n_rho; ++i)
      solution(unknowns[i]) = rhs(index(i)) / flexibility_scale;
    for (unsigned int a = 0; a < coupling.n_modes(); ++a)
      solution(n_r + a) = rhs(first_mode + a);
    return true;
  }



  template <int dim>
  void
  CondensedSystem<dim>::set_unknowns(
    const std::vector<PairEquation<dim>> &equations,
    std::vector<double>                  &key,
    std::vector<unsigned int>            &unknowns) const
  {
    // A row that says rho_i = 0 (open pairs, held directions) removes its
    // unknown: only the directions of the other pairs and the floating
    // modes remain, some 250 of 4131 unknowns on the 1377-pair model.
    const unsigned int n_r = n_pairs * dim;
    key.clear();
    unknowns.clear();
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
  }



  template <int dim>
  void
  CondensedSystem<dim>::set_system(
    const std::vector<PairEquation<dim>> &equations,
    const std::vector<double>            &key,
    const std::vector<unsigned int>      &unknowns)
  {
    // No key until the columns are there: a throw in request_columns()
    // must not leave the old factors under the new key.
    Factorisation &system = factorisation;
    system.coefficients.clear();
    system.regular = false;
    system.dense   = !use_sparse(unknowns);
    request_columns(system.dense ? unknowns : sparse_columns(unknowns));
    system.coefficients = key;
    system.unknowns     = unknowns;
    if (system.dense)
      assemble(equations, system);
    else
      assemble_sparse(equations, system);
  }



  template <int dim>
  Vector<double>
  CondensedSystem<dim>::right_hand_side(
    const std::vector<PairEquation<dim>> &equations,
    const IncrementLoads                 &loads) const
  {
    // Unknowns: rho * scale (a displacement) and alpha, so that all entries
    // are of unit order whatever the units of the model; the singularity
    // test then means the same for a rubber and a rock model. A row with
    // force terms is multiplied by scale.
    const Factorisation &system = factorisation;
    const unsigned int   n_r    = n_pairs * dim;
    const unsigned int   n_rho  = system.unknowns.size();
    const double         scale  = flexibility_scale;
    Vector<double>       rhs(system.size);
    for (unsigned int i = 0; i < n_rho; ++i)
      {
        const unsigned int       row   = system.unknowns[i];
        const PairEquation<dim> &eq    = equations[row];
        double                   value = eq.value;
        for (unsigned int e = 0; e < dim; ++e)
          value -= eq.displacement_coefficients[e] *
                   loads.displacement((row / dim) * dim + e);
        rhs(system.dense ? i : row) =
          (eq.has_force_terms() ? scale : 1.) * value;
      }
    const unsigned int first_mode = system.dense ? n_rho : n_r;
    for (unsigned int a = 0; a < coupling.n_modes(); ++a)
      rhs(first_mode + a) = -loads.resultant[a] * scale;
    return rhs;
  }



  template <int dim>
  void
  CondensedSystem<dim>::assemble(
    const std::vector<PairEquation<dim>> &equations,
    Factorisation                        &system) const
  {
    const unsigned int               n_r      = n_pairs * dim;
    const std::vector<unsigned int> &unknowns = system.unknowns;
    const unsigned int               n_rho    = unknowns.size();
    const unsigned int               n        = n_rho + coupling.n_modes();
    const double                     scale    = flexibility_scale;

    // Not regular until factorised: a throw below must not leave the
    // cache (keyed already) saying otherwise.
    system.regular = false;
    system.size    = n;
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
                  matrix(i, j) +=
                    row_scale * a * entry(source, unknowns[j]) / scale;
                for (const auto &[b, value] : coupling.row(source))
                  matrix(i, n_rho + b) += row_scale * a * value;
              }
            if (eq.force_coefficients[e] != 0. && column_of[k * dim + e] >= 0)
              matrix(i, column_of[k * dim + e]) += eq.force_coefficients[e];
          }
      }
    // Equilibrium of the floating blocks: P^T r = -F_e.
    for (unsigned int j = 0; j < n_rho; ++j)
      for (const auto &[a, value] : coupling.row(unknowns[j]))
        matrix(n_rho + a, j) = value;

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
  CondensedSystem<dim>::estimate_condition(Factorisation &system,
                                           const double   norm) const
  {
    // Condition estimate ||A||_1 ||A^{-1}||_1.
    const double inverse_norm =
      inverse_norm_estimate(system.size, {}, [&](Vector<double> &x) {
        system.matrix.solve(x);
      });
    system.regular = std::isfinite(norm) && norm * inverse_norm < 1e12;
  }


  template <int dim>
  bool
  CondensedSystem<dim>::use_sparse(
    const std::vector<unsigned int> &unknowns) const
  {
    if (state_system != ContactSolverParameters::StateSystem::automatic)
      return state_system == ContactSolverParameters::StateSystem::sparse;
    const double n = unknowns.size() + coupling.n_modes();
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
  CondensedSystem<dim>::assemble_sparse(
    const std::vector<PairEquation<dim>> &equations,
    Factorisation                        &system) const
  {
    const unsigned int n_r = n_pairs * dim;
    const unsigned int n   = n_r + coupling.n_modes();
    std::vector<bool>  active(n, false);
    for (const unsigned int row : system.unknowns)
      active[row] = true;
    std::fill(active.begin() + n_r, active.end(), true);
    system.regular = false;
    system.size    = n;
    system.matrix.reinit(0, 0);
    if (!system.sparse)
      {
        system.sparse = std::make_unique<UpdatedLU>();
        system.sparse->set_blocks(dim, n_r);
      }
    UpdatedLU &lu = *system.sparse;

    // The rows whose equations changed since the base, replaced.
    const unsigned int stride = 2 * dim + 1;
    if (lu.factorized() && lu.size() == n &&
        system.base_coefficients.size() == system.coefficients.size() &&
        system.base_columns == columns_on_demand().first)
      {
        std::vector<unsigned int> changed;
        for (unsigned int row = 0; row < n_r && changed.size() <= lu.max_rank();
             ++row)
          if (!std::equal(system.coefficients.begin() + row * stride,
                          system.coefficients.begin() + (row + 1) * stride,
                          system.base_coefficients.begin() + row * stride))
            changed.push_back(row);
        if (changed.size() <= lu.max_rank())
          {
            std::vector<UpdatedLU::Row> rows;
            for (const unsigned int row : changed)
              rows.push_back(sparse_row(equations, active, row));
            if (lu.replace_rows(changed, rows))
              {
                estimate_sparse_condition(system);
                // A system that seems singular is decided by its own LU.
                if (system.regular)
                  return;
              }
          }
      }

    // A new base.
    std::vector<UpdatedLU::Row> rows(n);
    for (unsigned int row = 0; row < n; ++row)
      rows[row] = sparse_row(equations, active, row);
    system.base_coefficients.clear();
    if (!lu.factorize(rows))
      return; // a zero pivot
    estimate_sparse_condition(system);
    if (system.regular)
      {
        system.base_coefficients = system.coefficients;
        system.base_columns      = columns_on_demand().first;
      }
  }


  template <int dim>
  std::vector<unsigned int>
  CondensedSystem<dim>::sparse_columns(
    const std::vector<unsigned int> &unknowns) const
  {
    // Every direction of a pair with an unknown left free: sparse_row()
    // reads the columns computed, and a direction that becomes an unknown
    // later then needs no new column (which would make a new base).
    std::vector<unsigned int> columns;
    for (const unsigned int row : unknowns)
      for (unsigned int f = 0; f < dim; ++f)
        columns.push_back((row / dim) * dim + f);
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    return columns;
  }


  template <int dim>
  UpdatedLU::Row
  CondensedSystem<dim>::sparse_row(
    const std::vector<PairEquation<dim>> &equations,
    const std::vector<bool>              &active,
    const unsigned int                    row) const
  {
    const unsigned int n_r = n_pairs * dim;
    UpdatedLU::Row     entries;
    if (row >= n_r)
      {
        // Equilibrium of the floating blocks: P^T r = -F_e.
        return coupling_columns[row - n_r];
      }
    if (!active[row])
      return {{row, 1.}};

    // The terms of assemble()'s row, every pair direction a column.
    const unsigned int       k  = row / dim;
    const PairEquation<dim> &eq = equations[row];
    const double row_scale      = eq.has_force_terms() ? flexibility_scale : 1.;
    for (unsigned int e = 0; e < dim; ++e)
      {
        const double a = eq.displacement_coefficients[e];
        if (a != 0.)
          {
            for (const auto &[b, s] : pair_sides[k])
              {
                const BlockFlexibility &flexibility = block_flexibility[b];
                for (unsigned int t = 0; t < flexibility.pairs.size(); ++t)
                  for (unsigned int f = 0; f < dim; ++f)
                    {
                      // H_b(s e, t f) as assemble() and
                      // relative_displacement() read it; on demand not
                      // where column t f was not computed: a pair left
                      // out, whose unknowns are x_i = 0 (under mpirun the
                      // other ranks hold no row of it either). A column
                      // computed later makes a new base (base_columns).
                      if (flexibility.on_demand &&
                          flexibility.columns[t * dim + f].empty())
                        continue;
                      const double h = flexibility(s * dim + e, t * dim + f);
                      entries.emplace_back(flexibility.pairs[t] * dim + f,
                                           row_scale * a * h /
                                             flexibility_scale);
                    }
              }
            for (const auto &[b, p] : coupling_rows[k * dim + e])
              entries.emplace_back(n_r + b, row_scale * a * p);
          }
        if (eq.force_coefficients[e] != 0.)
          entries.emplace_back(k * dim + e, eq.force_coefficients[e]);
      }
    // Columns increasing, each sum in the order its terms came.
    std::stable_sort(entries.begin(),
                     entries.end(),
                     [](const auto &x, const auto &y) {
                       return x.first < y.first;
                     });
    UpdatedLU::Row merged;
    for (const auto &[column, value] : entries)
      if (!merged.empty() && merged.back().first == column)
        merged.back().second += value;
      else
        merged.emplace_back(column, value);
    return merged;
  }


  template <int dim>
  void
  CondensedSystem<dim>::estimate_sparse_condition(Factorisation &system) const
  {
    // estimate_condition()'s probes on the unknowns left free (zero on the
    // removed ones), its norm over their columns: the estimate of the dense
    // system. Rows replaced in a regular base: regular where the bound of
    // the condition number says so, a hundred times below the limit.
    system.regular =
      system.sparse->rank() > 0 && system.sparse->condition_bound() < 1e10;
    if (system.regular)
      return;
    const unsigned int        n_r           = n_pairs * dim;
    const unsigned int        n             = system.size;
    std::vector<unsigned int> free_unknowns = system.unknowns;
    for (unsigned int a = 0; a < coupling.n_modes(); ++a)
      free_unknowns.push_back(n_r + a);
    std::vector<bool> columns(n, false);
    for (const unsigned int j : free_unknowns)
      columns[j] = true;
    const double norm = system.sparse->l1_norm(columns);
    const double inverse_norm =
      inverse_norm_estimate(n, free_unknowns, [&](Vector<double> &x) {
        system.sparse->solve(x, false);
      });
    system.regular = std::isfinite(norm) && norm * inverse_norm < 1e12;
  }


  template <int dim>
  bool
  CondensedSystem<dim>::solve_sparse(
    const std::vector<PairEquation<dim>> &equations,
    Factorisation                        &system,
    Vector<double>                       &x) const
  {
    // The factors of the base with rows replaced are accurate where S is
    // well conditioned, which replace_rows() checked; a backward error
    // above 1e-10 (a backward stable solve gives 1e-16) means they were
    // not, and the system is factorised itself.
    const Vector<double> b = x;
    if (system.sparse->solve(x) <= 1e-10 || system.sparse->rank() == 0)
      return true;
    system.base_coefficients.clear();
    assemble_sparse(equations, system);
    if (!system.regular)
      return false;
    x = b;
    system.sparse->solve(x);
    return true;
  }


  template <int dim>
  void
  CondensedSystem<dim>::add_row(
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
              if (column < 0)
                continue;
              // request_columns() computed it (on the block's owner,
              // which sent it to every rank).
              Assert(!flexibility.on_demand ||
                       !flexibility.columns[t * dim + f].empty(),
                     ExcInternalError());
              add(column,
                  factor * flexibility(s * dim + e, t * dim + f) /
                    flexibility_scale);
            }
      }
  }


  namespace
  {
    /**
     * d at the pair directions of a block's sides += @p values (side s,
     * direction i at s * dim + i; none where empty).
     */
    template <int dim, typename Values>
    void
    add_at_sides(const std::vector<unsigned int> &pairs,
                 const Values                    &values,
                 Vector<double>                  &d)
    {
      for (unsigned int r = 0; r < values.size(); ++r)
        d(pairs[r / dim] * dim + r % dim) += values[r];
    }
  } // namespace



  template <int dim>
  Vector<double>
  CondensedSystem<dim>::relative_displacement(const Vector<double> &solution,
                                              const IncrementLoads &loads) const
  {
    const unsigned int n_r = n_pairs * dim;
    Vector<double>     d(loads.displacement);
    for (unsigned int i = 0; i < n_r; ++i)
      for (const auto &[a, p] : coupling_rows[i])
        d(i) += p * solution(n_r + a);
    // C_hat rho block by block, over the sides whose force is not zero.
    std::vector<unsigned int> forced;
    for (unsigned int i = 0; i < n_r; ++i)
      if (solution(i) != 0.)
        forced.push_back(i);
    request_columns(forced);
    if (Parallel::n_ranks() == 1 ||
        std::none_of(block_flexibility.begin(),
                     block_flexibility.end(),
                     [](const auto &flexibility) {
                       return flexibility.on_demand != nullptr;
                     }))
      {
        for (const auto &flexibility : block_flexibility)
          add_block_displacement(flexibility, solution, d);
        return d;
      }
    // Under mpirun an on-demand block's H_b f comes from its owner (the
    // others hold its columns at the kept rows only), computed as on one
    // rank, and every block's is added in the same order as there.
    const unsigned int               n_blocks = block_flexibility.size();
    std::vector<std::vector<double>> from_owner(n_blocks);
    Parallel::together(MPI_COMM_WORLD, [&]() {
      for (unsigned int b = 0; b < n_blocks; ++b)
        if (block_flexibility[b].on_demand)
          from_owner[b] = block_displacement(block_flexibility[b], solution);
    });
    for (unsigned int b = 0; b < n_blocks; ++b)
      {
        const BlockFlexibility &flexibility = block_flexibility[b];
        if (!flexibility.on_demand)
          {
            add_block_displacement(flexibility, solution, d);
            continue;
          }
        Parallel::broadcast(flexibility.communicator,
                            flexibility.owner,
                            from_owner[b].data(),
                            from_owner[b].size());
        add_at_sides<dim>(flexibility.pairs, from_owner[b], d);
      }
    return d;
  }



  template <int dim>
  void
  CondensedSystem<dim>::add_block_displacement(
    const BlockFlexibility &flexibility,
    const Vector<double>   &solution,
    Vector<double>         &d) const
  {
    const unsigned int n_sides  = flexibility.pairs.size();
    unsigned int       n_forced = 0;
    for (unsigned int t = 0; t < n_sides; ++t)
      for (unsigned int j = 0; j < dim; ++j)
        n_forced += (solution(flexibility.pairs[t] * dim + j) != 0.);
    if (n_forced == 0)
      return;
    if (!flexibility.on_demand && 4 * n_forced >= n_sides * dim)
      {
        // H_b f by BLAS (H_b's rows are contiguous: the column-major
        // H_b^T).
        const types::blas_int n = n_sides * dim, one = 1;
        if (n == 0)
          return;
        Vector<double> f(n), value(n);
        for (unsigned int t = 0; t < n_sides; ++t)
          for (unsigned int j = 0; j < dim; ++j)
            f(t * dim + j) = solution(flexibility.pairs[t] * dim + j);
        const double alpha = 1., beta = 0.;
        gemv("T",
             &n,
             &n,
             &alpha,
             &flexibility.matrix(0, 0),
             &n,
             f.begin(),
             &one,
             &beta,
             value.begin(),
             &one);
        add_at_sides<dim>(flexibility.pairs, value, d);
        return;
      }
    // Few forced sides, or columns on demand: the forced columns only.
    add_at_sides<dim>(flexibility.pairs,
                      block_displacement(flexibility, solution),
                      d);
  }



  template <int dim>
  std::vector<double>
  CondensedSystem<dim>::block_displacement(const BlockFlexibility &flexibility,
                                           const Vector<double> &solution) const
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
    if (columns.empty())
      return {};
    std::vector<double> value(n_sides * dim, 0.);
    if (flexibility.compact)
      return value; // the owner's, from relative_displacement()
    for (unsigned int r = 0; r < value.size(); ++r)
      for (unsigned int c = 0; c < columns.size(); ++c)
        value[r] += flexibility(r, columns[c]) * forces[c];
    return value;
  }



  template class CondensedSystem<2>;
  template class CondensedSystem<3>;
} // namespace mbfem

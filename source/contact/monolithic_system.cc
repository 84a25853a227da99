#include <mbfem/base/exceptions.h>
#include <mbfem/contact/monolithic_system.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cmath>
#include <map>
#include <set>

namespace mbfem
{
  namespace
  {
    /**
     * A block's stiffness under its physical constraints alone, without
     * pins, so singular for a floating block (its free modes are held by
     * the contact multipliers of the whole system instead). Constrained
     * rows keep a diagonal entry.
     */
    template <int dim>
    void
    unpinned_stiffness(const Block<dim>     &block,
                       SparsityPattern      &pattern,
                       SparseMatrix<double> &matrix)
    {
      const AffineConstraints<double> &constraints =
        block.get_physical_constraints();
      DynamicSparsityPattern dsp(block.n_dofs());
      DoFTools::make_sparsity_pattern(block.get_dof_handler(),
                                      dsp,
                                      constraints,
                                      false);
      pattern.copy_from(dsp);
      matrix.reinit(pattern);
      block.assemble_matrix(constraints, matrix);
    }
  } // namespace



  template <int dim>
  MonolithicSystem<dim>::MonolithicSystem(
    const std::vector<ContactPair<dim>> &contact_pairs,
    const std::string                   &solver_package)
    : pairs(contact_pairs)
    , solver(solver_package)
  {}



  template <int dim>
  void
  MonolithicSystem<dim>::setup(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks)
  {
    std::vector<SparsityPattern>      patterns(blocks.size());
    std::vector<SparseMatrix<double>> stiffness(blocks.size());
    assemble_blocks(blocks, patterns, stiffness);
    make_relative_displacements(blocks, true);
    make_pattern(patterns);
    add_fixed_entries(stiffness);
    load.reinit(n_displacements);
  }



  template <int dim>
  void
  MonolithicSystem<dim>::assemble_blocks(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    std::vector<SparsityPattern>                   &patterns,
    std::vector<SparseMatrix<double>>              &stiffness)
  {
    offset.assign(blocks.size(), 0);
    n_displacements     = 0;
    double       trace  = 0.;
    unsigned int n_free = 0;
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        offset[b] = n_displacements;
        n_displacements += blocks[b]->n_dofs();
        unpinned_stiffness(*blocks[b], patterns[b], stiffness[b]);
        const auto &constraints = blocks[b]->get_physical_constraints();
        for (types::global_dof_index i = 0; i < blocks[b]->n_dofs(); ++i)
          if (!constraints.is_constrained(i))
            {
              trace += stiffness[b].diag_element(i);
              ++n_free;
            }
      }
    stiffness_scale = (n_free > 0 && trace > 0. ? trace / n_free : 1.);
  }



  template <int dim>
  void
  MonolithicSystem<dim>::make_pattern(
    const std::vector<SparsityPattern> &patterns)
  {
    // The pattern: the blocks' stiffnesses on the diagonal; each pair's
    // dim rows couple to every displacement its d depends on and to its own
    // dim forces (a slip row mixes the pair's components); G^T mirrors them.
    const types::global_dof_index n_rows = size();
    DynamicSparsityPattern        dsp(n_rows);
    for (unsigned int b = 0; b < patterns.size(); ++b)
      for (auto entry = patterns[b].begin(); entry != patterns[b].end();
           ++entry)
        dsp.add(offset[b] + entry->row(), offset[b] + entry->column());
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        std::set<types::global_dof_index> columns;
        for (unsigned int e = 0; e < dim; ++e)
          for (const auto &term : terms[k * dim + e])
            columns.insert(term.column);
        for (unsigned int i = 0; i < dim; ++i)
          {
            const types::global_dof_index row = n_displacements + k * dim + i;
            for (const auto column : columns)
              dsp.add(row, column);
            for (unsigned int e = 0; e < dim; ++e)
              dsp.add(row, n_displacements + k * dim + e);
            for (const auto &term : terms[k * dim + i])
              dsp.add(term.column, row);
          }
      }
    matrix.reinit(complete_index_set(n_rows),
                  complete_index_set(n_rows),
                  dsp,
                  MPI_COMM_SELF);
  }



  template <int dim>
  void
  MonolithicSystem<dim>::add_fixed_entries(
    const std::vector<SparseMatrix<double>> &stiffness)
  {
    // What does not change with the states: K, and -G^T in the
    // displacement rows (K u - G^T rho = f, rho = ks y). solve() rewrites
    // only the pairs' rows.
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    for (unsigned int b = 0; b < stiffness.size(); ++b)
      for (types::global_dof_index i = 0; i < stiffness[b].m(); ++i)
        {
          columns.clear();
          values.clear();
          for (auto entry = stiffness[b].begin(i); entry != stiffness[b].end(i);
               ++entry)
            {
              columns.push_back(offset[b] + entry->column());
              values.push_back(entry->value());
            }
          matrix.add(offset[b] + i,
                     columns.size(),
                     columns.data(),
                     values.data());
        }
    for (unsigned int r = 0; r < terms.size(); ++r)
      for (const auto &term : terms[r])
        matrix.add(term.column,
                   n_displacements + r,
                   -stiffness_scale * term.coefficient);
    matrix.compress(VectorOperation::add);
  }



  template <int dim>
  void
  MonolithicSystem<dim>::make_relative_displacements(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    const bool                                      with_terms)
  {
    if (with_terms)
      terms.assign(pairs.size() * dim, {});
    constant.assign(pairs.size() * dim, 0.);
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        const auto &pair = pairs[k];
        for (const int sign : {-1, 1})
          for (const auto &node : pair.side(sign).nodes)
            {
              const unsigned int b    = pair.side(sign).block;
              const auto        &dofs = node.dofs;
              const auto &constraints = blocks[b]->get_physical_constraints();
              for (unsigned int c = 0; c < dim; ++c)
                {
                  // u at the pair's node through the constraints:
                  // u_i = sum_j c_ij u_j + inhomogeneity.
                  std::vector<std::pair<types::global_dof_index, double>> u_i;
                  double u_0 = 0.;
                  if (constraints.is_constrained(dofs[c]))
                    {
                      u_i = *constraints.get_constraint_entries(dofs[c]);
                      u_0 = constraints.get_inhomogeneity(dofs[c]);
                    }
                  else
                    u_i.emplace_back(dofs[c], 1.);
                  for (unsigned int i = 0; i < dim; ++i)
                    {
                      const double weight =
                        sign * node.weight * pair.frame[i][c];
                      if (weight == 0.)
                        continue;
                      if (with_terms)
                        for (const auto &[j, c_ij] : u_i)
                          terms[k * dim + i].push_back(
                            {offset[b] + j, weight * c_ij});
                      constant[k * dim + i] += weight * u_0;
                    }
                }
            }
        // Merge repeated columns (both nodes tied to one platen master).
        for (unsigned int i = 0; i < dim && with_terms; ++i)
          {
            std::map<types::global_dof_index, double> merged;
            for (const auto &term : terms[k * dim + i])
              merged[term.column] += term.coefficient;
            terms[k * dim + i].clear();
            for (const auto &[column, coefficient] : merged)
              if (coefficient != 0.)
                terms[k * dim + i].push_back({column, coefficient});
          }
      }
  }



  template <int dim>
  void
  MonolithicSystem<dim>::set_load(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    IncrementLoads                                 &loads)
  {
    // Delta_F is the condensed system's: here the loads enter the blocks'
    // rows.
    loads.displacement.reinit(pairs.size() * dim);
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        const Vector<double> &f = blocks[b]->get_physical_load();
        for (types::global_dof_index i = 0; i < f.size(); ++i)
          load(offset[b] + i) = f(i);
      }
    // Prescribed values change with time, and with them the constants g;
    // the terms follow the constraints' structure, which does not.
    make_relative_displacements(blocks, false);
  }



  template <int dim>
  std::vector<std::array<bool, dim>>
  MonolithicSystem<dim>::held() const
  {
    std::vector<std::array<bool, dim>> result(pairs.size());
    for (unsigned int k = 0; k < pairs.size(); ++k)
      for (unsigned int i = 0; i < dim; ++i)
        {
          double largest = 0.;
          for (const auto &term : terms[k * dim + i])
            largest = std::max(largest, std::abs(term.coefficient));
          result[k][i] = largest < 1e-12;
        }
    return result;
  }



  template <int dim>
  bool
  MonolithicSystem<dim>::solve(const std::vector<PairEquation<dim>> &equations,
                               const IncrementLoads &,
                               Vector<double> &forces,
                               Vector<double> &displacement)
  {
    AssertDimension(equations.size(), pairs.size() * dim);
    const types::global_dof_index n_rows = size();
    const double                  ks     = stiffness_scale;
    Vector<double>                rhs(n_rows);

    // The pairs' rows are those of this trial's states; the rest was
    // assembled in setup().
    std::vector<types::global_dof_index> pair_rows(equations.size());
    for (unsigned int r = 0; r < equations.size(); ++r)
      pair_rows[r] = n_displacements + r;
    matrix.clear_rows(pair_rows);
    for (types::global_dof_index i = 0; i < n_displacements; ++i)
      rhs(i) = load(i);

    for (unsigned int r = 0; r < equations.size(); ++r)
      {
        const unsigned int            k   = r / dim;
        const types::global_dof_index row = n_displacements + r;
        const PairEquation<dim>      &eq  = equations[r];

        // force . rho + displacement . (G u + g) = value; a row without
        // force terms is multiplied by ks to match the stiffness rows.
        const double row_scale = (eq.has_force_terms() ? 1. : ks);
        double       value     = eq.value;
        for (unsigned int e = 0; e < dim; ++e)
          {
            const double a = eq.displacement_coefficients[e];
            if (a != 0.)
              {
                for (const auto &term : terms[k * dim + e])
                  matrix.add(row,
                             term.column,
                             row_scale * a * term.coefficient);
                value -= a * constant[k * dim + e];
              }
            if (eq.force_coefficients[e] != 0.)
              matrix.add(row,
                         n_displacements + k * dim + e,
                         ks * eq.force_coefficients[e]);
          }
        rhs(row) = row_scale * value;
      }
    matrix.compress(VectorOperation::add);

    solution.reinit(n_rows);
    try
      {
        solver.factorize(matrix);
        solver.solve(solution, rhs);
      }
    catch (const Exceptions::ExcSingularMatrix &)
      {
        return false;
      }
    if (!std::isfinite(solution.l2_norm()))
      return false;

    const unsigned int n_r = pairs.size() * dim;
    forces.reinit(n_r);
    displacement.reinit(n_r);
    for (unsigned int r = 0; r < n_r; ++r)
      {
        forces(r) = ks * solution(n_displacements + r);
        double d  = constant[r];
        for (const auto &term : terms[r])
          d += term.coefficient * solution(term.column);
        displacement(r) = d;
      }
    return true;
  }



  template <int dim>
  void
  MonolithicSystem<dim>::block_solution(const unsigned int b,
                                        const Block<dim>  &block,
                                        Vector<double>    &u) const
  {
    u.reinit(block.n_dofs());
    for (types::global_dof_index i = 0; i < u.size(); ++i)
      u(i) = solution(offset[b] + i);
    block.get_physical_constraints().distribute(u);
  }



  template <int dim>
  types::global_dof_index
  MonolithicSystem<dim>::size() const
  {
    return n_displacements + pairs.size() * dim;
  }



  template class MonolithicSystem<2>;
  template class MonolithicSystem<3>;
} // namespace mbfem

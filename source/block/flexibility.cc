#include <mbfem/block/flexibility.h>
#include <mbfem/linear_algebra/mumps_solver.h>

#include <algorithm>
#include <map>
#include <set>

namespace mbfem
{
  namespace
  {
    /**
     * Each contact DoF as a combination of unconstrained DoFs (masters):
     * weights[i] = (index into masters, weight) for dofs[i].
     */
    struct Masters
    {
      Masters(const AffineConstraints<double>            &constraints,
              const std::vector<types::global_dof_index> &dofs)
        : weights(dofs.size())
      {
        std::map<types::global_dof_index, unsigned int> master_index;
        const auto add_master = [&](const types::global_dof_index dof) {
          const auto [it, inserted] =
            master_index.emplace(dof, master_dofs.size());
          if (inserted)
            master_dofs.push_back(dof);
          return it->second;
        };
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto *entries = constraints.get_constraint_entries(dofs[i]);
            if (!constraints.is_constrained(dofs[i]))
              weights[i].emplace_back(add_master(dofs[i]), 1.);
            else if (entries != nullptr)
              for (const auto &[dof, weight] : *entries)
                weights[i].emplace_back(add_master(dof), weight);
          }
      }

      std::vector<unsigned int>                                 master_dofs;
      std::vector<std::vector<std::pair<unsigned int, double>>> weights;
    };
  } // namespace



  FullMatrix<double>
  contact_flexibility(const TrilinosWrappers::SparseMatrix       &stiffness,
                      const AffineConstraints<double>            &constraints,
                      const std::vector<types::global_dof_index> &dofs,
                      const bool positive_definite)
  {
    const Masters                    map(constraints, dofs);
    const std::vector<unsigned int> &masters = map.master_dofs;
    const auto                      &weights = map.weights;

    const std::size_t  m = dofs.size();
    FullMatrix<double> result(m, m);
    if (masters.empty())
      return result;

    MumpsSolver solver;
    solver.factorize(stiffness, positive_definite);
    const FullMatrix<double> inverse = solver.inverse_entries(masters, masters);

    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        {
          double value = 0.;
          for (const auto &[a, wa] : weights[i])
            for (const auto &[b, wb] : weights[j])
              value += wa * wb * inverse(a, b);
          result(i, j) = value;
        }
    return result;
  }



  ContactFlexibility::ContactFlexibility(
    std::shared_ptr<const MumpsSolver>          factorisation,
    const AffineConstraints<double>            &constraints,
    const std::vector<types::global_dof_index> &dofs)
    : solver(std::move(factorisation))
  {
    Masters map(constraints, dofs);
    master_dofs = std::move(map.master_dofs);
    weights     = std::move(map.weights);
  }



  ContactFlexibility::~ContactFlexibility() = default;



  bool
  ContactFlexibility::is_local() const
  {
    return solver != nullptr;
  }



  unsigned int
  ContactFlexibility::size() const
  {
    return weights.size();
  }



  std::map<unsigned int, double>
  ContactFlexibility::on_masters(const ContactLoad &load) const
  {
    std::map<unsigned int, double> result;
    for (const auto &[i, w] : load)
      for (const auto &[a, wa] : weights[i])
        result[a] += w * wa;
    return result;
  }



  bool
  ContactFlexibility::moves(const ContactLoad &load) const
  {
    for (const auto &[a, w] : on_masters(load))
      if (w != 0.)
        return true;
    return false;
  }



  std::vector<double>
  ContactFlexibility::forms(const std::vector<ContactLoad> &loads) const
  {
    // For each master column, the master rows some pattern pairs it with.
    std::vector<std::map<unsigned int, double>> patterns;
    std::vector<std::set<unsigned int>>         rows_of(solver->size());
    for (const auto &load : loads)
      {
        patterns.push_back(on_masters(load));
        for (const auto &[a, wa] : patterns.back())
          for (const auto &[b, wb] : patterns.back())
            rows_of[master_dofs[a]].insert(master_dofs[b]);
      }
    std::vector<std::vector<unsigned int>> rows(rows_of.size());
    for (unsigned int j = 0; j < rows_of.size(); ++j)
      rows[j].assign(rows_of[j].begin(), rows_of[j].end());
    rows_of.clear();
    const std::vector<std::vector<double>> entries =
      solver->inverse_entries(rows);
    const auto inverse = [&](const unsigned int i, const unsigned int j) {
      const auto &column = rows[j];
      const auto  p      = std::lower_bound(column.begin(), column.end(), i);
      return entries[j][p - column.begin()];
    };

    std::vector<double> result(loads.size(), 0.);
    for (unsigned int l = 0; l < loads.size(); ++l)
      for (const auto &[a, wa] : patterns[l])
        for (const auto &[b, wb] : patterns[l])
          result[l] += wa * wb * inverse(master_dofs[b], master_dofs[a]);
    return result;
  }



  FullMatrix<double>
  ContactFlexibility::columns(const std::vector<ContactLoad> &loads) const
  {
    // K^{-1} over all masters (rows) and the masters the patterns load
    // (columns), then C s = T K^{-1} T^T s.
    std::vector<std::map<unsigned int, double>> patterns;
    std::map<unsigned int, unsigned int>        column_of;
    std::vector<unsigned int>                   loaded;
    for (const auto &load : loads)
      {
        patterns.push_back(on_masters(load));
        for (const auto &[a, wa] : patterns.back())
          if (column_of.emplace(a, loaded.size()).second)
            loaded.push_back(master_dofs[a]);
      }
    const FullMatrix<double> inverse =
      solver->inverse_entries(master_dofs, loaded);

    FullMatrix<double> result(size(), loads.size());
    for (unsigned int l = 0; l < loads.size(); ++l)
      for (unsigned int i = 0; i < size(); ++i)
        {
          double value = 0.;
          for (const auto &[a, wa] : weights[i])
            for (const auto &[b, wb] : patterns[l])
              value += wa * wb * inverse(a, column_of.at(b));
          result(i, l) = value;
        }
    return result;
  }
} // namespace mbfem

#include <mbfem/block/flexibility.h>
#include <mbfem/linear_algebra/mumps_solver.h>

#include <map>

namespace mbfem
{
  FullMatrix<double>
  contact_flexibility(const TrilinosWrappers::SparseMatrix       &stiffness,
                      const AffineConstraints<double>            &constraints,
                      const std::vector<types::global_dof_index> &dofs,
                      const bool positive_definite)
  {
    // Each contact DoF as a combination of unconstrained DoFs (masters).
    std::map<types::global_dof_index, unsigned int>           master_index;
    std::vector<unsigned int>                                 masters;
    std::vector<std::vector<std::pair<unsigned int, double>>> weights(
      dofs.size());
    const auto add_master = [&](const types::global_dof_index dof) {
      const auto [it, inserted] = master_index.emplace(dof, masters.size());
      if (inserted)
        masters.push_back(dof);
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
} // namespace mbfem

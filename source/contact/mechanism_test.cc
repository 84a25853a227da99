#include <mbfem/block/block.h>
#include <mbfem/contact/mechanism_test.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mbfem
{
  namespace
  {
    /**
     * The null space of the positive semi-definite Gram matrix @p gram of
     * the constraints on the floating modes: its eigenvectors whose
     * eigenvalues are below 1e-10 times its largest diagonal entry (at
     * least @p floor), into the columns of @p vectors; returns how many.
     */
    unsigned int
    null_space(LAPACKFullMatrix<double> &gram,
               const double              floor,
               FullMatrix<double>       &vectors)
    {
      double largest = floor;
      for (unsigned int a = 0; a < gram.m(); ++a)
        largest = std::max(largest, gram(a, a));
      Vector<double> eigenvalues;
      gram.compute_eigenvalues_symmetric(
        -1., 1e-10 * largest, 1e-14, eigenvalues, vectors);
      return eigenvalues.size();
    }
  } // namespace



  template <int dim>
  MechanismTest<dim>::MechanismTest(
    const std::vector<ContactPair<dim>>      &pairs,
    const std::vector<std::array<bool, dim>> &held,
    const IncrementLoads                     &loads,
    const RigidCoupling<dim>                 &coupling)
    : pairs(pairs)
    , held(held)
    , loads(loads)
    , coupling(coupling)
  {}



  template <int dim>
  std::string
  MechanismTest<dim>::diagnose_singular(const Trial &trial) const
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
  MechanismTest<dim>::unheld_blocks(const Trial &trial) const
  {
    std::ostringstream message;
    for (unsigned int b = 0; b < coupling.n_blocks(); ++b)
      {
        const unsigned int q = coupling.n_modes(b);
        if (q == 0)
          continue;
        // The directions in which the block's pairs can push, given their
        // states; the block is held iff they span its q free modes.
        std::vector<std::vector<double>> columns;
        unsigned int                     counts[3] = {0, 0, 0};
        for (unsigned int k = 0; k < pairs.size(); ++k)
          {
            bool touches = false;
            for (unsigned int a = 0; a < q; ++a)
              for (unsigned int d = 0; d < dim; ++d)
                if (std::abs(coupling(k * dim + d, coupling.offset(b) + a)) >
                    0.)
                  touches = true;
            if (!touches)
              continue;
            ++counts[static_cast<int>(trial.state[k])];
            if (trial.state[k] == ContactState::open)
              continue;
            const double mu = pairs[k]
                                .joint
                                .slip_line(pairs[k].area,
                                           trial.broken[k],
                                           trial.tensile_slip[k])
                                .slope;
            for (unsigned int d = 0; d < dim; ++d)
              {
                if (held[k][d] ||
                    (trial.state[k] == ContactState::slip && d > 0))
                  continue;
                std::vector<double> column(q);
                for (unsigned int a = 0; a < q; ++a)
                  {
                    column[a] = coupling(k * dim + d, coupling.offset(b) + a);
                    if (trial.state[k] == ContactState::slip)
                      for (unsigned int e = 1; e < dim; ++e)
                        column[a] -=
                          mu * trial.slip_direction[k][e] *
                          coupling(k * dim + e, coupling.offset(b) + a);
                  }
                columns.push_back(column);
              }
          }
        LAPACKFullMatrix<double> gram(q, q);
        for (const auto &column : columns)
          for (unsigned int a = 0; a < q; ++a)
            for (unsigned int c = 0; c < q; ++c)
              gram(a, c) += column[a] * column[c];
        FullMatrix<double> eigenvectors;
        const unsigned int n_free = null_space(gram, 1., eigenvectors);
        if (n_free == 0)
          continue;
        message << "\n    " << coupling.block_name(b)
                << " cannot be in equilibrium: its contact pairs (" << counts[0]
                << " stick, " << counts[1] << " slip, " << counts[2]
                << " open) cannot hold its rigid-body motion";
        for (unsigned int v = 0; v < n_free; ++v)
          {
            Vector<double> combination(coupling.modes(b)[0].size());
            for (unsigned int a = 0; a < q; ++a)
              combination.add(eigenvectors(a, v), coupling.modes(b)[a]);
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
  Vector<double>
  MechanismTest<dim>::motion(const Trial &trial) const
  {
    if (coupling.n_modes() == 0)
      return Vector<double>();
    // The rows that fix a rigid motion: normal at a closed pair,
    // tangential at a stuck one.
    std::vector<unsigned int> rows;
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        const bool stuck =
          trial.state[k] == ContactState::stick || pairs[k].tied;
        if (trial.state[k] == ContactState::open && !pairs[k].tied)
          continue;
        for (unsigned int d = 0; d < dim; ++d)
          if (!held[k][d] && (d == 0 || stuck))
            rows.push_back(k * dim + d);
      }
    const unsigned int       q = coupling.n_modes();
    LAPACKFullMatrix<double> gram(q, q);
    // A row of P_hat couples the modes of the (at most two) blocks of its
    // pair only: add the products of its non-zero entries.
    std::vector<std::pair<unsigned int, double>> entries;
    for (const unsigned int row : rows)
      {
        entries.clear();
        for (const auto &[a, value] : coupling.row(row))
          if (value != 0.)
            entries.emplace_back(a, value);
        for (const auto &[a, x] : entries)
          for (const auto &[c, y] : entries)
            gram(a, c) += x * y;
      }
    FullMatrix<double> free;
    const unsigned int n_free = null_space(gram, 1e-300, free);
    if (n_free == 0)
      return Vector<double>();

    // Of the free motions, the one the loads drive (their work on the
    // modes, projected on the free space); a free motion they do no work
    // on is named as it is.
    Vector<double> motion(q);
    for (unsigned int v = 0; v < n_free; ++v)
      {
        double work = 0.;
        for (unsigned int a = 0; a < q; ++a)
          work += loads.resultant[a] * free(a, v);
        for (unsigned int a = 0; a < q; ++a)
          motion(a) += work * free(a, v);
      }
    if (motion.l2_norm() < 1e-8 * std::max(1e-300, [&] {
                             double f = 0.;
                             for (const double x : loads.resultant)
                               f += x * x;
                             return std::sqrt(f);
                           }()))
      for (unsigned int a = 0; a < q; ++a)
        motion(a) = free(a, 0);
    return motion;
  }


  template <int dim>
  std::string
  MechanismTest<dim>::describe(const Trial &trial) const
  {
    const Vector<double> motion = this->motion(trial);
    if (motion.size() == 0)
      return "";
    std::ostringstream message;
    for (unsigned int b = 0; b < coupling.n_blocks(); ++b)
      {
        Vector<double> combination(
          coupling.n_modes(b) > 0 ? coupling.modes(b)[0].size() : 0);
        for (unsigned int a = 0; a < coupling.n_modes(b); ++a)
          combination.add(motion(coupling.offset(b) + a), coupling.modes(b)[a]);
        if (coupling.n_modes(b) == 0 ||
            combination.linfty_norm() < 1e-6 * motion.linfty_norm())
          continue;
        combination /= combination.linfty_norm();
        unsigned int counts[3] = {0, 0, 0};
        for (unsigned int k = 0; k < pairs.size(); ++k)
          {
            bool touches = false;
            for (unsigned int a = 0; a < coupling.n_modes(b); ++a)
              for (unsigned int d = 0; d < dim; ++d)
                if (coupling(k * dim + d, coupling.offset(b) + a) != 0.)
                  touches = true;
            if (touches)
              ++counts[static_cast<int>(trial.state[k])];
          }
        message << "\n    " << coupling.block_name(b)
                << " cannot be in equilibrium: its contact pairs (" << counts[0]
                << " stick, " << counts[1] << " slip, " << counts[2]
                << " open) cannot hold its rigid-body motion ["
                << Block<dim>::describe_rigid_body_mode(combination)
                << "]: the loads exceed what friction and cohesion can carry, "
                   "or the block has lost contact.";
      }
    return message.str();
  }


  template class MechanismTest<2>;
  template class MechanismTest<3>;
} // namespace mbfem

#include <mbfem/contact/rigid_coupling.h>

#include <array>
#include <utility>

namespace mbfem
{
  template <int dim>
  void
  RigidCoupling<dim>::setup(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    const std::vector<ContactPair<dim>>            &pairs,
    const std::vector<bool>                        &present)
  {
    AssertThrow(present.empty() || present.size() == blocks.size(),
                ExcInternalError());
    const auto modes_of =
      [&](const unsigned int b) -> const std::vector<Vector<double>> & {
      static const std::vector<Vector<double>> none;
      return (present.empty() || present[b]) ? blocks[b]->floating_modes() :
                                               none;
    };
    first_mode.assign(blocks.size(), 0);
    block_modes.assign(blocks.size(), 0);
    total = 0;
    names.clear();
    mode_vectors.clear();
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        first_mode[b]  = total;
        block_modes[b] = modes_of(b).size();
        total += block_modes[b];
        names.push_back(blocks[b]->name());
        mode_vectors.push_back(block_modes[b] == 0 ?
                                 std::vector<Vector<double>>() :
                                 blocks[b]->free_rigid_body_modes());
      }

    p_hat = rows_of(blocks, pairs);
  }



  template <int dim>
  CouplingRows
  RigidCoupling<dim>::rows_of(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    const std::vector<ContactPair<dim>>            &pairs) const
  {
    const auto modes_of =
      [&](const unsigned int b) -> const std::vector<Vector<double>> & {
      static const std::vector<Vector<double>> none;
      return block_modes[b] > 0 ? blocks[b]->floating_modes() : none;
    };
    // P in global axes, pair by pair: a side's displacement is sum_i w_i
    // u(node_i), the force r_k on block b and -r_k on block a, hence the
    // sign; then into the pair's frame. Only the modes of the pair's two
    // blocks, the block with the lower amplitudes first. A pair whose two
    // sides are on one block (the arms of a U facing each other) gets one
    // entry per mode, the two sides' sums added, as a dense P_hat had.
    CouplingRows rows;
    rows.reinit(total);
    std::vector<CouplingRows::Entry> row;
    for (const auto &pair : pairs)
      {
        std::array<int, 2> signs = {{-1, 1}};
        if (first_mode[pair.b.block] < first_mode[pair.a.block])
          std::swap(signs[0], signs[1]);
        const bool one_block = (pair.a.block == pair.b.block);
        std::vector<std::array<double, dim>> global; // per mode, per axis
        std::vector<unsigned int>            mode_index;
        for (const int sign : signs)
          {
            const auto &side  = pair.side(sign);
            const auto &modes = modes_of(side.block);
            for (unsigned int a = 0; a < modes.size(); ++a)
              {
                const bool again = one_block && sign == signs[1];
                if (!again)
                  {
                    global.push_back({});
                    mode_index.push_back(first_mode[side.block] + a);
                  }
                std::array<double, dim> &p =
                  global[again ? a : global.size() - 1];
                for (const auto &node : side.nodes)
                  for (unsigned int c = 0; c < dim; ++c)
                    p[c] += sign * node.weight * modes[a](node.dofs[c]);
              }
          }
        for (unsigned int i = 0; i < dim; ++i)
          {
            row.clear();
            for (unsigned int m = 0; m < global.size(); ++m)
              {
                double value = 0.;
                for (unsigned int c = 0; c < dim; ++c)
                  value += pair.frame[i][c] * global[m][c];
                row.emplace_back(mode_index[m], value);
              }
            rows.add_row(row);
          }
      }
    return rows;
  }



  template <int dim>
  std::vector<double>
  RigidCoupling<dim>::load_resultant(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks) const
  {
    std::vector<double> resultant(total, 0.);
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        if (block_modes[b] == 0)
          continue;
        const auto block_resultant = blocks[b]->external_load_resultant();
        for (unsigned int a = 0; a < block_resultant.size(); ++a)
          resultant[first_mode[b] + a] = block_resultant[a];
      }
    return resultant;
  }



  template class RigidCoupling<2>;
  template class RigidCoupling<3>;
} // namespace mbfem

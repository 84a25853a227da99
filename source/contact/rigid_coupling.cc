#include <mbfem/contact/rigid_coupling.h>

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

    // P in global axes: a side's displacement is sum_i w_i u(node_i), the
    // force r_k on block b and -r_k on block a, hence the sign.
    const unsigned int n_r = pairs.size() * dim;
    FullMatrix<double> p_global(n_r, total);
    for (unsigned int b = 0; b < blocks.size(); ++b)
      {
        const auto &modes = modes_of(b);
        for (unsigned int k = 0; k < pairs.size() && !modes.empty(); ++k)
          for (const int sign : {-1, 1})
            {
              const auto &side = pairs[k].side(sign);
              if (side.block != b)
                continue;
              for (const auto &node : side.nodes)
                for (unsigned int a = 0; a < modes.size(); ++a)
                  for (unsigned int c = 0; c < dim; ++c)
                    p_global(k * dim + c, first_mode[b] + a) +=
                      sign * node.weight * modes[a](node.dofs[c]);
            }
      }

    // ... and into the pairs' frames.
    p_hat.reinit(n_r, total);
    for (unsigned int k = 0; k < pairs.size(); ++k)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int a = 0; a < total; ++a)
          {
            double value = 0.;
            for (unsigned int c = 0; c < dim; ++c)
              value += pairs[k].frame[i][c] * p_global(k * dim + c, a);
            p_hat(k * dim + i, a) = value;
          }
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

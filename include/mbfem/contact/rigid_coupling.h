#ifndef mbfem_contact_rigid_coupling_h
#define mbfem_contact_rigid_coupling_h

#include <mbfem/block/block.h>
#include <mbfem/contact/coupling_rows.h>
#include <mbfem/interface/contact_interface.h>

#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The floating blocks' free rigid-body modes seen from the contact pairs
   * (the paper's eq. 15): the amplitudes alpha numbered block by block, and
   * P_hat, the relative displacement of every pair direction (in the pair's
   * frame) per unit amplitude. Both formulations need it: the condensed
   * system solves for alpha, and the mechanism checks and the statics
   * certificate of both read P_hat.
   */
  template <int dim>
  class RigidCoupling
  {
  public:
    /**
     * Numbers the modes of @p blocks and builds P_hat for @p pairs. A
     * block that @p present marks false (one a later stage adds) has no
     * modes here: it carries no load and touches nothing, so it stays put.
     * Empty: every block is present.
     */
    void
    setup(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
          const std::vector<ContactPair<dim>>            &pairs,
          const std::vector<bool>                        &present = {});

    /** All amplitudes (the floating modes of every block). */
    unsigned int
    n_modes() const
    {
      return total;
    }

    /** The floating modes of block @p b (0 for a supported block). */
    unsigned int
    n_modes(const unsigned int b) const
    {
      return block_modes[b];
    }

    /** The index of block @p b's first amplitude. */
    unsigned int
    offset(const unsigned int b) const
    {
      return first_mode[b];
    }

    unsigned int
    n_blocks() const
    {
      return block_modes.size();
    }

    const std::string &
    block_name(const unsigned int b) const
    {
      return names[b];
    }

    /** Block @p b's free modes as displacement vectors of its DoFs. */
    const std::vector<Vector<double>> &
    modes(const unsigned int b) const
    {
      return mode_vectors[b];
    }

    /** P_hat(pair direction @p row, amplitude @p a). */
    double
    operator()(const unsigned int row, const unsigned int a) const
    {
      return p_hat(row, a);
    }

    /**
     * The amplitudes that pair direction @p row moves with (those of its
     * pair's floating blocks) and P_hat's values there, amplitudes
     * ascending. Loops over a row go through these, not over all
     * amplitudes.
     */
    ArrayView<const CouplingRows::Entry>
    row(const unsigned int row) const
    {
      return p_hat.row(row);
    }

    /** P_hat, (pairs x dim) x n_modes(), by rows. */
    const CouplingRows &
    matrix() const
    {
      return p_hat;
    }

    /**
     * P_hat's rows for @p pairs (pair by pair, normal then tangents) with
     * the modes numbered as setup() numbered them: the statics
     * certificate's rows of the node-to-node pairs that a merged pair
     * stands for at a cross-point (ContactPair::cross_point_pairs).
     */
    CouplingRows
    rows_of(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
            const std::vector<ContactPair<dim>>            &pairs) const;

    /**
     * F_e: the resultant of each block's external load on each of its free
     * modes, per amplitude (after every block's assemble_load()).
     */
    std::vector<double>
    load_resultant(
      const std::vector<std::unique_ptr<Block<dim>>> &blocks) const;

  private:
    std::vector<unsigned int>                first_mode;
    std::vector<unsigned int>                block_modes;
    unsigned int                             total = 0;
    std::vector<std::string>                 names;
    std::vector<std::vector<Vector<double>>> mode_vectors;
    CouplingRows                             p_hat;
  };
} // namespace mbfem

#endif

#ifndef mbfem_block_floating_modes_h
#define mbfem_block_floating_modes_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  /**
   * The rigid-body motions a block's supports leave free (the paper's
   * floating blocks, eqs. 5-10), and the pins that remove them.
   *
   * The rigid-body modes are the dim translations and the rotations (1 in
   * 2D, 3 in 3D) about the block's centre, with lengths scaled by the
   * block's size so that all modes are of unit order. The free ones are the
   * null space of the supports' constraint equations applied to the modes,
   * in reduced row-echelon form (unique and readable: "translation x", not
   * "0.71 translation x + 0.71 ..."). A floating block is pinned at just
   * enough DoFs to remove them (a statically determinate support): its
   * flexibility is that of the pinned block, and the pins carry no force
   * once the block is in equilibrium.
   */
  template <int dim>
  class FloatingModes
  {
  public:
    /**
     * Finds the free modes of @p physical_constraints (supports, platens,
     * hanging nodes) and chooses the pins; @p block_name is for messages.
     */
    void
    compute(const DoFHandler<dim>           &dof_handler,
            const Mapping<dim>              &mapping,
            const AffineConstraints<double> &physical_constraints,
            const std::string               &block_name);

    /** The free modes as combinations of the rigid-body modes. */
    const std::vector<Vector<double>> &
    coefficients() const;

    /** The free modes as displacement vectors; empty for a held block. */
    const std::vector<Vector<double>> &
    modes() const;

    /** The DoFs that hold the free modes (as many as there are modes). */
    const std::vector<types::global_dof_index> &
    pins() const;

    /**
     * The point the rotations are taken about and the length the modes
     * are scaled by (the class), as compute() found them: a block's modes
     * in another frame, for a group of blocks (free_group_motions()).
     */
    const Point<dim> &
    centre() const;
    double
    size() const;

    /**
     * All rigid-body modes as displacement vectors (see the class); their
     * centre and size into @p centre and @p size if given.
     */
    static std::vector<Vector<double>>
    rigid_body_modes(const DoFHandler<dim> &dof_handler,
                     const Mapping<dim>    &mapping,
                     Point<dim>            *centre = nullptr,
                     double                *size   = nullptr);

    /**
     * The rigid motions that the blocks of @p group, moving together as
     * one body, leave free under all their supports: a motion whose
     * restriction to every block is a free mode of that block. Each block
     * may be held in some directions only (a roller here, another there);
     * the group is held when these directions together leave no motion
     * free. Returned as coefficients of the rigid-body modes about
     * @p centre (the mean of the blocks' centres) scaled by @p size, in
     * reduced row-echelon form (row_echelon()); empty if the group is held.
     */
    static std::vector<Vector<double>>
    free_group_motions(const std::vector<const FloatingModes<dim> *> &group,
                       Point<dim>                                    &centre,
                       double                                        &size);

    /**
     * The rows of @p basis (a basis of a space of mode coefficients) in
     * reduced row-echelon form, entries below 1e-12 set to zero: unique and
     * readable ("translation x", not "0.71 translation x + 0.71 ...").
     */
    static std::vector<Vector<double>>
    row_echelon(FullMatrix<double> basis);

    /** "translation x", "0.50 translation x + rotation about z", ... */
    static std::string
    describe(const Vector<double> &coefficients);

  private:
    /** The null space of the constraints on the modes, in RREF. */
    static std::vector<Vector<double>>
    free_combinations(const std::vector<Vector<double>> &modes,
                      const AffineConstraints<double>   &physical_constraints);

    /** Greedy column pivoting on the free modes. */
    void
    choose_pins(const AffineConstraints<double> &physical_constraints,
                const std::string               &block_name);

    std::vector<Vector<double>>          free_coefficients;
    std::vector<Vector<double>>          free_modes;
    std::vector<types::global_dof_index> pinned;
    Point<dim>                           mode_centre;
    double                               mode_size = 1.;
  };
} // namespace mbfem

#endif

#ifndef mbfem_block_plastic_state_h
#define mbfem_block_plastic_state_h

#include <mbfem/material/material.h>
#include <mbfem/material/plasticity.h>

#include <deal.II/base/symmetric_tensor.h>

#include <memory>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  template <int dim>
  class Block;

  /** What one plastic update of a block found. */
  struct PlasticUpdate
  {
    /**
     * Squared L2 norms of the residual r = F(x) - x of the fixed-point map
     * (x the plastic strain in the load, F(x) the one the return mapping
     * gives back) and of F(x).
     */
    double change2 = 0.;
    double norm2   = 0.;
    /** r_prev . (r - r_prev) and |r - r_prev|^2, for Aitken's relaxation. */
    double       aitken_numerator   = 0.;
    double       aitken_denominator = 0.;
    unsigned int n_yielded          = 0;
    unsigned int n_points           = 0;
    /** Area (2D) or volume (3D) of the yielded quadrature points. */
    double yielded_measure = 0.;
    /** Largest sqrt(2/3 eps_p : eps_p). */
    double max_equivalent = 0.;

    PlasticUpdate &
    operator+=(const PlasticUpdate &other);
  };

  /**
   * The plastic and Newton state of one block: the Mohr-Coulomb law, the
   * plastic strain at every point of the block's state_quadrature()
   * (committed, in the load, and the one the last return mapping gave back)
   * and, for Newton's method, the linearisation at those points. The block
   * owns one and asks it, at assembly, for the tangent of the stiffness and
   * for the stress its load carries; the driver asks it to update, relax,
   * commit and restore. A block without plasticity has a disabled state:
   * every query gives the elastic answer and every update is a no-op.
   *
   * Points are numbered cell-major, index = active cell index * points per
   * cell + q.
   */
  template <int dim>
  class PlasticState
  {
  public:
    /**
     * Makes the state elastic-perfectly plastic (Mohr-Coulomb) if
     * @p parameters are enabled, with the material of @p block, one point
     * per point of its state_quadrature() on each active cell; after the
     * block's triangulation is filled.
     */
    void
    initialize(const PlasticityParameters &parameters, const Block<dim> &block);

    /** Whether the block is plastic at all. */
    bool
    enabled() const;

    /** Whether Newton's method (Plasticity/Method) is used. */
    bool
    uses_newton() const;

    /**
     * The return mapping at every quadrature point, from the current
     * solution of @p block and the plastic strain of the last converged
     * increment; the result becomes the plastic strain that the next
     * assemble_load() puts into the load (int B^T D eps_p).
     */
    PlasticUpdate
    update(const Block<dim> &block);

    /**
     * Moves the plastic strain in the load by @p omega times the residual
     * of the last update() (omega = 1: plain fixed point).
     */
    void
    relax(const double omega);

    /**
     * Newton's method: whether the tangent stiffness differs from the one
     * last assembled, so that the block must be reassembled and
     * refactorised and its flexibility recomputed before the next pass.
     * Always false for the initial-stress method.
     */
    bool
    tangent_changed() const;

    /**
     * Newton's method: with a perfectly plastic tangent, yielded rock and
     * slipping pairs can form a mechanism, and the tangent system is
     * singular although the elastic one is not. @p suspend = true puts the
     * elastic stiffness back and makes update() do initial-stress
     * iterations for the rest of the step; false (at the start of every
     * step) resumes Newton. Returns whether the stiffness last assembled
     * had a plastic tangent, i.e. whether suspending changes anything.
     */
    bool
    suspend_newton(const bool suspend);

    /** Accepts the plastic strain of the converged increment. */
    void
    commit();

    /**
     * Goes back to the plastic state of the last commit (a failed increment
     * is retried in smaller steps).
     */
    void
    restore();

    /**
     * D eps_p at every quadrature point (cell-major, for the stresses at
     * output points), and per active cell (of @p n_cells) the fraction of
     * its points yielded and the largest equivalent plastic strain.
     */
    void
    cell_fields(const unsigned int                  n_cells,
                std::vector<SymmetricTensor<2, 3>> &plastic_stress,
                std::vector<double>                &yielded,
                std::vector<double>                &equivalent_strain) const;

    /**
     * D eps_p (3x3) of the plastic strain in the load at quadrature point
     * @p q of cell @p cell; only if enabled().
     */
    SymmetricTensor<2, 3>
    plastic_stress(const unsigned int cell, const unsigned int q) const;

    /**
     * The in-plane stress whose int B^T s the load carries at point @p q of
     * cell @p cell: D eps_p and, with Newton's method, (C_t - D) eps(u_j),
     * the part of K_t u_j that the elastic stiffness does not give. Only if
     * enabled().
     */
    SymmetricTensor<2, dim>
    load_stress(const unsigned int cell, const unsigned int q) const;

    /**
     * Newton's method: the consistent tangent at point @p index (cell-major)
     * that the stiffness is assembled with.
     */
    const SymmetricTensor<4, dim> &
    tangent(const std::size_t index) const;

    /**
     * Called once the block's stiffness has been assembled with the current
     * tangent: it is no longer stale.
     */
    void
    tangent_assembled();

  private:
    /**
     * Newton's method at one point: the residual of the linearisation into
     * @p result, and the new tangent and linearisation point.
     */
    void
    update_newton_point(const std::size_t              index,
                        const SymmetricTensor<2, dim> &strain,
                        const SymmetricTensor<2, 3>   &trial,
                        const SymmetricTensor<2, 3>   &stress,
                        const double                   JxW,
                        PlasticUpdate                 &result);

    /**
     * The initial-stress method at one point: the residual of the
     * fixed-point map and its Aitken terms into @p result.
     */
    void
    update_fixed_point(const std::size_t            index,
                       const SymmetricTensor<2, 3> &updated,
                       const double                 JxW,
                       PlasticUpdate               &result);

    std::unique_ptr<MohrCoulomb> mohr_coulomb;
    /** Twice the shear modulus, to measure Newton's residual in strain. */
    double                             two_mu            = 0.;
    unsigned int                       n_points_per_cell = 0;
    std::vector<SymmetricTensor<2, 3>> plastic_strain_committed;
    std::vector<SymmetricTensor<2, 3>> plastic_strain;      // F(x)
    std::vector<SymmetricTensor<2, 3>> plastic_strain_load; // x
    std::vector<SymmetricTensor<2, 3>> plastic_residual;
    std::vector<SymmetricTensor<2, 3>> plastic_residual_previous;
    bool                               have_previous_residual = false;
    std::vector<bool>                  yielded;
    /**
     * Newton's method: at every point of the plastic state the consistent
     * tangent, whether it is a plastic one, and the strain and (in-plane)
     * stress it was taken at, the linearisation point u_j. The load then
     * carries int B^T (C_t - D) eps(u_j), so that the block's solve is
     * K_t u_{j+1} = f - f_int(u_j) + K_t u_j and keeps the form (and the
     * contact flexibility) of the elastic one.
     */
    struct Linearisation
    {
      std::vector<SymmetricTensor<4, dim>> tangent;
      std::vector<bool>                    plastic;
      std::vector<SymmetricTensor<2, dim>> strain;
      std::vector<SymmetricTensor<2, dim>> stress;
    };
    bool                    newton = false;
    SymmetricTensor<4, dim> elastic_tangent;
    Linearisation           linearisation;
    /** The linearisation at the last commit, for restore(). */
    Linearisation linearisation_committed;
    bool          tangent_is_stale = false;
    /** Whether the stiffness last assembled used a plastic tangent. */
    bool assembled_plastic_tangent = false;
    /** Initial-stress iterations for the rest of the step (suspend_newton). */
    bool newton_suspended = false;
  };
} // namespace mbfem

#endif

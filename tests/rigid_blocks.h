// Rigid blocks whose statics certificate (StaticAdmissibility) the unit
// tests check against closed forms: the coupling P_hat of a rigid block's
// modes to pairs at its base corners, written down directly. Shared by
// tests/static_admissibility.cc and tests/mechanism_factor.cc.
#ifndef mbfem_tests_rigid_blocks_h
#define mbfem_tests_rigid_blocks_h

#include <mbfem/contact/static_admissibility.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <cmath>
#include <vector>

namespace rigid_blocks
{
  using namespace dealii;
  using mbfem::JointLaw;
  using mbfem::StaticAdmissibility;

  /**
   * 2D: a b x h block (weight W, centre at its middle) on a plane at
   * theta, pairs at the two base corners; the block is side b, the normal
   * points into it. Modes: translation x, y, rotation about the centre
   * (in units of the block's size, as Block::rigid_body_modes()).
   */
  inline StaticAdmissibility<2>::Result
  incline_2d(const double   theta,
             const double   b,
             const double   h,
             const JointLaw joint,
             const double   weight)
  {
    const Tensor<1, 2> t({std::cos(theta), std::sin(theta)}); // up-dip
    const Tensor<1, 2> n({-std::sin(theta), std::cos(theta)});
    const Tensor<1, 2> centre = 0.5 * b * t + 0.5 * h * n;
    const double       size   = std::sqrt(b * b + h * h);
    FullMatrix<double> coupling(4, 3);
    std::vector<StaticAdmissibility<2>::Candidate> candidates(2);
    for (unsigned int k = 0; k < 2; ++k)
      {
        const Tensor<1, 2> x        = (k == 0 ? 0. : b) * t - centre;
        const Tensor<1, 2> modes[3] = {Tensor<1, 2>({1., 0.}),
                                       Tensor<1, 2>({0., 1.}),
                                       Tensor<1, 2>(
                                         {-x[1] / size, x[0] / size})};
        for (unsigned int a = 0; a < 3; ++a)
          {
            coupling(2 * k, a)     = n * modes[a];
            coupling(2 * k + 1, a) = t * modes[a];
          }
        candidates[k].joint = joint;
        candidates[k].area  = 0.5 * b;
      }
    // F_e = Phi^T f for the weight at the centre: no moment about it.
    const std::vector<double> resultant = {0., -weight, 0.};
    return StaticAdmissibility<2>(candidates,
                                  mbfem::CouplingRows(coupling),
                                  resultant)
      .solve();
  }


  /**
   * 3D: fills the coupling rows of pair @p k at @p arm from the block's
   * reference point, in the frame (n, t1, t2): the block's three
   * translations and its rotations about x, y, z in units of @p size.
   */
  inline void
  couple_pair_3d(FullMatrix<double> &coupling,
                 const unsigned int  k,
                 const Tensor<1, 3> &arm,
                 const double        size,
                 const Tensor<1, 3> (&frame)[3])
  {
    for (unsigned int a = 0; a < 6; ++a)
      {
        Tensor<1, 3> mode, e;
        if (a < 3)
          mode[a] = 1.;
        else
          {
            e[a - 3] = 1.;
            mode     = cross_product_3d(e, arm) / size;
          }
        for (unsigned int i = 0; i < 3; ++i)
          coupling(3 * k + i, a) = frame[i] * mode;
      }
  }
} // namespace rigid_blocks

#endif

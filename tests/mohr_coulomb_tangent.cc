// The consistent tangent of the Mohr-Coulomb return mapping
// (MohrCoulomb::tangent, central differences), on random yielding trial
// stresses, for associated and non-associated flow. What must hold:
// - it is the derivative: for a random strain step d eps of 1e-5 of the
//   strain scale, R(trial + D d eps) - R(trial) = C : d eps to 1e-4
//   relative (the remainder is O(|d eps|) where the mapping is smooth; a
//   step that crosses from plane to edge or apex is not smooth, so at most
//   1 % of the trials may miss);
// - associated flow: C has the major symmetry (the tangent of an
//   associated perfectly plastic model is symmetric), to 1e-6 relative;
//   psi = 0: it does not (the asymmetry is printed, it must be large);
// - the 2D (plane strain) tangent is the in-plane block of the 3D one;
// - elastic_tangent() is D (C : eps = lambda tr(eps) 1 + 2 mu eps).

#include <mbfem/material/plasticity.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace dealii;

int
main()
{
  const mbfem::Material                  material(20e9, 0.25);
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  const double                           scale = 10e6;

  for (const double psi : {30., 0.})
    {
      mbfem::PlasticityParameters parameters;
      parameters.enabled         = true;
      parameters.cohesion        = 1e6;
      parameters.friction_angle  = 30.;
      parameters.dilatancy_angle = psi;
      const mbfem::MohrCoulomb mc(parameters, material);

      unsigned int n_yielded = 0, n_derivative = 0, n_plane = 0, n_edge = 0,
                   n_apex   = 0;
      double worst_symmetry = 0., least_asymmetry = 1e300,
             worst_plane_strain = 0.;
      for (unsigned int sample = 0; sample < 1000; ++sample)
        {
          SymmetricTensor<2, 3> trial;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              trial[i][j] = scale * (uniform(random) - (i == j ? 0.6 : 0.));
          SymmetricTensor<2, 3> sigma, eps_p;
          if (!mc.return_map(trial, sigma, eps_p))
            continue;
          ++n_yielded;
          const auto   s   = eigenvalues(sigma);
          const double tol = 1e-9 * scale;
          if (std::abs(s[0] - s[2]) < tol)
            ++n_apex;
          else if (std::abs(s[0] - s[1]) < tol || std::abs(s[1] - s[2]) < tol)
            ++n_edge;
          else
            ++n_plane;
          const SymmetricTensor<4, 3> C = mc.tangent<3>(trial);

          // The derivative in a random direction.
          SymmetricTensor<2, 3> d_eps;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              d_eps[i][j] = uniform(random);
          d_eps *= 1e-5 * (scale / 20e9) / d_eps.norm();
          SymmetricTensor<2, 3> moved, unused;
          mc.return_map(trial + mc.elastic_stress(d_eps), moved, unused);
          const SymmetricTensor<2, 3> change    = moved - sigma;
          const SymmetricTensor<2, 3> predicted = C * d_eps;
          if ((change - predicted).norm() <=
              1e-4 * std::max(change.norm(), 1e-6 * scale * 1e-5))
            ++n_derivative;

          // Major symmetry, relative to the size of C.
          double asymmetry = 0., size = 0.;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              for (unsigned int k = 0; k < 3; ++k)
                for (unsigned int l = k; l < 3; ++l)
                  {
                    asymmetry =
                      std::max(asymmetry,
                               std::abs(C[i][j][k][l] - C[k][l][i][j]));
                    size = std::max(size, std::abs(C[i][j][k][l]));
                  }
          if (psi > 0.)
            worst_symmetry = std::max(worst_symmetry, asymmetry / size);
          else
            least_asymmetry = std::min(least_asymmetry, asymmetry / size);

          // Plane strain: the in-plane block.
          const SymmetricTensor<4, 2> C2 = mc.tangent<2>(trial);
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              for (unsigned int k = 0; k < 2; ++k)
                for (unsigned int l = 0; l < 2; ++l)
                  worst_plane_strain =
                    std::max(worst_plane_strain,
                             std::abs(C2[i][j][k][l] - C[i][j][k][l]) / size);
        }
      std::printf("psi = %g: %u of 1000 trials yielded (%u to the plane, %u "
                  "to an edge, %u to the apex)\n",
                  psi,
                  n_yielded,
                  n_plane,
                  n_edge,
                  n_apex);
      std::printf("  C : d eps is the change of the returned stress in %u "
                  "of them (at least 99 %%: %s)\n",
                  n_derivative,
                  n_derivative >= 0.99 * n_yielded ? "yes" : "NO");
      if (psi > 0.)
        std::printf("  major symmetry (associated flow): %s\n",
                    worst_symmetry < 1e-6 ? "yes" : "NO");
      else
        std::printf("  not symmetric (non-associated flow): %s\n",
                    least_asymmetry > 1e-3 ? "yes" : "NO");
      std::printf("  2D tangent = in-plane block of the 3D one: %s\n",
                  worst_plane_strain < 1e-6 ? "yes" : "NO");
    }

  // elastic_tangent() against D.
  mbfem::PlasticityParameters parameters;
  parameters.enabled = true;
  const mbfem::MohrCoulomb mc(parameters, material);
  SymmetricTensor<2, 3>    eps;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = i; j < 3; ++j)
      eps[i][j] = uniform(random) * 1e-3;
  const SymmetricTensor<2, 3> expected = mc.elastic_stress(eps);
  const SymmetricTensor<2, 3> got      = mc.elastic_tangent<3>() * eps;
  std::printf("elastic_tangent() = D: %s\n",
              (got - expected).norm() < 1e-12 * expected.norm() ? "yes" : "NO");
}

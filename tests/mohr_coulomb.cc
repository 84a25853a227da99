// The Mohr-Coulomb return mapping on random trial stresses (random
// principal values in random principal axes), for associated and
// non-associated flow. What must hold at every yielded point:
// - the returned stress is on the yield surface, f = 0 to 1e-7 of the
//   stress scale (f is evaluated from eigenvalues, which deal.II computes
//   to about sqrt(machine epsilon) where two coincide, as on an edge), and
//   was not moved when the trial was elastic;
// - principal axes are kept, and eps_p = D^{-1} (trial - stress);
// - associated flow (psi = phi): the return is the closest point of the
//   (convex) elastic domain in the energy norm, i.e.
//   (trial - sigma) : D^{-1} (tau - sigma) <= 0 for every admissible tau,
//   checked against 2000 random admissible stresses per point;
// - non-associated flow with psi = 0: no plastic volume change, except at
//   the apex, where perfect plasticity has no other admissible stress.
// The counts of returns to the plane, an edge and the apex are printed:
// all three kinds must be exercised.

#include <mbfem/material/plasticity.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace dealii;

int
main()
{
  const mbfem::Material                  material(20e9, 0.25);
  std::mt19937                           random(42);
  std::uniform_real_distribution<double> uniform(-1., 1.);

  for (const double psi : {30., 0.})
    {
      mbfem::PlasticityParameters parameters;
      parameters.enabled         = true;
      parameters.cohesion        = 1e6;
      parameters.friction_angle  = 30.;
      parameters.dilatancy_angle = psi;
      const mbfem::MohrCoulomb mc(parameters, material);
      const double             scale = 10e6;

      unsigned int n_yielded = 0, n_plane = 0, n_edge = 0, n_apex = 0;
      double       worst_f = 0., worst_inequality = 0., worst_volume = 0.,
             worst_strain = 0.;
      for (unsigned int sample = 0; sample < 2000; ++sample)
        {
          // A random rotation from a random unit quaternion.
          double q[4], norm = 0.;
          for (double &c : q)
            {
              c = uniform(random);
              norm += c * c;
            }
          for (double &c : q)
            c /= std::sqrt(norm);
          Tensor<2, 3> R;
          R[0][0] = 1 - 2 * (q[2] * q[2] + q[3] * q[3]);
          R[0][1] = 2 * (q[1] * q[2] - q[0] * q[3]);
          R[0][2] = 2 * (q[1] * q[3] + q[0] * q[2]);
          R[1][0] = 2 * (q[1] * q[2] + q[0] * q[3]);
          R[1][1] = 1 - 2 * (q[1] * q[1] + q[3] * q[3]);
          R[1][2] = 2 * (q[2] * q[3] - q[0] * q[1]);
          R[2][0] = 2 * (q[1] * q[3] - q[0] * q[2]);
          R[2][1] = 2 * (q[2] * q[3] + q[0] * q[1]);
          R[2][2] = 1 - 2 * (q[1] * q[1] + q[2] * q[2]);
          Tensor<2, 3> diagonal;
          for (unsigned int i = 0; i < 3; ++i)
            diagonal[i][i] = scale * (uniform(random) - 0.2);
          const SymmetricTensor<2, 3> trial =
            symmetrize(Tensor<2, 3>(R * diagonal * transpose(R)));

          SymmetricTensor<2, 3> sigma, eps_p;
          if (!mc.return_map(trial, sigma, eps_p))
            {
              worst_f = std::max(worst_f, (sigma - trial).norm() / scale);
              continue;
            }
          ++n_yielded;
          worst_f =
            std::max(worst_f, std::abs(mc.yield_function(sigma)) / scale);
          worst_strain =
            std::max(worst_strain,
                     (eps_p - mc.elastic_strain(trial - sigma)).norm() /
                       std::max(eps_p.norm(), 1e-300));
          const auto   s   = eigenvalues(sigma);
          const double tol = 1e-9 * scale;
          if (std::abs(s[0] - s[2]) < tol)
            ++n_apex;
          else if (std::abs(s[0] - s[1]) < tol || std::abs(s[1] - s[2]) < tol)
            ++n_edge;
          else
            ++n_plane;

          const bool at_apex = std::abs(s[0] - s[2]) < tol;
          if (psi == 0. && !at_apex)
            worst_volume =
              std::max(worst_volume,
                       std::abs(trace(eps_p)) / std::max(eps_p.norm(), 1e-300));
          if (psi > 0.)
            for (unsigned int k = 0; k < 2000; ++k)
              {
                // A random admissible stress: random principal values in
                // random order, scaled into the elastic domain.
                SymmetricTensor<2, 3> tau;
                for (unsigned int i = 0; i < 3; ++i)
                  for (unsigned int j = i; j < 3; ++j)
                    tau[i][j] = scale * uniform(random);
                while (mc.yield_function(tau) > 0.)
                  tau = 0.5 * tau - 0.5e6 * unit_symmetric_tensor<3>();
                const double inequality =
                  (trial - sigma) * mc.elastic_strain(tau - sigma);
                worst_inequality =
                  std::max(worst_inequality,
                           inequality / (scale * scale / 20e9));
              }
        }
      std::printf("psi = %g: %u of 2000 trials yielded (%u to the plane, "
                  "%u to an edge, %u to the apex)\n",
                  psi,
                  n_yielded,
                  n_plane,
                  n_edge,
                  n_apex);
      std::printf("  on the yield surface (or unmoved): %s\n",
                  worst_f < 1e-7 ? "yes" : "NO");
      std::printf("  eps_p = D^-1 (trial - sigma): %s\n",
                  worst_strain < 1e-9 ? "yes" : "NO");
      if (psi == 0.)
        std::printf("  no plastic volume change away from the apex: %s\n",
                    worst_volume < 1e-9 ? "yes" : "NO");
      else
        std::printf("  closest point in the energy norm: %s\n",
                    worst_inequality < 1e-9 ? "yes" : "NO");
    }
}

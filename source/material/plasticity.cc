#include <mbfem/material/plasticity.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <cmath>

namespace mbfem
{
  void
  PlasticityParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Plasticity");
    {
      prm.declare_entry(
        "Enabled",
        "false",
        Patterns::Bool(),
        "Elastic-perfectly plastic Mohr-Coulomb blocks. Each block keeps its "
        "elastic stiffness (and contact flexibility); the plastic strain "
        "enters as a load, and each increment is repeated until it settles "
        "(the initial-stress method). Stresses include the in-situ stress.");
      prm.declare_entry("Cohesion",
                        "0",
                        Patterns::Double(0.),
                        "c of the rock (stress).");
      prm.declare_entry("Friction angle",
                        "30",
                        Patterns::Double(0., 89.),
                        "phi of the rock, in degrees.");
      prm.declare_entry("Dilatancy angle",
                        "0",
                        Patterns::Double(0., 89.),
                        "psi of the plastic potential, in degrees (psi = phi: "
                        "associated flow).");
      prm.declare_entry(
        "Tolerance",
        "1e-6",
        Patterns::Double(0.),
        "An increment has converged when the plastic strain is estimated to "
        "be within this (relative, L2 over the blocks) of its limit: the "
        "change of the last iteration times r / (1 - r), r the observed "
        "rate of the (linear) convergence, at least the change itself.");
      prm.declare_entry("Relaxation",
                        "aitken",
                        Patterns::Selection("aitken|none"),
                        "aitken: each step of the fixed-point iteration is "
                        "scaled by Aitken's factor from the last two "
                        "residuals (bounded to [0.05, 20]); none: plain "
                        "steps, slower but monotone.");
      prm.declare_entry(
        "Method",
        "initial stress",
        Patterns::Selection("initial stress|Newton"),
        "initial stress: each block keeps its elastic stiffness, its one "
        "factorisation and its contact flexibility; the plastic strain is a "
        "load, iterated to a fixed point (linear convergence, slow near a "
        "limit load). Newton: the consistent tangent; every iteration "
        "reassembles and refactorises each block and recomputes the contact "
        "flexibilities (quadratic convergence; condensed contact "
        "formulation only).");
      prm.declare_entry("Maximum iterations",
                        "1000",
                        Patterns::Integer(1),
                        "Most plastic iterations in one increment before the "
                        "run stops with a message.");
    }
    prm.leave_subsection();
  }



  void
  PlasticityParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Plasticity");
    {
      enabled         = prm.get_bool("Enabled");
      cohesion        = prm.get_double("Cohesion");
      friction_angle  = prm.get_double("Friction angle");
      dilatancy_angle = prm.get_double("Dilatancy angle");
      tolerance       = prm.get_double("Tolerance");
      max_iterations  = prm.get_integer("Maximum iterations");
      aitken          = prm.get("Relaxation") == "aitken";
      newton          = prm.get("Method") == "Newton";
      AssertThrow(!enabled || friction_angle > 0.,
                  ExcMessage("Plasticity/Friction angle must be > 0 (a "
                             "Tresca rock is not supported)."));
      AssertThrow(dilatancy_angle <= friction_angle,
                  ExcMessage("Plasticity/Dilatancy angle must not exceed the "
                             "friction angle."));
    }
    prm.leave_subsection();
  }



  MohrCoulomb::MohrCoulomb(const PlasticityParameters &parameters,
                           const Material             &material)
    : lambda(material.lambda())
    , mu(material.mu())
    , youngs_modulus(material.youngs_modulus)
    , poissons_ratio(material.poissons_ratio)
  {
    const double phi = parameters.friction_angle * numbers::PI / 180.;
    const double psi = parameters.dilatancy_angle * numbers::PI / 180.;
    k                = (1. + std::sin(phi)) / (1. - std::sin(phi));
    m                = (1. + std::sin(psi)) / (1. - std::sin(psi));
    sigma_c = 2. * parameters.cohesion * std::cos(phi) / (1. - std::sin(phi));
  }



  SymmetricTensor<2, 3>
  MohrCoulomb::elastic_stress(const SymmetricTensor<2, 3> &strain) const
  {
    return lambda * trace(strain) * unit_symmetric_tensor<3>() +
           2. * mu * strain;
  }



  SymmetricTensor<2, 3>
  MohrCoulomb::elastic_strain(const SymmetricTensor<2, 3> &stress) const
  {
    return ((1. + poissons_ratio) * stress -
            poissons_ratio * trace(stress) * unit_symmetric_tensor<3>()) /
           youngs_modulus;
  }



  double
  MohrCoulomb::yield_function(const SymmetricTensor<2, 3> &stress) const
  {
    const auto principal = eigenvalues(stress); // descending
    return k * principal[0] - principal[2] - sigma_c;
  }



  bool
  MohrCoulomb::return_map(const SymmetricTensor<2, 3> &trial,
                          SymmetricTensor<2, 3>       &stress,
                          SymmetricTensor<2, 3>       &plastic_strain) const
  {
    const auto   eigen   = eigenvectors(trial); // descending
    const double s_tr[3] = {eigen[0].first, eigen[1].first, eigen[2].first};
    const double f       = k * s_tr[0] - s_tr[2] - sigma_c;
    stress               = trial;
    plastic_strain       = SymmetricTensor<2, 3>();
    if (f <= 1e-12 * (std::abs(s_tr[0]) + std::abs(s_tr[2]) + sigma_c))
      return false;

    // Principal elasticity D = lambda 1 1^T + 2 mu I and its inverse.
    FullMatrix<double> D(3, 3), C(3, 3);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        D(i, j) = lambda + (i == j ? 2. * mu : 0.);
    C.invert(D);
    const auto apply = [](const FullMatrix<double> &A, const double *x) {
      std::array<double, 3> y{{0., 0., 0.}};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          y[i] += A(i, j) * x[j];
      return y;
    };

    // Return to the plane: sigma = trial - f / (a^T D b) D b.
    const double                a[3] = {k, 0., -1.};
    const double                b[3] = {m, 0., -1.};
    const std::array<double, 3> Db   = apply(D, b);
    const double aDb = a[0] * Db[0] + a[1] * Db[1] + a[2] * Db[2];
    double       s[3];
    for (unsigned int i = 0; i < 3; ++i)
      s[i] = s_tr[i] - f / aDb * Db[i];

    const double tolerance = 1e-12 * (std::abs(s_tr[0]) + std::abs(s_tr[2]));
    const bool   ordered = s[0] >= s[1] - tolerance && s[1] >= s[2] - tolerance;
    if (!ordered)
      {
        // An edge: sigma = apex + t r_f, with the plastic strain in the span
        // of the two planes' flow directions, i.e. D^{-1} (trial - sigma)
        // orthogonal to r_g.
        const double apex                = sigma_c / (k - 1.);
        const bool   first_edge          = s[0] < s[1]; // sigma_1 = sigma_2
        const double r_f[3]              = {1., first_edge ? 1. : k, k};
        const double r_g[3]              = {1., first_edge ? 1. : m, m};
        const std::array<double, 3> Cr_g = apply(C, r_g);
        double                      numerator = 0., denominator = 0.;
        for (unsigned int i = 0; i < 3; ++i)
          {
            numerator += Cr_g[i] * (s_tr[i] - apex);
            denominator += Cr_g[i] * r_f[i];
          }
        const double t = numerator / denominator;
        for (unsigned int i = 0; i < 3; ++i)
          s[i] = apex + (t < 0. ? t * r_f[i] : 0.); // beyond it: the apex
      }

    double difference[3];
    for (unsigned int i = 0; i < 3; ++i)
      difference[i] = s_tr[i] - s[i];
    const std::array<double, 3> e = apply(C, difference);
    stress                        = SymmetricTensor<2, 3>();
    for (unsigned int i = 0; i < 3; ++i)
      {
        const SymmetricTensor<2, 3> projector =
          symmetrize(outer_product(eigen[i].second, eigen[i].second));
        stress += s[i] * projector;
        plastic_strain += e[i] * projector;
      }
    return true;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  MohrCoulomb::tangent(const SymmetricTensor<2, 3> &trial) const
  {
    // Central differences with a strain step of 1e-6 of the stress scale:
    // truncation ~1e-12 where the mapping is smooth, round-off ~1e-10.
    const double            h = 1e-6 * (trial.norm() + sigma_c) / (2. * mu);
    SymmetricTensor<4, dim> result;
    SymmetricTensor<2, 3>   plus, minus, unused;
    for (unsigned int m = 0; m < dim; ++m)
      for (unsigned int n = m; n < dim; ++n)
        {
          SymmetricTensor<2, 3> strain;
          strain[m][n]                     = h; // also [n][m]
          const SymmetricTensor<2, 3> step = elastic_stress(strain);
          return_map(trial + step, plus, unused);
          return_map(trial - step, minus, unused);
          // C : E^{mn} = dS; for m != n the contraction counts C[k][l][m][n]
          // twice.
          const double factor = (m == n ? 1. : 0.5) / (2. * h);
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = k; l < dim; ++l)
              result[k][l][m][n] = factor * (plus[k][l] - minus[k][l]);
        }
    return result;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  MohrCoulomb::elastic_tangent() const
  {
    SymmetricTensor<4, dim> result;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = k; l < dim; ++l)
        for (unsigned int m = 0; m < dim; ++m)
          for (unsigned int n = m; n < dim; ++n)
            result[k][l][m][n] =
              (k == l && m == n ? lambda : 0.) +
              (k == m && l == n ? (k == l ? 2. : 1.) * mu : 0.);
    return result;
  }



  template SymmetricTensor<4, 2>
  MohrCoulomb::tangent<2>(const SymmetricTensor<2, 3> &) const;
  template SymmetricTensor<4, 3>
  MohrCoulomb::tangent<3>(const SymmetricTensor<2, 3> &) const;
  template SymmetricTensor<4, 2>
  MohrCoulomb::elastic_tangent<2>() const;
  template SymmetricTensor<4, 3>
  MohrCoulomb::elastic_tangent<3>() const;
} // namespace mbfem

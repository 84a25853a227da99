// Material law and stress invariants against hand-computed values:
// Lame constants, the plane-strain sigma_zz, principal stresses sorted with
// tension positive, and von Mises for uniaxial stress and pure shear.

#include <mbfem/material/material.h>

#include <cstdio>
#include <iostream>

using namespace dealii;

int
main()
{
  const mbfem::Material material(1000., 0.25);
  // lambda = E nu/((1+nu)(1-2nu)) = 400, mu = E/(2(1+nu)) = 400
  std::printf("lambda = %.6f, mu = %.6f\n", material.lambda(), material.mu());

  // Plane strain, eps_xx = 1e-3: sigma_xx = (lambda + 2mu) eps = 1.2,
  // sigma_yy = sigma_zz = lambda eps = 0.4
  SymmetricTensor<2, 2> eps2;
  eps2[0][0]                     = 1e-3;
  const SymmetricTensor<2, 3> s2 = material.stress_3d<2>(eps2);
  std::printf("plane strain: sigma_xx = %.6f, sigma_yy = %.6f, "
              "sigma_zz = %.6f\n",
              s2[0][0],
              s2[1][1],
              s2[2][2]);

  // 3D, a general strain: principal stresses of the stress are its sorted
  // eigenvalues; their sum is the trace.
  SymmetricTensor<2, 3> eps3;
  eps3[0][0]                            = 1e-3;
  eps3[1][1]                            = -2e-3;
  eps3[0][1]                            = 5e-4;
  eps3[1][2]                            = -3e-4;
  const SymmetricTensor<2, 3> s3        = material.stress<3>(eps3);
  const std::array<double, 3> principal = mbfem::principal_stresses(s3);
  std::printf("principal: %.6f >= %.6f >= %.6f, sum - trace = %.1e\n",
              principal[0],
              principal[1],
              principal[2],
              std::abs(principal[0] + principal[1] + principal[2] - trace(s3)));

  // Uniaxial tension 10: principal (10, 0, 0), von Mises 10.
  SymmetricTensor<2, 3> uniaxial;
  uniaxial[0][0] = 10.;
  const auto pu  = mbfem::principal_stresses(uniaxial);
  std::printf("uniaxial: principal %.6f %.6f %.6f, von Mises %.6f\n",
              pu[0],
              pu[1],
              pu[2],
              mbfem::von_mises_stress(uniaxial));

  // Pure shear tau = 1: principal (1, 0, -1), von Mises sqrt(3).
  SymmetricTensor<2, 3> shear;
  shear[0][1]   = 1.;
  const auto ps = mbfem::principal_stresses(shear);
  std::printf("shear: principal %.6f %.6f %.6f, von Mises %.6f "
              "(sqrt(3) = %.6f)\n",
              ps[0],
              ps[1],
              ps[2],
              mbfem::von_mises_stress(shear),
              std::sqrt(3.));

  // Bad values are refused with a message.
  for (const double nu : {0.5, -1.0})
    try
      {
        mbfem::Material bad(1., nu);
        std::cout << "nu = " << nu << " accepted (wrong)" << std::endl;
      }
    catch (ExceptionBase &e)
      {
        std::cout << "nu = " << nu << " refused" << std::endl;
      }
  try
    {
      mbfem::Material bad(0., 0.2);
      std::cout << "E = 0 accepted (wrong)" << std::endl;
    }
  catch (ExceptionBase &e)
    {
      std::cout << "E = 0 refused" << std::endl;
    }
}

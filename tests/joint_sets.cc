// Contact/Joint sets: parsing, and which planes a set claims. A set is
// given as a geologist gives it (dip, dip direction, tolerance) and claims
// a plane whose normal, of either sign, is within the tolerance:
// - 2D (x east, y up): dip 30 towards +x (dd 90) has the upward normal
//   (sin 30, cos 30); its downward normal is claimed too; dip 30 towards
//   -x (dd 270) is not; a plane 4 degrees off is, 6 degrees off is not;
// - 3D (x east, y north, z up): dip 60 towards the south-east (dd 135);
//   a horizontal plane belongs to 'dip 0' whatever its dip direction;
// - unknown keys and out-of-range values end with a message.

#include <mbfem/interface/joint_sets.h>

#include <deal.II/base/numbers.h>

#include <cmath>
#include <iostream>

using namespace dealii;

int
main()
{
  mbfem::JointLaw defaults;
  defaults.friction_coefficient = 0.5;
  const auto sets               = mbfem::parse_joint_sets(
    "east: dip 30, dip direction 90, friction 0.7; "
                  "se: dip 60, dip direction 135, tolerance 2, cohesion 0.1; "
                  "flat: dip 0",
    defaults);
  for (const auto &set : sets)
    std::cout << set.name << ": dip " << set.dip << ", dip direction "
              << set.dip_direction << ", tolerance " << set.tolerance << ", mu "
              << set.joint.friction_coefficient << ", c " << set.joint.cohesion
              << std::endl;

  const double r      = numbers::PI / 180.;
  const auto   plane2 = [&](const double dip, const double sign) {
    Tensor<1, 2> n;
    n[0] = sign * std::sin(dip * r);
    n[1] = std::cos(dip * r);
    return n;
  };
  std::cout << "2D dip 30 east: " << sets[0].contains(plane2(30, 1))
            << ", its downward normal: " << sets[0].contains(-plane2(30, 1))
            << ", dip 30 west: " << sets[0].contains(plane2(30, -1))
            << ", dip 34 east: " << sets[0].contains(plane2(34, 1))
            << ", dip 36 east: " << sets[0].contains(plane2(36, 1))
            << std::endl;

  Tensor<1, 3> se;
  se[0]           = std::sin(60 * r) * std::sin(135 * r);
  se[1]           = std::sin(60 * r) * std::cos(135 * r);
  se[2]           = std::cos(60 * r);
  Tensor<1, 3> nw = se;
  nw[0] *= -1;
  nw[1] *= -1;
  Tensor<1, 3> up;
  up[2] = -1;
  std::cout << "3D dip 60 towards 135: " << sets[1].contains(se)
            << ", towards 315: " << sets[1].contains(nw)
            << ", horizontal in 'flat': " << sets[2].contains(up) << std::endl;

  for (const std::string bad :
       {"a: dip 95", "b: strike 30", "c dip 30", "d: friction x"})
    try
      {
        mbfem::parse_joint_sets(bad, defaults);
        std::cout << "'" << bad << "' accepted" << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        // The message, without the source file and line around it.
        const std::string what  = e.what();
        const auto        start = what.find("Contact/Joint sets");
        std::cout << "'" << bad << "' refused: "
                  << what.substr(start, what.find('\n', start) - start)
                  << std::endl;
      }
}

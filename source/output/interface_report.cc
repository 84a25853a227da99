#include <mbfem/output/interface_report.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace mbfem
{
  namespace
  {
    /**
     * Axes in the mean plane of an interface, along which the summary gives
     * the extent of the closed and stuck pairs (an x-range means nothing on
     * an inclined or a 3D interface). The mean normal is the area-weighted
     * normal of the interface's pairs (tied pairs, whose frame is the
     * global axes, left out). In 2D the one axis is the normal turned by
     * 90 degrees; in 3D the first is the strike (horizontal, or x on a
     * horizontal interface) and the second the dip line. Each axis points
     * so that its first non-zero component is positive, so a horizontal
     * interface has the axes x (and y), as before.
     */
    template <int dim>
    std::vector<Tensor<1, dim>>
    in_plane_axes(const std::vector<ContactPair<dim>> &pairs,
                  const unsigned int                   interface)
    {
      Tensor<1, dim> normal;
      for (const auto &pair : pairs)
        if (pair.interface == interface && !pair.tied)
          normal += pair.area * pair.frame[0];
      if (normal.norm() == 0.)
        normal[dim - 1] = 1.; // all pairs tied: the global axes
      normal /= normal.norm();

      std::vector<Tensor<1, dim>> axes;
      if constexpr (dim == 2)
        axes.push_back(Tensor<1, dim>({-normal[1], normal[0]}));
      else
        {
          Tensor<1, dim> vertical;
          vertical[dim - 1]     = 1.;
          Tensor<1, dim> strike = cross_product_3d(vertical, normal);
          if (strike.norm() < 1e-12) // horizontal interface
            {
              strike    = Tensor<1, dim>();
              strike[0] = 1.;
            }
          strike /= strike.norm();
          axes.push_back(strike);
          axes.push_back(cross_product_3d(normal, strike));
        }
      for (auto &axis : axes)
        for (unsigned int d = 0; d < dim; ++d)
          if (std::abs(axis[d]) > 1e-12)
            {
              if (axis[d] < 0.)
                axis *= -1.;
              break;
            }
      return axes;
    }



    /** "s" for the one axis of a 2D interface, "s1" and "s2" in 3D. */
    std::string
    axis_name(const unsigned int j, const std::size_t n_axes)
    {
      return n_axes == 1 ? std::string("s") : "s" + std::to_string(j + 1);
    }



    /**
     * Smallest and largest coordinate of a set of pairs along each in-plane
     * axis of their interface; empty while nothing was added.
     */
    template <int dim>
    struct Extents
    {
      std::vector<Tensor<1, dim>> axes;
      std::vector<double>         min, max;

      explicit Extents(const std::vector<Tensor<1, dim>> &axes)
        : axes(axes)
        , min(axes.size(), 1e300)
        , max(axes.size(), -1e300)
      {}

      void
      add(const Point<dim> &point)
      {
        for (unsigned int j = 0; j < axes.size(); ++j)
          {
            min[j] = std::min(min[j], point * axes[j]);
            max[j] = std::max(max[j], point * axes[j]);
          }
      }

      std::string
      to_string() const
      {
        std::ostringstream s;
        if (min[0] > max[0])
          return "none";
        s << std::fixed << std::setprecision(5);
        for (unsigned int j = 0; j < axes.size(); ++j)
          s << (j > 0 ? ", " : "") << axis_name(j, axes.size()) << " from "
            << min[j] << " to " << max[j] << " (half-width "
            << 0.5 * (max[j] - min[j]) << ")";
        return s.str();
      }
    };



    /** The axes of Extents, written once per interface. */
    template <int dim>
    std::string
    axes_to_string(const std::vector<Tensor<1, dim>> &axes)
    {
      std::ostringstream s;
      s << std::fixed << std::setprecision(4);
      for (unsigned int j = 0; j < axes.size(); ++j)
        {
          s << (j > 0 ? ", " : "") << axis_name(j, axes.size()) << " along (";
          for (unsigned int d = 0; d < dim; ++d)
            s << (d > 0 ? ", " : "") << axes[j][d] + 0.; // no -0.0000
          s << ")";
        }
      return s.str();
    }



    /** Squared L2 errors of p and q, and of the exact fields' norms. */
    struct TractionErrors
    {
      double p_error2 = 0., p_norm2 = 0., q_error2 = 0., q_norm2 = 0.;
      /** Against the exact traction averaged over each pair's area. */
      double p_error2_average = 0., q_error2_average = 0.;
    };

    /**
     * Adds pair @p k's errors: at its midpoint, and against the closed
     * form averaged over its tributary segment (force / area is such an
     * average, which matters where the traction is not smooth, at the edge
     * of the contact zone).
     */
    template <int dim>
    void
    add_traction_errors(const ContactSolver<dim> &contact,
                        const ContactParameters  &parameters,
                        const unsigned int        k,
                        TractionErrors           &errors)
    {
      const auto          &pair = contact.pairs()[k];
      const Tensor<1, dim> rho  = contact.local_force(k) / pair.area;
      const Point<2>       point(pair.midpoint()[0], pair.midpoint()[1]);
      const auto          &exact_p = *parameters.exact_normal_traction;
      const auto          &exact_q = *parameters.exact_tangential_traction;
      const double         p_exact = exact_p.value(point);
      const double         q_exact = exact_q.value(point);
      errors.p_error2 += pair.area * std::pow(rho[0] - p_exact, 2);
      errors.p_norm2 += pair.area * p_exact * p_exact;
      errors.q_error2 += pair.area * std::pow(rho[1] - q_exact, 2);
      errors.q_norm2 += pair.area * q_exact * q_exact;

      // Midpoint rule with 64 points along the tangent.
      const Tensor<1, 2> tangent({pair.frame[1][0], pair.frame[1][1]});
      double             p_average = 0., q_average = 0.;
      for (unsigned int j = 0; j < 64; ++j)
        {
          const Point<2> y =
            point + ((j + 0.5) / 64 - 0.5) * pair.area * tangent;
          p_average += exact_p.value(y) / 64;
          q_average += exact_q.value(y) / 64;
        }
      errors.p_error2_average += pair.area * std::pow(rho[0] - p_average, 2);
      errors.q_error2_average += pair.area * std::pow(rho[1] - q_average, 2);
    }



    /**
     * Table 1 at the end: whether the slipping pairs of interface @p i are
     * on the Mohr-Coulomb cone and the stuck ones inside it, to 1e-8 of the
     * interface's largest pair force.
     */
    template <int dim>
    std::string
    coulomb_check(const ContactSolver<dim> &contact, const unsigned int i)
    {
      const auto &pairs         = contact.pairs();
      double      largest_force = 0., off_cone = 0., outside = 0.;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        if (pairs[k].interface == i)
          largest_force =
            std::max(largest_force, contact.local_force(k).norm());
      for (unsigned int k = 0; k < pairs.size(); ++k)
        if (pairs[k].interface == i && !pairs[k].tied &&
            contact.state(k) != ContactState::open)
          {
            const Tensor<1, dim> rho        = contact.local_force(k);
            Tensor<1, dim>       tangential = rho;
            tangential[0]                   = 0.;
            const double limit =
              pairs[k].joint.shear_strength(rho[0],
                                            pairs[k].area,
                                            contact.broken(k));
            if (contact.state(k) == ContactState::slip)
              off_cone =
                std::max(off_cone, std::abs(tangential.norm() - limit));
            else
              outside = std::max(outside, tangential.norm() - limit);
          }
      const double tolerance = 1e-8 * std::max(largest_force, 1e-300);
      return std::string("slipping pairs on the cone ") +
             (off_cone <= tolerance ? "yes" : "NO") +
             ", stuck pairs inside it " + (outside <= tolerance ? "yes" : "NO");
    }



    void
    print_traction_errors(TractionErrors errors, ConditionalOStream &pcout)
    {
      // An exact traction that is not finite at a pair, or whose square
      // overflows (1e308), has no error to print; the increments are on
      // disk, and the run ends with the reason.
      for (const double e :
           {errors.p_error2, errors.q_error2, errors.p_norm2, errors.q_norm2})
        AssertThrow(std::isfinite(e),
                    ExcMessage("The L2 error against 'Contact/Exact "
                               "traction' is not finite: the exact traction "
                               "is not finite at some pair, or so large that "
                               "its square overflows. Check its functions; "
                               "the results of the increments are on disk."));
      // Where the exact q is zero (a geostatic joint), q is measured
      // against the size of p instead.
      if (errors.q_norm2 == 0.)
        errors.q_norm2 = errors.p_norm2;
      // Where the exact traction is zero throughout, no error is relative
      // to it: the absolute one is shown, and said to be so.
      const auto relative = [](const double error2, const double norm2) {
        std::ostringstream text;
        if (norm2 > 0.)
          text << std::fixed << std::setprecision(4)
               << std::sqrt(error2 / norm2);
        else
          text << std::scientific << std::setprecision(3) << std::sqrt(error2)
               << " (absolute: the exact traction is zero)";
        return text.str();
      };
      pcout << "    relative L2 error against Contact/Exact traction: p "
            << relative(errors.p_error2, errors.p_norm2) << ", q "
            << relative(errors.q_error2, errors.q_norm2)
            << " (at the pairs); p "
            << relative(errors.p_error2_average, errors.p_norm2) << ", q "
            << relative(errors.q_error2_average, errors.q_norm2)
            << " (averaged over each pair's area)\n";
    }
  } // namespace



  template <int dim>
  void
  print_interface_summary(const ContactSolver<dim> &contact,
                          const ContactParameters  &parameters,
                          ConditionalOStream       &pcout)
  {
    const auto &pairs       = contact.pairs();
    const bool  with_errors = (dim == 2 && parameters.compute_traction_errors);
    for (unsigned int i = 0; i < parameters.interfaces.size(); ++i)
      {
        double         p_max = 0., q_max = 0.;
        const auto     axes = in_plane_axes(pairs, i);
        Extents<dim>   closed(axes), stuck(axes);
        TractionErrors errors;
        for (unsigned int k = 0; k < pairs.size(); ++k)
          if (pairs[k].interface == i)
            {
              Tensor<1, dim> q = contact.local_force(k) / pairs[k].area;
              p_max            = std::max(p_max, q[0]);
              q[0]             = 0.;
              q_max            = std::max(q_max, q.norm());
              if (contact.state(k) != ContactState::open)
                closed.add(pairs[k].midpoint());
              if (contact.state(k) == ContactState::stick)
                stuck.add(pairs[k].midpoint());
              if (with_errors)
                add_traction_errors(contact, parameters, k, errors);
            }
        pcout << "  interface " << i + 1
              << " at the end: max p = " << std::setprecision(6) << p_max
              << ", max |q| = " << q_max << "\n    extents "
              << axes_to_string(axes)
              << "\n    closed pairs: " << closed.to_string()
              << "\n    stuck pairs:  " << stuck.to_string() << "\n"
              << "    Coulomb: " << coulomb_check(contact, i) << "\n";
        if (with_errors)
          print_traction_errors(errors, pcout);
      }
  }



  template void
  print_interface_summary(const ContactSolver<2> &,
                          const ContactParameters &,
                          ConditionalOStream &);
  template void
  print_interface_summary(const ContactSolver<3> &,
                          const ContactParameters &,
                          ConditionalOStream &);
} // namespace mbfem

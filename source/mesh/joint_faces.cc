#include <mbfem/mesh/joint_faces.h>

#include <deal.II/base/geometry_info.h>

#include <cmath>

namespace mbfem
{
  namespace
  {
    /** Unit normal and area of a segment (2D) or a quadrilateral (3D). */
    template <int dim>
    std::pair<Tensor<1, dim>, double>
    normal_and_area(const std::vector<Point<dim>> &x)
    {
      Tensor<1, dim> n;
      if constexpr (dim == 2)
        {
          n[0] = -(x[1][1] - x[0][1]);
          n[1] = x[1][0] - x[0][0];
        }
      else
        // Half the cross product of the diagonals: the area of a planar
        // quadrilateral, and its normal.
        n = 0.5 * cross_product_3d(x[2] - x[0], x[3] - x[1]);
      const double area = n.norm();
      return {area > 0. ? n / area : n, area};
    }
  } // namespace



  template <int dim>
  JointFaces<dim>::JointFaces(const GmshJointElements &elements)
  {
    std::map<long, unsigned int> group_of_tag;
    for (const auto &[tag, name] : elements.names)
      {
        group_of_tag[tag] = names.size();
        names.push_back(name);
      }
    areas.assign(names.size(), 0.);
    double largest = 0.;
    for (const auto &[tag, corners] : elements.elements)
      {
        Face face;
        face.group = group_of_tag.at(tag);
        for (const auto &x : corners)
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = x[d];
            face.corners.push_back(p);
            face.centre += p / double(corners.size());
          }
        const auto [normal, area] = normal_and_area(face.corners);
        face.normal               = normal;
        areas[face.group] += area;
        for (const auto &p : face.corners)
          largest = std::max(largest, 2. * p.distance(face.centre));
        faces.push_back(face);
      }
    bin_size  = (largest > 0. ? largest : 1.);
    tolerance = 1e-6 * bin_size;
    for (unsigned int f = 0; f < faces.size(); ++f)
      bins[bin_of(faces[f].centre)].push_back(f);
  }



  template <int dim>
  std::array<long long, dim>
  JointFaces<dim>::bin_of(const Point<dim> &point) const
  {
    std::array<long long, dim> bin;
    for (unsigned int d = 0; d < dim; ++d)
      bin[d] = std::llround(std::floor(point[d] / bin_size));
    return bin;
  }



  /**
   * Whether @p point is on @p face: within the tolerance of its plane, and
   * on the inner side of each of its edges (faces of quadrilateral and
   * hexahedral cells are convex).
   */
  template <int dim>
  bool
  JointFaces<dim>::contains(const Face &face, const Point<dim> &point) const
  {
    if (std::abs((point - face.centre) * face.normal) > tolerance)
      return false;
    const auto &x = face.corners;
    if constexpr (dim == 2)
      {
        // A segment: the point projects between its two ends.
        const Tensor<1, dim> edge = x[1] - x[0];
        const double         t = ((point - x[0]) * edge) / edge.norm_square();
        return t > -1e-6 && t < 1. + 1e-6;
      }
    else
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          const Tensor<1, dim> edge = x[(i + 1) % x.size()] - x[i];
          if (cross_product_3d(edge, point - x[i]) * face.normal <
              -tolerance * edge.norm())
            return false;
        }
    return true;
  }



  template <int dim>
  unsigned int
  JointFaces<dim>::group_of(const Point<dim> &point) const
  {
    if (faces.empty())
      return numbers::invalid_unsigned_int;
    const auto centre = bin_of(point);
    for (unsigned int k = 0; k < std::pow(3, dim); ++k)
      {
        auto bin = centre;
        for (unsigned int d = 0, code = k; d < dim; ++d, code /= 3)
          bin[d] += long(code % 3) - 1;
        const auto in_bin = bins.find(bin);
        if (in_bin != bins.end())
          for (const unsigned int f : in_bin->second)
            if (contains(faces[f], point))
              return faces[f].group;
      }
    return numbers::invalid_unsigned_int;
  }



  template class JointFaces<2>;
  template class JointFaces<3>;
} // namespace mbfem

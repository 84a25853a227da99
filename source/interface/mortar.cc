#include <mbfem/interface/mortar.h>
#include <mbfem/mesh/mesh.h>

#include <deal.II/base/qprojector.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

namespace mbfem
{
  namespace
  {
    /** A face of one side of the interface. */
    template <int dim>
    struct SideFace
    {
      unsigned int                                   block;
      typename DoFHandler<dim>::active_cell_iterator cell;
      unsigned int                                   face;
      /** Corners of the face, its centre and outward normal there. */
      std::vector<Point<dim>> vertices;
      Point<dim>              centre;
      Tensor<1, dim>          normal;
      double                  diameter = 0.;
    };

    /** A node of a face: its scalar shape function in FE_Q, its dim DoFs. */
    template <int dim>
    struct FaceNode
    {
      unsigned int                             base;
      std::array<types::global_dof_index, dim> dofs;
      Point<dim>                               point;
    };

    /** One multiplier: a node of the side that carries the forces. */
    template <int dim>
    struct Multiplier
    {
      unsigned int                             block = 0;
      std::array<types::global_dof_index, dim> dofs;
      Point<dim>                               point;
      /** Integral of phi_j over the whole side, and of phi_j n. */
      double         full_area = 0.;
      Tensor<1, dim> normal;
      /** D_j, and the integral of psi_j times the distance along n. */
      double area = 0.;
      double gap  = 0.;
      /** M_jk by (block, first DoF) of the other side's node k. */
      std::map<std::pair<unsigned int, types::global_dof_index>, double> m;
      std::map<std::pair<unsigned int, types::global_dof_index>, FaceNode<dim>>
        other_nodes;
    };



    /** The faces of side @p s (0: a, 1: b) of @p declaration. */
    template <int dim>
    std::vector<SideFace<dim>>
    collect_faces(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                  const InterfaceDeclaration                     &declaration,
                  const unsigned int                              s)
    {
      const unsigned int own =
        (s == 0 ? declaration.side_a : declaration.side_b);
      const unsigned int other =
        (s == 0 ? declaration.side_b : declaration.side_a);
      std::vector<SideFace<dim>> faces;
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          if (declaration.by_blocks && blocks[b]->get_id() != own)
            continue;
          const types::boundary_id id =
            (declaration.by_blocks ? interface_boundary_id(other) : own);
          FEFaceValues<dim> centre(blocks[b]->get_mapping(),
                                   blocks[b]->get_fe(),
                                   QGauss<dim - 1>(1),
                                   update_normal_vectors);
          for (const auto &cell :
               blocks[b]->get_dof_handler().active_cell_iterators())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == id)
                {
                  centre.reinit(cell, f);
                  SideFace<dim> face{
                    b, cell, f, {}, Point<dim>(), centre.normal_vector(0), 0.};
                  for (const unsigned int v : cell->face(f)->vertex_indices())
                    face.vertices.push_back(cell->face(f)->vertex(v));
                  face.centre   = cell->face(f)->center();
                  face.diameter = cell->face(f)->diameter();
                  faces.push_back(face);
                }
        }
      AssertThrow(!faces.empty(),
                  ExcMessage("Contact interface '" + declaration.description +
                             "': side " + std::to_string(own) +
                             " has no faces in the mesh" +
                             (declaration.by_blocks ?
                                " shared with block " + std::to_string(other) :
                                std::string(" with that boundary id")) +
                             "."));
      return faces;
    }



    /** The nodes of @p face: FE_Q's shape functions with support on it. */
    template <int dim>
    std::vector<FaceNode<dim>>
    face_nodes(const Block<dim> &block, const SideFace<dim> &face)
    {
      const auto                          &fe   = block.get_fe();
      const auto                          &base = fe.base_element(0);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      face.cell->get_dof_indices(dof_indices);
      std::vector<FaceNode<dim>> nodes;
      for (unsigned int i = 0; i < base.n_dofs_per_cell(); ++i)
        if (base.has_support_on_face(i, face.face))
          {
            FaceNode<dim> node;
            node.base = i;
            for (unsigned int d = 0; d < dim; ++d)
              node.dofs[d] = dof_indices[fe.component_to_system_index(d, i)];
            node.point = block.get_mapping().transform_unit_to_real_cell(
              face.cell, base.get_unit_support_points()[i]);
            nodes.push_back(node);
          }
      return nodes;
    }



    /**
     * The dual basis of @p face: psi_j = sum_i A(j, i) phi_i with
     * A = D M^-1 (M the face's mass matrix of its nodes, D its row sums),
     * so that the integral of psi_j phi_i over the face is D_j delta_ij.
     * Adds each node's integral of phi_j and phi_j n to its multiplier;
     * @p measure is the face's length or area.
     */
    template <int dim>
    FullMatrix<double>
    dual_basis(const Block<dim>                 &block,
               const SideFace<dim>              &face,
               const std::vector<FaceNode<dim>> &nodes,
               const std::vector<unsigned int>  &of_face,
               std::vector<Multiplier<dim>>     &multipliers,
               double                           &measure)
    {
      const auto           &fe = block.get_fe();
      const QGauss<dim - 1> quadrature(fe.degree + 2);
      FEFaceValues<dim>     values(block.get_mapping(),
                               fe,
                               quadrature,
                               update_values | update_JxW_values);
      values.reinit(face.cell, face.face);
      const unsigned int n = nodes.size();
      FullMatrix<double> mass(n, n), dual(n, n);
      Vector<double>     lumped(n);
      for (const unsigned int q : values.quadrature_point_indices())
        for (unsigned int i = 0; i < n; ++i)
          {
            const double phi_i =
              values.shape_value(fe.component_to_system_index(0, nodes[i].base),
                                 q);
            lumped(i) += phi_i * values.JxW(q);
            multipliers[of_face[i]].full_area += phi_i * values.JxW(q);
            for (unsigned int j = 0; j < n; ++j)
              mass(i, j) +=
                phi_i *
                values.shape_value(fe.component_to_system_index(0,
                                                                nodes[j].base),
                                   q) *
                values.JxW(q);
          }
      mass.gauss_jordan();
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          dual(i, j) = lumped(i) * mass(i, j);
      measure = 0.;
      for (unsigned int i = 0; i < n; ++i)
        measure += lumped(i);
      return dual;
    }



    /**
     * A point of the overlap: where it is on the multiplier side (unit
     * point of the cell), its weight (length or area there), the normal,
     * and the point it projects to on the other side along that normal.
     */
    template <int dim>
    struct OverlapPoint
    {
      Point<dim>     unit;
      double         weight;
      Tensor<1, dim> normal;
      Point<dim>     other_unit;
      double         distance;
    };



    /** The overlaps of a face with the other side's faces, by face. */
    template <int dim>
    using Overlaps =
      std::vector<std::pair<unsigned int, std::vector<OverlapPoint<dim>>>>;



    /** The length or area of a face that @p overlaps cover. */
    template <int dim>
    double
    covered_measure(const Overlaps<dim> &overlaps)
    {
      double measure = 0.;
      for (const auto &[c, points] : overlaps)
        for (const auto &point : points)
          measure += point.weight;
      return measure;
    }



    /**
     * The dual basis of the part of a face that the other side covers
     * (Popp, Seitz, Gee and Wall 2013): D and M integrated over the
     * overlaps only, so that the integral of psi_j phi_i over the covered
     * part is D_j delta_ij and the weights reproduce what both sides
     * represent there. The dual basis of the whole face reproduced only
     * constants on a face covered in part (tests/mortar_interfaces.cc). A
     * pseudo-inverse: a shape function that barely reaches a small overlap
     * leaves M nearly singular.
     */
    template <int dim>
    FullMatrix<double>
    dual_basis_of_overlap(const Block<dim>                 &block,
                          const std::vector<FaceNode<dim>> &nodes,
                          const Overlaps<dim>              &overlaps)
    {
      const auto              &base = block.get_fe().base_element(0);
      const unsigned int       n    = nodes.size();
      LAPACKFullMatrix<double> mass(n, n);
      Vector<double>           lumped(n);
      std::vector<double>      phi(n);
      for (const auto &[c, points] : overlaps)
        for (const auto &point : points)
          {
            for (unsigned int i = 0; i < n; ++i)
              phi[i] = base.shape_value(nodes[i].base, point.unit);
            for (unsigned int i = 0; i < n; ++i)
              {
                lumped(i) += phi[i] * point.weight;
                for (unsigned int j = 0; j < n; ++j)
                  mass(i, j) += phi[i] * phi[j] * point.weight;
              }
          }
      mass.compute_inverse_svd(1e-12);
      FullMatrix<double> dual(n, n);
      Vector<double>     unit(n), column(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          unit    = 0.;
          unit(i) = 1.;
          mass.vmult(column, unit); // column i of M^+
          for (unsigned int j = 0; j < n; ++j)
            dual(j, i) = lumped(j) * column(j);
        }
      return dual;
    }



    /** Adds the contributions of @p points to the multipliers of a face. */
    template <int dim>
    void
    integrate(const Block<dim>                     &side,
              const std::vector<FaceNode<dim>>     &nodes,
              const FullMatrix<double>             &dual,
              const Block<dim>                     &other,
              const unsigned int                    other_block,
              const std::vector<FaceNode<dim>>     &other_nodes,
              const std::vector<OverlapPoint<dim>> &points,
              const std::vector<unsigned int>      &of_face,
              std::vector<Multiplier<dim>>         &multipliers)
    {
      const auto         &base       = side.get_fe().base_element(0);
      const auto         &other_base = other.get_fe().base_element(0);
      std::vector<double> phi(nodes.size()), psi(nodes.size()),
        phi_other(other_nodes.size());
      for (const auto &point : points)
        {
          for (unsigned int i = 0; i < nodes.size(); ++i)
            {
              phi[i] = base.shape_value(nodes[i].base, point.unit);
              multipliers[of_face[i]].normal +=
                phi[i] * point.weight * point.normal;
            }
          for (unsigned int k = 0; k < other_nodes.size(); ++k)
            phi_other[k] =
              other_base.shape_value(other_nodes[k].base, point.other_unit);
          for (unsigned int j = 0; j < nodes.size(); ++j)
            {
              psi[j] = 0.;
              for (unsigned int i = 0; i < nodes.size(); ++i)
                psi[j] += dual(j, i) * phi[i];
              Multiplier<dim> &multiplier = multipliers[of_face[j]];
              multiplier.area += psi[j] * point.weight;
              multiplier.gap += psi[j] * point.distance * point.weight;
              for (unsigned int k = 0; k < other_nodes.size(); ++k)
                {
                  const auto key =
                    std::make_pair(other_block, other_nodes[k].dofs[0]);
                  multiplier.m[key] += psi[j] * phi_other[k] * point.weight;
                  multiplier.other_nodes.emplace(key, other_nodes[k]);
                }
            }
        }
    }



    /** Whether the bounding boxes of two faces, widened by @p reach, meet. */
    template <int dim>
    bool
    may_overlap(const SideFace<dim> &a,
                const SideFace<dim> &b,
                const double         reach)
    {
      return a.centre.distance(b.centre) <=
             0.5 * (a.diameter + b.diameter) + reach + 1e-10 * a.diameter;
    }



    /**
     * 2D: a face as a curve x(xi), xi in [0, 1], through the block's
     * mapping, with its tangent and outward normal.
     */
    struct FaceCurve
    {
      const Mapping<2>                            &mapping;
      typename DoFHandler<2>::active_cell_iterator cell;
      unsigned int                                 face;
      Tensor<1, 2>                                 outward;

      Point<2>
      unit(const double xi) const
      {
        const Quadrature<2> q =
          QProjector<2>::project_to_face(ReferenceCells::Quadrilateral,
                                         Quadrature<1>(Point<1>(xi)),
                                         face);
        return q.point(0);
      }

      Point<2>
      point(const double xi) const
      {
        return mapping.transform_unit_to_real_cell(cell, unit(xi));
      }

      /** dx/dxi, by central differences (exact on straight faces). */
      Tensor<1, 2>
      tangent(const double xi) const
      {
        const double h = 1e-4;
        return (point(xi + h) - point(xi - h)) / (2. * h);
      }

      Tensor<1, 2>
      normal(const double xi) const
      {
        const Tensor<1, 2> t = tangent(xi);
        Tensor<1, 2>       n;
        n[0] = t[1];
        n[1] = -t[0];
        n /= n.norm();
        return (n * outward < 0 ? -n : n);
      }
    };



    /**
     * Whether a Newton step on a face's unit coordinate has settled: below
     * 1e-10 (the next is then below round-off) or at the round-off of a
     * step, about eps |x| / |dx/dxi|. A fixed 1e-14 was not reached away
     * from the origin, and the points it dropped made whole faces look
     * covered in part (a patch test moved by (30, 30) carried 2.9 MPa).
     */
    bool
    settled(const double step, const Point<2> &x, const Tensor<1, 2> &tangent)
    {
      const double round_off = 100. * std::numeric_limits<double>::epsilon() *
                               (std::abs(x[0]) + std::abs(x[1])) /
                               tangent.norm();
      return std::abs(step) < std::max(1e-10, round_off);
    }



    /**
     * 2D: xi on @p curve of the point whose normal passes through @p x
     * (Gauss-Newton on (x - x(xi)).t(xi) = 0), and the distance along it;
     * xi is NaN where the iteration diverges or does not settle, so that
     * the callers' range checks drop the point.
     */
    std::pair<double, double>
    project_along_normal(const FaceCurve &curve, const Point<2> &x)
    {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      double       xi  = 0.5;
      for (unsigned int it = 0; it < 50; ++it)
        {
          const Tensor<1, 2> t    = curve.tangent(xi);
          const double       step = ((x - curve.point(xi)) * t) / (t * t);
          if (!std::isfinite(step) || std::abs(xi + step) > 1e3)
            return {nan, nan};
          xi += step;
          if (settled(step, x, t))
            return {xi, (x - curve.point(xi)) * curve.normal(xi)};
        }
      return {nan, nan};
    }



    /**
     * 2D: eta on @p curve where the line x + s n meets it (Newton on the
     * cross product), and s; eta is NaN where the line runs along the
     * curve or the iteration diverges or does not settle.
     */
    std::pair<double, double>
    intersect_line(const FaceCurve    &curve,
                   const Point<2>     &x,
                   const Tensor<1, 2> &n,
                   double              eta)
    {
      const double nan   = std::numeric_limits<double>::quiet_NaN();
      const auto   cross = [](const Tensor<1, 2> &a, const Tensor<1, 2> &b) {
        return a[0] * b[1] - a[1] * b[0];
      };
      for (unsigned int it = 0; it < 50; ++it)
        {
          const Tensor<1, 2> t     = curve.tangent(eta);
          const double       slope = cross(t, n);
          const double       step  = cross(curve.point(eta) - x, n) / slope;
          if (!std::isfinite(step) || std::abs(eta - step) > 1e3)
            return {nan, nan};
          eta -= step;
          if (settled(step, x, t))
            return {eta, (curve.point(eta) - x) * n};
        }
      return {nan, nan};
    }



    /**
     * 2D: where @p curve faces the point @p x of normal @p n: along the
     * common normal, the bisector of n and the curve's outward normal at
     * the foot (found from the projection along n). Across the gap between
     * two curved surfaces the line along one side's normal meets the other
     * off the facing point, so that a normal approach would count as slip:
     * in Hertz's problem a shear of half the final one under the normal
     * load alone. Node-to-node pairs face each other along the same common
     * normal (contact_interface.cc). Returns eta, the distance along the
     * direction, and the direction.
     */
    std::tuple<double, double, Tensor<1, 2>>
    facing_point(const FaceCurve    &curve,
                 const Point<2>     &x,
                 const Tensor<1, 2> &n,
                 const double        eta)
    {
      auto [foot, distance]  = intersect_line(curve, x, n, eta);
      Tensor<1, 2> direction = n;
      for (unsigned int it = 0; it < 20 && std::isfinite(foot); ++it)
        {
          Tensor<1, 2> common = n - curve.normal(foot);
          if (common.norm() < 1e-8)
            break; // the surfaces do not face each other
          common /= common.norm();
          const auto [next, d] = intersect_line(curve, x, common, foot);
          const bool settled   = std::abs(next - foot) < 1e-13;
          foot                 = next;
          distance             = d;
          direction            = common;
          if (settled)
            break;
        }
      return {foot, distance, direction};
    }



    /** The curve of face @p f of its block. */
    FaceCurve
    curve_of(const std::vector<std::unique_ptr<Block<2>>> &blocks,
             const SideFace<2>                            &f)
    {
      return {blocks[f.block]->get_mapping(), f.cell, f.face, f.normal};
    }

    /**
     * The face of @p other_faces (among @p candidates) that the line from
     * @p x along @p n meets nearest, within @p reach, and where on it
     * (eta); invalid_unsigned_int if none.
     */
    std::pair<unsigned int, double>
    faced_face_2d(const std::vector<std::unique_ptr<Block<2>>> &blocks,
                  const std::vector<SideFace<2>>               &other_faces,
                  const std::vector<unsigned int>              &candidates,
                  const Point<2>                               &x,
                  const Tensor<1, 2>                           &n,
                  const double                                  reach)
    {
      unsigned int found = numbers::invalid_unsigned_int;
      double       best  = std::numeric_limits<double>::max();
      double       eta0  = 0.5;
      for (const unsigned int c : candidates)
        {
          const auto [eta, d] =
            intersect_line(curve_of(blocks, other_faces[c]), x, n, 0.5);
          if (eta >= -1e-10 && eta <= 1. + 1e-10 && std::abs(d) <= reach &&
              std::abs(d) < best)
            {
              best  = std::abs(d);
              found = c;
              eta0  = eta;
            }
        }
      return {found, eta0};
    }

    /**
     * Gauss's rule of @p n_points on the segment [xi0, xi1] of a face's
     * unit interval.
     */
    Quadrature<1>
    segment_rule(const double       xi0,
                 const double       xi1,
                 const unsigned int n_points)
    {
      const QGauss<1>       gauss(n_points);
      std::vector<Point<1>> xi;
      std::vector<double>   w;
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          xi.emplace_back(xi0 + (xi1 - xi0) * gauss.point(q)[0]);
          w.push_back((xi1 - xi0) * gauss.weight(q));
        }
      return Quadrature<1>(xi, w);
    }

    /**
     * Across a curved gap the common normal at @p point (whose point and
     * normal are @p x and @p n) may reach a neighbour of face @p found:
     * the first candidate it does reach within @p reach gets the point as
     * an overlap of its own.
     */
    void
    overlap_on_neighbour_2d(
      const std::vector<std::unique_ptr<Block<2>>> &blocks,
      const std::vector<SideFace<2>>               &other_faces,
      const std::vector<unsigned int>              &candidates,
      const unsigned int                            found,
      const OverlapPoint<2>                        &point,
      const Point<2>                               &x,
      const Tensor<1, 2>                           &n,
      const double                                  reach,
      std::vector<std::pair<unsigned int, std::vector<OverlapPoint<2>>>>
        &overlaps)
    {
      for (const unsigned int c : candidates)
        if (c != found)
          {
            const FaceCurve curve = curve_of(blocks, other_faces[c]);
            const auto [eta_c, d_c, direction_c] =
              facing_point(curve, x, n, 0.5);
            if (eta_c >= -1e-10 && eta_c <= 1. + 1e-10)
              {
                if (std::abs(d_c) <= reach)
                  overlaps.emplace_back(c,
                                        std::vector<OverlapPoint<2>>{
                                          {point.unit,
                                           point.weight,
                                           direction_c,
                                           curve.unit(eta_c),
                                           d_c}});
                return;
              }
          }
    }

    /**
     * 2D: the overlap of face @p s of the multiplier side with face @p o of
     * the other side, as Gauss points on the segments of s between the
     * projections of the other faces' ends (@p breaks, sorted).
     */
    void
    overlap_points_2d(
      const std::vector<std::unique_ptr<Block<2>>> &blocks,
      const SideFace<2>                            &s,
      const FaceCurve                              &s_curve,
      const std::vector<SideFace<2>>               &other_faces,
      const std::vector<unsigned int>              &candidates,
      const std::vector<double>                    &breaks,
      const double                                  reach,
      std::vector<std::pair<unsigned int, std::vector<OverlapPoint<2>>>>
        &overlaps)
    {
      const Block<2> &side = *blocks[s.block];
      for (unsigned int b = 0; b + 1 < breaks.size(); ++b)
        {
          const double xi0 = breaks[b], xi1 = breaks[b + 1];
          if (xi1 - xi0 < 1e-12)
            continue;
          // The other side's face this segment faces: the nearest one
          // whose curve the normal at the segment's middle meets.
          const double middle      = 0.5 * (xi0 + xi1);
          const auto [found, eta0] = faced_face_2d(blocks,
                                                   other_faces,
                                                   candidates,
                                                   s_curve.point(middle),
                                                   s_curve.normal(middle),
                                                   reach);
          if (found == numbers::invalid_unsigned_int)
            continue;
          const Block<2> &other = *blocks[other_faces[found].block];
          // Exact for the polynomial integrand of straight faces; curved
          // ones get the same rule, with room to spare.
          const Quadrature<1> segment =
            segment_rule(xi0,
                         xi1,
                         side.get_fe().degree + other.get_fe().degree + 3);
          FEFaceValues<2> values(side.get_mapping(),
                                 side.get_fe(),
                                 segment,
                                 update_JxW_values | update_normal_vectors |
                                   update_quadrature_points);
          values.reinit(s.cell, s.face);
          const FaceCurve o_curve = curve_of(blocks, other_faces[found]);
          std::vector<OverlapPoint<2>> points;
          for (const unsigned int q : values.quadrature_point_indices())
            {
              const Point<2>     x = values.quadrature_point(q);
              const Tensor<1, 2> n = values.normal_vector(q);
              const auto [eta, d, direction] =
                facing_point(o_curve, x, n, eta0);
              const OverlapPoint<2> point{s_curve.unit(segment.point(q)[0]),
                                          values.JxW(q),
                                          direction,
                                          o_curve.unit(eta),
                                          d};
              if (eta < -1e-10 || eta > 1. + 1e-10)
                overlap_on_neighbour_2d(blocks,
                                        other_faces,
                                        candidates,
                                        found,
                                        point,
                                        x,
                                        n,
                                        reach,
                                        overlaps);
              else if (std::abs(d) <= reach)
                points.push_back(point);
            }
          overlaps.emplace_back(found, std::move(points));
        }
    }



    /** 2D: the overlaps of face @p s with the faces of the other side. */
    template <int dim>
    std::vector<std::pair<unsigned int, std::vector<OverlapPoint<dim>>>>
    overlaps_of_face(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                     const SideFace<dim>                            &s,
                     const std::vector<SideFace<dim>> &other_faces,
                     const std::vector<unsigned int>  &candidates,
                     const double                      reach);

    template <>
    std::vector<std::pair<unsigned int, std::vector<OverlapPoint<2>>>>
    overlaps_of_face(const std::vector<std::unique_ptr<Block<2>>> &blocks,
                     const SideFace<2>                            &s,
                     const std::vector<SideFace<2>>               &other_faces,
                     const std::vector<unsigned int>              &candidates,
                     const double                                  reach)
    {
      const Block<2> &side = *blocks[s.block];
      const FaceCurve s_curve{side.get_mapping(), s.cell, s.face, s.normal};
      // Only faces that face this one (as in 3D): not the back of a thin
      // block, nor a face at right angles within the search distance.
      std::vector<unsigned int> facing;
      for (const unsigned int c : candidates)
        if (other_faces[c].normal * s.normal < -1e-3)
          facing.push_back(c);
      // The segments end where the normals through the other faces' ends
      // cross this face: between them the integrand is one polynomial.
      std::vector<double> breaks{0., 1.};
      for (const unsigned int c : facing)
        for (const auto &vertex : other_faces[c].vertices)
          {
            const auto [xi, d] = project_along_normal(s_curve, vertex);
            if (xi > 0. && xi < 1. && std::abs(d) <= reach + 1e-10 * s.diameter)
              breaks.push_back(xi);
          }
      std::sort(breaks.begin(), breaks.end());
      std::vector<std::pair<unsigned int, std::vector<OverlapPoint<2>>>>
        overlaps;
      overlap_points_2d(
        blocks, s, s_curve, other_faces, facing, breaks, reach, overlaps);
      return overlaps;
    }



    /**
     * 3D, flat faces: the corners of @p face in the plane (origin, t1, t2)
     * in counter-clockwise order (deal.II numbers them lexicographically).
     */
    std::vector<std::array<double, 2>>
    polygon_in_plane(const SideFace<3>  &face,
                     const Point<3>     &origin,
                     const Tensor<1, 3> &t1,
                     const Tensor<1, 3> &t2)
    {
      std::vector<std::array<double, 2>> polygon;
      for (const unsigned int v : {0u, 1u, 3u, 2u})
        polygon.push_back({{(face.vertices[v] - origin) * t1,
                            (face.vertices[v] - origin) * t2}});
      double area = 0.;
      for (unsigned int i = 0; i < 4; ++i)
        {
          const auto &p = polygon[i], &q = polygon[(i + 1) % 4];
          area += p[0] * q[1] - q[0] * p[1];
        }
      if (area < 0.)
        std::reverse(polygon.begin(), polygon.end());
      return polygon;
    }



    /**
     * A rule on the triangle (0,0), (1,0), (0,1) from the Gauss rule of @p n
     * points on the square collapsed onto it (Duffy): exact for
     * polynomials of total degree 2n - 2, of any n.
     */
    Quadrature<2>
    duffy_triangle(const unsigned int n)
    {
      const QGauss<1>       gauss(n);
      std::vector<Point<2>> points;
      std::vector<double>   weights;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            const double u = gauss.point(i)[0], v = gauss.point(j)[0];
            points.emplace_back(u, (1. - u) * v);
            weights.push_back(gauss.weight(i) * gauss.weight(j) * (1. - u));
          }
      return Quadrature<2>(points, weights);
    }



    /** Sutherland-Hodgman: @p subject clipped by the convex @p clip. */
    std::vector<std::array<double, 2>>
    clip_polygon(std::vector<std::array<double, 2>>        subject,
                 const std::vector<std::array<double, 2>> &clip)
    {
      for (unsigned int e = 0; e < clip.size() && !subject.empty(); ++e)
        {
          const auto &a = clip[e], &b = clip[(e + 1) % clip.size()];
          const auto  inside = [&](const std::array<double, 2> &p) {
            return (b[0] - a[0]) * (p[1] - a[1]) -
                     (b[1] - a[1]) * (p[0] - a[0]) >=
                   0.;
          };
          std::vector<std::array<double, 2>> result;
          for (unsigned int i = 0; i < subject.size(); ++i)
            {
              const auto &p   = subject[i],
                         &q   = subject[(i + 1) % subject.size()];
              const bool p_in = inside(p), q_in = inside(q);
              if (p_in)
                result.push_back(p);
              if (p_in != q_in)
                {
                  const double dp = (b[0] - a[0]) * (p[1] - a[1]) -
                                    (b[1] - a[1]) * (p[0] - a[0]);
                  const double dq = (b[0] - a[0]) * (q[1] - a[1]) -
                                    (b[1] - a[1]) * (q[0] - a[0]);
                  const double t = dp / (dp - dq);
                  result.push_back(
                    {{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}});
                }
            }
          subject = std::move(result);
        }
      return subject;
    }



    /** 3D: refuses a face that is not flat, naming where it is. */
    void
    check_flat(const SideFace<3> &face, const Tensor<1, 3> &normal)
    {
      // The edges too: a face beside a curved boundary keeps the curved
      // manifold on its lines (mesh.cc), which MappingQ follows.
      const auto cell_face = face.cell->face(face.face);
      bool       flat = (cell_face->manifold_id() == numbers::flat_manifold_id);
      for (unsigned int l = 0; l < cell_face->n_lines(); ++l)
        flat &=
          (cell_face->line(l)->manifold_id() == numbers::flat_manifold_id);
      for (const auto &vertex : face.vertices)
        flat &=
          std::abs((vertex - face.centre) * normal) <= 1e-10 * face.diameter;
      std::ostringstream where;
      where << face.centre;
      AssertThrow(flat,
                  ExcMessage("A mortar interface in 3D needs flat faces; the "
                             "face at (" +
                             where.str() +
                             ") is curved. Use node-to-node pairs there "
                             "(matching meshes)."));
    }



    template <>
    std::vector<std::pair<unsigned int, std::vector<OverlapPoint<3>>>>
    overlaps_of_face(const std::vector<std::unique_ptr<Block<3>>> &blocks,
                     const SideFace<3>                            &s,
                     const std::vector<SideFace<3>>               &other_faces,
                     const std::vector<unsigned int>              &candidates,
                     const double                                  reach)
    {
      const Block<3>    &side = *blocks[s.block];
      const Tensor<1, 3> n    = s.normal;
      check_flat(s, n);
      Tensor<1, 3> t1 = s.vertices[1] - s.vertices[0];
      t1 -= (t1 * n) * n;
      t1 /= t1.norm();
      const Tensor<1, 3> t2  = cross_product_3d(n, t1);
      const auto         own = polygon_in_plane(s, s.centre, t1, t2);

      std::vector<std::pair<unsigned int, std::vector<OverlapPoint<3>>>>
        overlaps;
      for (const unsigned int c : candidates)
        {
          const SideFace<3> &o        = other_faces[c];
          const Block<3>    &other    = *blocks[o.block];
          const Tensor<1, 3> o_normal = o.normal;
          // Exact where the faces are parallelograms, for psi_j phi_k and
          // for the mass matrix of a face covered in part.
          const unsigned int  p = side.get_fe().degree;
          const Quadrature<2> triangle_rule =
            duffy_triangle(std::max(p + other.get_fe().degree, 2 * p) + 2);
          check_flat(o, o_normal);
          if (o_normal * n > -1e-3)
            continue; // not facing this face
          const auto overlap =
            clip_polygon(polygon_in_plane(o, s.centre, t1, t2), own);
          std::vector<OverlapPoint<3>> points;
          for (unsigned int i = 1; i + 1 < overlap.size(); ++i)
            {
              const auto  &a = overlap[0], &b = overlap[i], &e = overlap[i + 1];
              const double area2 =
                (b[0] - a[0]) * (e[1] - a[1]) - (b[1] - a[1]) * (e[0] - a[0]);
              if (area2 <= 1e-14 * s.diameter * s.diameter)
                continue;
              for (unsigned int q = 0; q < triangle_rule.size(); ++q)
                {
                  const Point<2> &r = triangle_rule.point(q);
                  const double    y0 =
                    a[0] + r[0] * (b[0] - a[0]) + r[1] * (e[0] - a[0]);
                  const double y1 =
                    a[1] + r[0] * (b[1] - a[1]) + r[1] * (e[1] - a[1]);
                  const Point<3> x = s.centre + y0 * t1 + y1 * t2;
                  // Along n to the other face's plane.
                  const double d = ((o.centre - x) * o_normal) / (n * o_normal);
                  if (std::abs(d) > reach)
                    continue;
                  OverlapPoint<3> point;
                  point.unit =
                    side.get_mapping().transform_real_to_unit_cell(s.cell, x);
                  point.other_unit =
                    other.get_mapping().transform_real_to_unit_cell(o.cell,
                                                                    x + d * n);
                  point.weight   = triangle_rule.weight(q) * area2;
                  point.normal   = n;
                  point.distance = d;
                  points.push_back(point);
                }
            }
          if (!points.empty())
            overlaps.emplace_back(c, std::move(points));
        }
      return overlaps;
    }



    /** The pair of multiplier @p j, or false if it faces nothing. */
    template <int dim>
    bool
    make_pair_of_multiplier(const Multiplier<dim> &j,
                            const unsigned int     k,
                            const double           coincident,
                            const std::string     &description,
                            ContactPair<dim>      &pair)
    {
      // A node whose dual function barely meets the other side (or meets
      // it only where psi_j < 0) would get huge weights: it has no pair.
      if (!(j.area > 1e-3 * j.full_area))
        return false;
      pair.interface = k;
      pair.a.block   = j.block;
      pair.a.nodes   = {{j.dofs, 1.}};
      pair.a.point   = j.point;

      double largest = 0.;
      for (const auto &[key, m] : j.m)
        largest = std::max(largest, std::abs(m));
      std::set<unsigned int> blocks;
      Point<dim>             facing;
      for (const auto &[key, m] : j.m)
        if (std::abs(m) > 1e-12 * largest)
          {
            const FaceNode<dim> &node = j.other_nodes.at(key);
            pair.b.nodes.push_back({node.dofs, m / j.area});
            facing += (m / j.area) * node.point;
            blocks.insert(key.first);
          }
      std::ostringstream where;
      where << j.point;
      AssertThrow(blocks.size() == 1,
                  ExcMessage("Mortar interface '" + description +
                             "': the node at (" + where.str() + ") faces " +
                             std::to_string(blocks.size()) +
                             " blocks of the other side. Give each block of "
                             "the other side its own boundary id and "
                             "declare one interface per block ('boundaries "
                             "3:4 mortar; boundaries 3:5 mortar'), or "
                             "'blocks 1:2 mortar' where they share faces in "
                             "the mesh."));
      pair.b.block     = *blocks.begin();
      pair.b.point     = facing;
      pair.frame       = frame_of_normal(j.normal);
      pair.initial_gap = j.gap / j.area;
      if (std::abs(pair.initial_gap) <= coincident)
        pair.initial_gap = 0.;
      pair.area = j.area;
      return true;
    }
    /**
     * The side (0 or 1) of @p faces whose nodes carry the multipliers: the
     * one with fewer distinct nodes (a node shared by several faces counts
     * once), or more with @p on_finer_side; side 0 where both have as many.
     */
    template <int dim>
    unsigned int
    multiplier_side(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                    const std::vector<SideFace<dim>> (&faces)[2],
                    const bool on_finer_side)
    {
      unsigned int n_nodes[2] = {0, 0};
      for (unsigned int s = 0; s < 2; ++s)
        {
          std::set<std::pair<unsigned int, types::global_dof_index>> distinct;
          for (const auto &face : faces[s])
            for (const auto &node : face_nodes(*blocks[face.block], face))
              distinct.emplace(face.block, node.dofs[0]);
          n_nodes[s] = distinct.size();
        }
      return n_nodes[0] == n_nodes[1] ?
               0 :
               ((n_nodes[1] > n_nodes[0]) == on_finer_side ? 1 : 0);
    }

    /**
     * The multipliers of the nodes @p nodes of a face of block @p block:
     * each node's index in @p multipliers, added there the first time a
     * face names it (@p index: by block and first DoF).
     */
    template <int dim, typename Node>
    std::vector<unsigned int>
    add_multipliers(const unsigned int            block,
                    const std::vector<Node>      &nodes,
                    std::map<std::pair<unsigned int, types::global_dof_index>,
                             unsigned int>       &index,
                    std::vector<Multiplier<dim>> &multipliers)
    {
      std::vector<unsigned int> of_face;
      for (const auto &node : nodes)
        {
          const auto [it, inserted] =
            index.emplace(std::make_pair(block, node.dofs[0]),
                          multipliers.size());
          if (inserted)
            {
              Multiplier<dim> multiplier;
              multiplier.block = block;
              multiplier.dofs  = node.dofs;
              multiplier.point = node.point;
              multipliers.push_back(multiplier);
            }
          of_face.push_back(it->second);
        }
      return of_face;
    }
  } // namespace



  template <int dim>
  std::vector<Point<dim>>
  mortar_pairs(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
               const InterfaceDeclaration                     &declaration,
               const unsigned int                              k,
               const double                                    reach,
               const double                                    coincident,
               const bool                                      on_finer_side,
               std::vector<ContactPair<dim>>                  &pairs)
  {
    std::vector<SideFace<dim>> faces[2] = {
      collect_faces(blocks, declaration, 0),
      collect_faces(blocks, declaration, 1)};
    // The multipliers live on the coarser side (or the finer one): the
    // measurements behind the choice are in doc/mortar.md.
    const unsigned int side = multiplier_side(blocks, faces, on_finer_side);
    const auto        &own = faces[side], &other = faces[1 - side];

    std::map<std::pair<unsigned int, types::global_dof_index>, unsigned int>
                                 index;
    std::vector<Multiplier<dim>> multipliers;
    for (const auto &s : own)
      {
        const Block<dim>               &block = *blocks[s.block];
        const auto                      nodes = face_nodes(block, s);
        const std::vector<unsigned int> of_face =
          add_multipliers(s.block, nodes, index, multipliers);
        double             measure = 0.;
        FullMatrix<double> dual =
          dual_basis(block, s, nodes, of_face, multipliers, measure);

        std::vector<unsigned int> candidates;
        for (unsigned int c = 0; c < other.size(); ++c)
          if (may_overlap(s, other[c], reach))
            candidates.push_back(c);
        const Overlaps<dim> overlaps =
          overlaps_of_face(blocks, s, other, candidates, reach);
        // Only for p = 1, whose shape functions are positive: of higher
        // degree, a node's integral over the covered part may be zero or
        // negative, it then gets no pair and the others' dual functions no
        // longer sum to one (a face split between two interfaces carried
        // 1.16 times the pressure at p = 2). There the whole face's basis
        // stays, which reproduces constants.
        const double covered = covered_measure(overlaps);
        if (block.get_fe().degree == 1 && covered > 0. &&
            covered < (1. - 1e-9) * measure)
          dual = dual_basis_of_overlap(block, nodes, overlaps);
        for (const auto &[c, points] : overlaps)
          {
            const Block<dim> &facing = *blocks[other[c].block];
            integrate(block,
                      nodes,
                      dual,
                      facing,
                      other[c].block,
                      face_nodes(facing, other[c]),
                      points,
                      of_face,
                      multipliers);
          }
      }

    std::vector<Point<dim>> unpaired;
    for (const auto &multiplier : multipliers)
      {
        ContactPair<dim> pair;
        if (make_pair_of_multiplier(
              multiplier, k, coincident, declaration.description, pair))
          pairs.push_back(pair);
        else
          unpaired.push_back(multiplier.point);
      }
    return unpaired;
  }



  template std::vector<Point<2>>
  mortar_pairs(const std::vector<std::unique_ptr<Block<2>>> &,
               const InterfaceDeclaration &,
               const unsigned int,
               const double,
               const double,
               const bool,
               std::vector<ContactPair<2>> &);
  template std::vector<Point<3>>
  mortar_pairs(const std::vector<std::unique_ptr<Block<3>>> &,
               const InterfaceDeclaration &,
               const unsigned int,
               const double,
               const double,
               const bool,
               std::vector<ContactPair<3>> &);
} // namespace mbfem

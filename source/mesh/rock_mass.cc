// A jointed rock mass built from its joint sets (issue 61): the domain cut
// by every plane of every set with gmsh's OpenCASCADE fragments, each block
// meshed with hexahedra (quadrilaterals), written as a gmsh file that the
// blocks are then read from. gmsh 4.8's C++ API (Debian's libgmsh-dev).

#include <mbfem/mesh/rock_mass.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mbfem
{
  void
  RockMassParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rock mass");
    {
      prm.declare_entry("Origin",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "For Source = rock mass: the lowest corner of the "
                        "box (rectangle in 2D) that the joint sets of "
                        "'Contact/Joint sets' with a spacing cut into "
                        "blocks. x east, y north (2D: up), z up.");
      prm.declare_entry("Size",
                        "10, 10, 10",
                        Patterns::List(Patterns::Double(0.), 2, 3),
                        "The box's extent along x, y (and z).");
      prm.declare_entry("Mesh size",
                        "1",
                        Patterns::Double(0.),
                        "The target edge length of the blocks' elements. "
                        "gmsh meshes each block with triangles "
                        "(tetrahedra) of twice this size and splits each "
                        "into quadrilaterals (hexahedra); the faces two "
                        "blocks share are meshed once, so the blocks' "
                        "nodes match there.");
    }
    prm.leave_subsection();
  }



  void
  RockMassParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rock mass");
    {
      origin = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Origin")));
      size = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Size")));
      mesh_size = prm.get_double("Mesh size");
      AssertThrow(mesh_size > 0.,
                  ExcMessage("Mesh/Rock mass/Mesh size must be positive."));
    }
    prm.leave_subsection();
  }



  namespace
  {
    using Point3  = std::array<double, 3>;
    using DimTags = gmsh::vectorpair;

    /** The box of 'Mesh/Rock mass' in three coordinates (z = 0 in 2D). */
    struct Domain
    {
      Point3 origin{}, size{};
      double mesh_size = 1.;
    };

    /** 'Mesh/Rock mass' checked for a model of @p dim dimensions. */
    Domain
    domain_of(const RockMassParameters &parameters, const unsigned int dim)
    {
      for (const auto &[entry, values] :
           {std::make_pair("Origin", &parameters.origin),
            std::make_pair("Size", &parameters.size)})
        AssertThrow(values->size() == dim,
                    ExcMessage(std::string("Mesh/Rock mass/") + entry +
                               ": give " + std::to_string(dim) +
                               " numbers for a " + std::to_string(dim) +
                               "D model, not " +
                               std::to_string(values->size()) + "."));
      Domain domain;
      for (unsigned int d = 0; d < dim; ++d)
        {
          domain.origin[d] = parameters.origin[d];
          domain.size[d]   = parameters.size[d];
          AssertThrow(domain.size[d] > 0.,
                      ExcMessage("Mesh/Rock mass/Size: every extent must be "
                                 "positive."));
        }
      domain.mesh_size = parameters.mesh_size;
      return domain;
    }

    double
    dot(const Point3 &a, const Point3 &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    Point3
    cross(const Point3 &a, const Point3 &b)
    {
      return {a[1] * b[2] - a[2] * b[1],
              a[2] * b[0] - a[0] * b[2],
              a[0] * b[1] - a[1] * b[0]};
    }

    Point3
    unit(const Point3 &a)
    {
      const double n = std::sqrt(dot(a, a));
      return {a[0] / n, a[1] / n, a[2] / n};
    }

    Point3
    along(const Point3 &x, const double t, const Point3 &v)
    {
      return {x[0] + t * v[0], x[1] + t * v[1], x[2] + t * v[2]};
    }

    /**
     * gmsh for the time of one build, quiet, and finalised however the
     * build ends (an exception included): gmsh keeps one global model.
     */
    struct GmshSession
    {
      GmshSession()
      {
        // Not the user's gmshrc: the same blocks from the same input.
        gmsh::initialize(0, nullptr, false);
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::model::add("rock mass");
      }
      ~GmshSession()
      {
        gmsh::finalize();
      }
    };

    /** gmsh's last error, for a message. */
    std::string
    gmsh_error()
    {
      std::string error;
      gmsh::logger::getLastError(error);
      return error.empty() ? std::string("no message") : error;
    }

    /** The domain's corners (4 in 2D, 8 in 3D). */
    std::vector<Point3>
    corners(const Domain &domain, const unsigned int dim)
    {
      std::vector<Point3> result;
      for (unsigned int c = 0; c < (1u << dim); ++c)
        {
          Point3 x = domain.origin;
          for (unsigned int d = 0; d < dim; ++d)
            if (c & (1u << d))
              x[d] += domain.size[d];
          result.push_back(x);
        }
      return result;
    }

    /**
     * The offsets d (planes n . x = d) of @p set's planes that cut the
     * domain, not closer than a millionth of its diagonal to a corner
     * (a plane through a corner or along a face cuts nothing off).
     */
    std::vector<double>
    plane_offsets(const JointPlanes &set,
                  const Domain      &domain,
                  const unsigned int dim)
    {
      double low = 1e300, high = -1e300;
      for (const Point3 &x : corners(domain, dim))
        {
          low  = std::min(low, dot(set.normal, x));
          high = std::max(high, dot(set.normal, x));
        }
      const double diagonal      = std::sqrt(dot(domain.size, domain.size)),
                   margin        = 1e-6 * diagonal;
      const double        origin = dot(set.normal, set.point);
      std::vector<double> offsets;
      for (long k =
             std::lround(std::ceil((low + margin - origin) / set.spacing));
           origin + k * set.spacing < high - margin;
           ++k)
        offsets.push_back(origin + k * set.spacing);
      return offsets;
    }

    /**
     * A plane n . x = @p offset as a gmsh entity larger than the domain
     * (a line in 2D, a square in 3D), centred at the point of the plane
     * nearest the domain's centre.
     */
    std::pair<int, int>
    add_plane(const Point3      &n,
              const double       offset,
              const Point3      &centre,
              const double       half_width,
              const unsigned int dim)
    {
      const Point3 c = along(centre, offset - dot(n, centre), n);
      namespace occ  = gmsh::model::occ;
      if (dim == 2)
        {
          const Point3 t = {n[1], -n[0], 0.};
          const Point3 a = along(c, -half_width, t),
                       b = along(c, half_width, t);
          return {1,
                  occ::addLine(occ::addPoint(a[0], a[1], 0.),
                               occ::addPoint(b[0], b[1], 0.))};
        }
      const Point3     u = unit(std::abs(n[2]) < 0.9 ? cross({0., 0., 1.}, n) :
                                                   cross({1., 0., 0.}, n));
      const Point3     v = cross(n, u);
      std::vector<int> points, lines;
      for (const auto &[s, t] : std::vector<std::pair<double, double>>{
             {-1., -1.}, {1., -1.}, {1., 1.}, {-1., 1.}})
        {
          const Point3 x =
            along(along(c, s * half_width, u), t * half_width, v);
          points.push_back(occ::addPoint(x[0], x[1], x[2]));
        }
      for (unsigned int i = 0; i < 4; ++i)
        lines.push_back(occ::addLine(points[i], points[(i + 1) % 4]));
      return {2, occ::addPlaneSurface({occ::addCurveLoop(lines)})};
    }

    /**
     * Removes what the fragments left outside the domain: the pieces of the
     * planes that bound no block.
     */
    void
    remove_outside_pieces(const unsigned int dim)
    {
      DimTags pieces, outside;
      gmsh::model::getEntities(pieces, dim - 1);
      for (const auto &piece : pieces)
        {
          std::vector<int> up, down;
          gmsh::model::getAdjacencies(piece.first, piece.second, up, down);
          if (up.empty())
            outside.push_back(piece);
        }
      gmsh::model::occ::remove(outside, true);
      gmsh::model::occ::synchronize();
    }

    /**
     * The blocks (gmsh entities of dimension @p dim) ordered by their
     * centres: lowest first, then along y, then x, each compared to a
     * millionth of the domain's size.
     */
    std::vector<int>
    ordered_blocks(const unsigned int dim, const double scale)
    {
      DimTags entities;
      gmsh::model::getEntities(entities, dim);
      std::vector<std::pair<Point3, int>> centres;
      for (const auto &[d, tag] : entities)
        {
          Point3 c;
          gmsh::model::occ::getCenterOfMass(d, tag, c[0], c[1], c[2]);
          centres.emplace_back(c, tag);
        }
      const double tolerance = 1e-6 * scale;
      std::sort(centres.begin(),
                centres.end(),
                [&](const auto &a, const auto &b) {
                  for (int d = dim - 1; d >= 0; --d)
                    if (std::abs(a.first[d] - b.first[d]) > tolerance)
                      return a.first[d] < b.first[d];
                  return false;
                });
      std::vector<int> tags;
      for (const auto &centre : centres)
        tags.push_back(centre.second);
      return tags;
    }

    /**
     * Boundary ids of the domain's faces (edges in 2D): 1 bottom, 2 top
     * (z in 3D, y in 2D), 3 and 4 x = min and max, 5 and 6 y = min and max
     * (3D); each a physical group of the faces' pieces.
     */
    void
    add_boundary_groups(const Domain &domain, const unsigned int dim)
    {
      const unsigned int vertical = dim - 1;
      const double tolerance = 1e-6 * std::sqrt(dot(domain.size, domain.size));
      std::vector<std::vector<int>> groups(7);
      DimTags                       faces;
      gmsh::model::getEntities(faces, dim - 1);
      for (const auto &[d, tag] : faces)
        {
          std::vector<int> up, down;
          gmsh::model::getAdjacencies(d, tag, up, down);
          if (up.size() != 1)
            continue; // a joint, between two blocks
          Point3 low, high;
          gmsh::model::getBoundingBox(
            d, tag, low[0], low[1], low[2], high[0], high[1], high[2]);
          for (unsigned int axis = 0; axis < dim; ++axis)
            for (const unsigned int side : {0u, 1u})
              {
                const double plane =
                  domain.origin[axis] + side * domain.size[axis];
                if (std::abs(low[axis] - plane) > tolerance ||
                    std::abs(high[axis] - plane) > tolerance)
                  continue;
                const unsigned int id =
                  axis == vertical ? 1 + side : 3 + 2 * axis + side;
                groups[id].push_back(tag);
              }
        }
      const char *names[] = {
        "", "bottom", "top", "x min", "x max", "y min", "y max"};
      for (unsigned int id = 1; id < groups.size(); ++id)
        if (!groups[id].empty())
          {
            gmsh::model::addPhysicalGroup(dim - 1, groups[id], id);
            gmsh::model::setPhysicalName(dim - 1, id, names[id]);
          }
    }

    /** gmsh's options for an all-quadrilateral (all-hexahedral) mesh. */
    void
    set_mesh_options(const double mesh_size, const unsigned int dim)
    {
      // Each triangle (tetrahedron) is split into quadrilaterals
      // (hexahedra) of half its edge: twice the size asked for, at every
      // corner of the blocks. (With Mesh.MeshSizeMax instead, gmsh 4.8's
      // subdivision made a unit cube of 5717 nodes at size 1; with the
      // corners' sizes, 147.)
      DimTags corners;
      gmsh::model::getEntities(corners, 0);
      gmsh::model::mesh::setSize(corners, 2. * mesh_size);
      gmsh::option::setNumber("Mesh.Algorithm", 6); // Frontal-Delaunay
      if (dim == 2)
        {
          gmsh::option::setNumber("Mesh.RecombineAll", 1);
          gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);
        }
      else
        {
          gmsh::option::setNumber("Mesh.Algorithm3D", 1); // Delaunay
          gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 2);
        }
      gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
      gmsh::option::setNumber("Mesh.SaveAll", 0);
    }
  } // namespace



  namespace
  {
    /** Refusals of a set before gmsh sees it. */
    void
    check_set(const JointPlanes         &set,
              const std::vector<double> &offsets,
              const Domain              &domain)
    {
      const std::string what = "Contact/Joint sets: the set '" + set.name + "'";
      AssertThrow(set.spacing >= domain.mesh_size,
                  ExcMessage(what + " is spaced " +
                             Utilities::to_string(set.spacing) +
                             ", closer than 'Mesh/Rock mass/Mesh size' (" +
                             Utilities::to_string(domain.mesh_size) +
                             "): its blocks would be thinner than one "
                             "element. Refine the mesh size or widen the "
                             "spacing."));
      AssertThrow(!offsets.empty(),
                  ExcMessage(what +
                             " misses the domain: none of its planes (spaced " +
                             Utilities::to_string(set.spacing) +
                             " through its point) cuts the box of "
                             "'Mesh/Rock mass'. Check its point, dip and "
                             "dip direction."));
    }

    /** Every plane of every set cut into the domain (@p dim - 1 entities). */
    DimTags
    add_planes(const Domain                   &domain,
               const std::vector<JointPlanes> &sets,
               const unsigned int              dim,
               RockMassSummary                &summary)
    {
      Point3 centre = domain.origin;
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] += domain.size[d] / 2.;
      const double half_width = std::sqrt(dot(domain.size, domain.size));
      DimTags      planes;
      for (const JointPlanes &set : sets)
        {
          const std::vector<double> offsets = plane_offsets(set, domain, dim);
          check_set(set, offsets, domain);
          summary.planes_per_set.push_back(offsets.size());
          for (const double offset : offsets)
            planes.push_back(
              add_plane(set.normal, offset, centre, half_width, dim));
        }
      return planes;
    }

    /** The blocks' physical groups and measures into @p summary. */
    void
    add_block_groups(const Domain      &domain,
                     const unsigned int dim,
                     RockMassSummary   &summary)
    {
      const std::vector<int> blocks =
        ordered_blocks(dim, std::sqrt(dot(domain.size, domain.size)));
      summary.n_blocks = blocks.size();
      summary.smallest = 1e300;
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          gmsh::model::addPhysicalGroup(dim, {blocks[b]}, b + 1);
          gmsh::model::setPhysicalName(dim,
                                       b + 1,
                                       "block " + std::to_string(b + 1));
          double measure = 0.;
          gmsh::model::occ::getMass(dim, blocks[b], measure);
          summary.blocks_measure += measure;
          summary.smallest = std::min(summary.smallest, measure);
          summary.largest  = std::max(summary.largest, measure);
          // (half an element: a block of exactly one element's size is not
          // reported for its round-off)
          summary.n_small += (measure < 0.5 * std::pow(domain.mesh_size, dim));
        }
    }
  } // namespace



  template <int dim>
  RockMassSummary
  build_rock_mass(const RockMassParameters       &parameters,
                  const std::vector<JointPlanes> &sets,
                  const std::string              &msh_file)
  {
    const Domain    domain = domain_of(parameters, dim);
    RockMassSummary summary;
    summary.domain_measure = 1.;
    for (unsigned int d = 0; d < dim; ++d)
      summary.domain_measure *= domain.size[d];
    const GmshSession session;
    namespace occ = gmsh::model::occ;
    try
      {
        const auto   &o = domain.origin;
        const auto   &s = domain.size;
        const DimTags box =
          dim == 2 ?
            DimTags{{2, occ::addRectangle(o[0], o[1], 0., s[0], s[1])}} :
            DimTags{{3, occ::addBox(o[0], o[1], o[2], s[0], s[1], s[2])}};
        const DimTags planes = add_planes(domain, sets, dim, summary);
        if (!planes.empty())
          {
            DimTags              pieces;
            std::vector<DimTags> map;
            occ::fragment(box, planes, pieces, map);
          }
        occ::synchronize();
        remove_outside_pieces(dim);
        add_block_groups(domain, dim, summary);
        add_boundary_groups(domain, dim);
        set_mesh_options(domain.mesh_size, dim);
        gmsh::model::mesh::generate(dim);
        std::vector<int>                      types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, dim);
        for (const auto &t : tags)
          summary.n_cells += t.size();
        gmsh::write(msh_file);
      }
    catch (const ExceptionBase &)
      {
        throw; // our own refusals
      }
    catch (...)
      {
        AssertThrow(false,
                    ExcMessage("Mesh/Source = rock mass: gmsh could not cut "
                               "or mesh the domain by the joint sets: " +
                               gmsh_error()));
      }
    return summary;
  }



  template RockMassSummary
  build_rock_mass<2>(const RockMassParameters &,
                     const std::vector<JointPlanes> &,
                     const std::string &);
  template RockMassSummary
  build_rock_mass<3>(const RockMassParameters &,
                     const std::vector<JointPlanes> &,
                     const std::string &);
} // namespace mbfem

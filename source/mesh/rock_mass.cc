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
#include <filesystem>
#include <sstream>

namespace mbfem
{
  void
  RockMassParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rock mass");
    {
      prm.declare_entry("Domain",
                        "box",
                        Patterns::Selection("box|slope|file"),
                        "For Source = rock mass, what the joint sets of "
                        "'Contact/Joint sets' with a spacing or a point "
                        "cut into blocks: 'box' (a rectangle in 2D: Origin "
                        "and Size), or 'slope' (a profile in the x-z "
                        "plane, y up in 2D, its face dipping towards +x, "
                        "extruded along y in 3D: Origin and the Slope "
                        "entries, on the uncut Base), or 'file' (every "
                        "volume, surface in 2D, of 'Geometry file'). x "
                        "east, y north (2D: up), z up.");
      prm.declare_entry("Geometry file",
                        "",
                        Patterns::Anything(),
                        "For Domain = file: a geometry gmsh reads, .brep, "
                        ".step or .stp (OpenCASCADE), or a .geo that uses "
                        "SetFactory(\"OpenCASCADE\"); each of its volumes "
                        "(surfaces in 2D) is cut by the joints, so a "
                        "geometry of several volumes gives blocks of "
                        "several materials' extents. A relative path is "
                        "taken from the parameter file's folder.");
      prm.declare_entry("Origin",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "The box's lowest corner; for a slope the foot of "
                        "its back, at the level of its toe.");
      prm.declare_entry("Size",
                        "10, 10, 10",
                        Patterns::List(Patterns::Double(0.), 2, 3),
                        "The box's extent along x, y (and z).");
      prm.declare_entry("Slope height",
                        "10",
                        Patterns::Double(0.),
                        "From the toe to the crest.");
      prm.declare_entry("Face angle",
                        "60",
                        Patterns::Double(0., 90.),
                        "The dip of the slope's face, in degrees (its dip "
                        "direction is 90, towards +x).");
      prm.declare_entry("Crest width",
                        "10",
                        Patterns::Double(0.),
                        "From the back of the slope (x = Origin) to the "
                        "top of the face.");
      prm.declare_entry("Slope length",
                        "10",
                        Patterns::Double(0.),
                        "3D: the slope's extent along y (its strike).");
      prm.declare_entry("Base",
                        "0, 0, 0",
                        Patterns::List(Patterns::Double(0.), 3, 3),
                        "A slope's base, one block the joints do not cut "
                        "(the rock the slope was cut from): its depth "
                        "under the toe, how far it reaches behind the "
                        "slope's back (up to the crest's level) and in "
                        "front of the toe. Depth 0: no base, the slope's "
                        "bottom is the domain's (boundary id 1).");
      prm.declare_entry("Mesh size",
                        "1",
                        Patterns::Double(0.),
                        "The target edge length of the blocks' elements. "
                        "gmsh meshes each block with triangles "
                        "(tetrahedra) of twice this size and splits each "
                        "into quadrilaterals (hexahedra); the faces two "
                        "blocks share are meshed once, so the blocks' "
                        "nodes match there.");
      prm.declare_entry(
        "Block meshes",
        "split",
        Patterns::Selection("split|structured"),
        "How the blocks are meshed. split: gmsh's tetrahedra (triangles) "
        "split into hexahedra (quadrilaterals), for blocks of any shape. "
        "structured: each block a grid of hexahedra (quadrilaterals) of "
        "about 'Mesh size', gmsh's transfinite meshes, for blocks that are "
        "all hexahedra (quadrilaterals), as where three sets (two in 2D) "
        "cut a box: far fewer cells (one per block at a mesh size of the "
        "spacing); refused where a block has another shape.");
    }
    prm.leave_subsection();
  }



  void
  RockMassParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rock mass");
    {
      domain        = prm.get("Domain");
      geometry_file = prm.get("Geometry file");
      origin        = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Origin")));
      size = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Size")));
      slope_height                = prm.get_double("Slope height");
      face_angle                  = prm.get_double("Face angle");
      crest_width                 = prm.get_double("Crest width");
      slope_length                = prm.get_double("Slope length");
      const std::vector<double> b = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Base")));
      std::copy(b.begin(), b.end(), base.begin());
      mesh_size    = prm.get_double("Mesh size");
      block_meshes = prm.get("Block meshes");
      AssertThrow(mesh_size > 0.,
                  ExcMessage("Mesh/Rock mass/Mesh size must be positive."));
    }
    prm.leave_subsection();
  }



  namespace
  {
    using Point3  = std::array<double, 3>;
    using DimTags = gmsh::vectorpair;

    /**
     * 'Mesh/Rock mass' in three coordinates (z = 0 in 2D): the bounding
     * box of what the joints cut (the box, or the slope without its base)
     * and that of the whole domain, whose faces carry the boundary ids.
     */
    struct Domain
    {
      const RockMassParameters *parameters = nullptr;
      Point3                    origin{}, size{};
      Point3                    outer_origin{}, outer_size{};
      double                    mesh_size = 1.;
    };

    /** The horizontal distance from the slope's back to its toe. */
    double
    toe_of(const RockMassParameters &p)
    {
      return p.crest_width +
             p.slope_height / std::tan(p.face_angle * M_PI / 180.);
    }

    /** The slope's bounding boxes, its entries checked. */
    void
    slope_boxes(const RockMassParameters &p,
                const unsigned int        dim,
                Domain                   &domain)
    {
      const std::string where = "Mesh/Rock mass (Domain = slope): ";
      AssertThrow(p.slope_height > 0. && p.crest_width > 0. &&
                    p.face_angle > 0. && (dim == 2 || p.slope_length > 0.),
                  ExcMessage(where + "the Slope height, Crest width, Face "
                                     "angle (and in 3D the Slope length) "
                                     "must be positive."));
      const unsigned int v = dim - 1;
      domain.size[0]       = toe_of(p);
      domain.size[v]       = p.slope_height;
      if (dim == 3)
        domain.size[1] = p.slope_length;
      domain.outer_origin = domain.origin;
      domain.outer_size   = domain.size;
      if (p.base[0] > 0.)
        {
          domain.outer_origin[0] -= p.base[1];
          domain.outer_origin[v] -= p.base[0];
          domain.outer_size[0] += p.base[1] + p.base[2];
          domain.outer_size[v] += p.base[0];
        }
      else
        AssertThrow(p.base[1] == 0. && p.base[2] == 0.,
                    ExcMessage(where + "Base: a base that reaches behind "
                                       "or in front of the slope needs a "
                                       "depth (its first number)."));
    }

    /** 'Mesh/Rock mass' checked for a model of @p dim dimensions. */
    Domain
    domain_of(const RockMassParameters &parameters, const unsigned int dim)
    {
      Domain domain;
      domain.parameters = &parameters;
      domain.mesh_size  = parameters.mesh_size;
      if (parameters.domain == "file")
        {
          const std::string &file = parameters.geometry_file;
          AssertThrow(!file.empty() && std::filesystem::exists(file),
                      ExcMessage("Mesh/Rock mass/Geometry file: <" + file +
                                 "> does not exist (Domain = file)."));
          return domain; // its boxes once gmsh has read it
        }
      const bool box = (parameters.domain == "box");
      for (const auto &[entry, values] :
           {std::make_pair("Origin", &parameters.origin),
            std::make_pair("Size", &parameters.size)})
        AssertThrow(values->size() == dim ||
                      (!box && values == &parameters.size),
                    ExcMessage(std::string("Mesh/Rock mass/") + entry +
                               ": give " + std::to_string(dim) +
                               " numbers for a " + std::to_string(dim) +
                               "D model, not " +
                               std::to_string(values->size()) + "."));
      for (unsigned int d = 0; d < dim; ++d)
        {
          domain.origin[d] = parameters.origin[d];
          domain.size[d]   = box ? parameters.size[d] : 0.;
          AssertThrow(!box || domain.size[d] > 0.,
                      ExcMessage("Mesh/Rock mass/Size: every extent must be "
                                 "positive."));
        }
      domain.outer_origin = domain.origin;
      domain.outer_size   = domain.size;
      if (!box)
        slope_boxes(parameters, dim, domain);
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
      return {{a[1] * b[2] - a[2] * b[1],
               a[2] * b[0] - a[0] * b[2],
               a[0] * b[1] - a[1] * b[0]}};
    }

    Point3
    unit(const Point3 &a)
    {
      const double n = std::sqrt(dot(a, a));
      return {{a[0] / n, a[1] / n, a[2] / n}};
    }

    Point3
    along(const Point3 &x, const double t, const Point3 &v)
    {
      return {{x[0] + t * v[0], x[1] + t * v[1], x[2] + t * v[2]}};
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
     * domain's box, not closer than a millionth of its diagonal to a corner
     * (a plane through a corner or along a face cuts nothing off). A set
     * of spacing 0 is one plane (a fault) through its point.
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
      if (set.spacing == 0.)
        {
          if (origin > low + margin && origin < high - margin)
            offsets.push_back(origin);
          return offsets;
        }
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
          const Point3 t = {{n[1], -n[0], 0.}};
          const Point3 a = along(c, -half_width, t),
                       b = along(c, half_width, t);
          return {1,
                  occ::addLine(occ::addPoint(a[0], a[1], 0.),
                               occ::addPoint(b[0], b[1], 0.))};
        }
      const Point3 u = unit(std::abs(n[2]) < 0.9 ? cross({{0., 0., 1.}}, n) :
                                                   cross({{1., 0., 0.}}, n));
      const Point3 v = cross(n, u);
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
     * Boundary ids of the faces (edges in 2D) that lie on the faces of the
     * domain's bounding box: 1 bottom, 2 top (z in 3D, y in 2D), 3 and 4
     * x = min and max, 5 and 6 y = min and max (3D); each a physical group
     * of the faces' pieces. A slope's face has none.
     */
    void
    add_boundary_groups(const Domain &domain, const unsigned int dim)
    {
      const unsigned int vertical = dim - 1;
      const double       tolerance =
        1e-6 * std::sqrt(dot(domain.outer_size, domain.outer_size));
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
                  domain.outer_origin[axis] + side * domain.outer_size[axis];
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

    /**
     * The number of blocks that are not hexahedra (quadrilaterals in 2D):
     * 6 faces of 4 edges (4 edges).
     */
    unsigned int
    n_not_hexahedral(const unsigned int dim)
    {
      DimTags      blocks;
      unsigned int count = 0;
      gmsh::model::getEntities(blocks, dim);
      for (const auto &block : blocks)
        {
          DimTags faces;
          gmsh::model::getBoundary({block}, faces, false, false, false);
          bool hexahedral = faces.size() == 2 * dim;
          for (const auto &face : faces)
            if (dim == 3 && hexahedral)
              {
                DimTags edges;
                gmsh::model::getBoundary({face}, edges, false, false, false);
                hexahedral = edges.size() == 4;
              }
          count += !hexahedral;
        }
      return count;
    }

    /**
     * 'Block meshes = structured': transfinite grids of quadrilaterals
     * (hexahedra) of about the mesh size, refused where a block is not a
     * hexahedron.
     */
    void
    set_structured_options(const double mesh_size, const unsigned int dim)
    {
      const unsigned int n_other = n_not_hexahedral(dim);
      AssertThrow(n_other == 0,
                  ExcMessage("Mesh/Rock mass/Block meshes = structured: " +
                             std::to_string(n_other) + " of the blocks " +
                             (dim == 3 ? "are not hexahedra (6 faces of 4 "
                                         "edges)" :
                                         "are not quadrilaterals") +
                             ", as where a set cuts a corner off the domain; "
                             "use 'Block meshes = split'."));
      DimTags corners;
      gmsh::model::getEntities(corners, 0);
      gmsh::model::mesh::setSize(corners, mesh_size);
      gmsh::model::mesh::setTransfiniteAutomatic({}, 2.35, true);
    }

    /** gmsh's options for an all-quadrilateral (all-hexahedral) mesh. */
    void
    set_mesh_options(const Domain &domain, const unsigned int dim)
    {
      gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
      gmsh::option::setNumber("Mesh.SaveAll", 0);
      if (domain.parameters->block_meshes == "structured")
        return set_structured_options(domain.mesh_size, dim);
      // Each triangle (tetrahedron) is split into quadrilaterals
      // (hexahedra) of half its edge: twice the size asked for, at every
      // corner of the blocks. (With Mesh.MeshSizeMax instead, gmsh 4.8's
      // subdivision made a unit cube of 5717 nodes at size 1; with the
      // corners' sizes, 147.)
      DimTags corners;
      gmsh::model::getEntities(corners, 0);
      gmsh::model::mesh::setSize(corners, 2. * domain.mesh_size);
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
      AssertThrow(set.spacing == 0. || set.spacing >= domain.mesh_size,
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
                             " through its point; 0: one plane) cuts the "
                             "bounding box of 'Mesh/Rock mass'. Check its "
                             "point, dip and dip direction."));
    }

    /**
     * Whether every corner of the face (curve in 2D) @p tag lies on a
     * plane of @p set: the face is a piece of that set's joints.
     */
    bool
    on_set(const int                  tag,
           const JointPlanes         &set,
           const std::vector<double> &offsets,
           const unsigned int         dim,
           const double               tolerance)
    {
      DimTags points;
      gmsh::model::getBoundary(
        {{int(dim) - 1, tag}}, points, false, false, true);
      for (const double offset : offsets)
        {
          bool all = !points.empty();
          for (const auto &[d, point] : points)
            {
              std::vector<double> x;
              gmsh::model::getValue(0, point, {}, x);
              all = all && std::abs(dot(set.normal, {{x[0], x[1], x[2]}}) -
                                    offset) < tolerance;
            }
          if (all)
            return true;
        }
      return false;
    }

    /**
     * Physical groups of the joints between blocks, one per set with the
     * set's name (tags from 1000): the faces in one of its planes. The
     * mesh's reader hands them to the joint sets by name
     * (mesh/joint_faces.h), so each face takes its own set's law, not the
     * set of the nearest orientation.
     */
    void
    add_joint_groups(const Domain                   &domain,
                     const std::vector<JointPlanes> &sets,
                     const unsigned int              dim)
    {
      const double tolerance = 1e-6 * std::sqrt(dot(domain.size, domain.size));
      std::vector<std::vector<int>> groups(sets.size());
      DimTags                       faces;
      gmsh::model::getEntities(faces, dim - 1);
      for (const auto &[d, tag] : faces)
        {
          std::vector<int> up, down;
          gmsh::model::getAdjacencies(d, tag, up, down);
          if (up.size() != 2)
            continue; // not between two blocks
          for (unsigned int s = 0; s < sets.size(); ++s)
            if (on_set(tag,
                       sets[s],
                       plane_offsets(sets[s], domain, dim),
                       dim,
                       tolerance))
              {
                groups[s].push_back(tag);
                break;
              }
        }
      for (unsigned int s = 0; s < sets.size(); ++s)
        if (!groups[s].empty())
          {
            gmsh::model::addPhysicalGroup(dim - 1, groups[s], 1000 + s);
            gmsh::model::setPhysicalName(dim - 1, 1000 + s, sets[s].name);
          }
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

    /**
     * The blocks' physical groups and measures into @p summary; the base
     * (gmsh tag @p base, 0: none) is block 1.
     */
    void
    add_block_groups(const Domain      &domain,
                     const unsigned int dim,
                     const int          base,
                     RockMassSummary   &summary)
    {
      std::vector<int> blocks =
        ordered_blocks(dim, std::sqrt(dot(domain.size, domain.size)));
      if (base != 0)
        {
          blocks.erase(std::find(blocks.begin(), blocks.end(), base));
          blocks.insert(blocks.begin(), base);
        }
      summary.has_base = (base != 0);
      summary.n_blocks = blocks.size();
      summary.smallest = 1e300;
      for (unsigned int b = 0; b < blocks.size(); ++b)
        {
          gmsh::model::addPhysicalGroup(dim, {blocks[b]}, b + 1);
          gmsh::model::setPhysicalName(dim,
                                       b + 1,
                                       (b == 0 && base != 0) ?
                                         std::string("base") :
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



  namespace
  {
    /**
     * A polygon of points (x, v) relative to the domain's origin, v
     * upwards: a surface in 2D, in the x-z plane extruded along y by the
     * slope's length in 3D.
     */
    std::pair<int, int>
    add_profile(const std::vector<std::pair<double, double>> &xv,
                const Domain                                 &domain,
                const unsigned int                            dim)
    {
      namespace occ = gmsh::model::occ;
      std::vector<int> points, lines;
      for (const auto &[x, v] : xv)
        {
          Point3 p = domain.origin;
          p[0] += x;
          p[dim - 1] += v;
          points.push_back(occ::addPoint(p[0], p[1], p[2]));
        }
      for (unsigned int i = 0; i < points.size(); ++i)
        lines.push_back(
          occ::addLine(points[i], points[(i + 1) % points.size()]));
      const int surface = occ::addPlaneSurface({occ::addCurveLoop(lines)});
      if (dim == 2)
        return {2, surface};
      DimTags extruded;
      occ::extrude(
        {{2, surface}}, 0., domain.parameters->slope_length, 0., extruded);
      for (const auto &entity : extruded)
        if (entity.first == 3)
          return entity;
      AssertThrow(false, ExcMessage("gmsh did not extrude the slope."));
      return {};
    }

    /**
     * The volumes (surfaces in 2D) of 'Geometry file', its physical groups
     * dropped; the domain's boxes set to its bounding box.
     */
    DimTags
    read_geometry(Domain &domain, const unsigned int dim)
    {
      const std::string &file = domain.parameters->geometry_file;
      const std::string  extension =
        std::filesystem::path(file).extension().string();
      if (extension == ".geo")
        gmsh::merge(file);
      else
        {
          DimTags shapes;
          gmsh::model::occ::importShapes(file, shapes, true);
        }
      gmsh::model::occ::synchronize();
      gmsh::model::removePhysicalGroups();
      DimTags entities;
      gmsh::model::getEntities(entities, dim);
      AssertThrow(!entities.empty(),
                  ExcMessage("Mesh/Rock mass/Geometry file: <" + file +
                             "> has no " + (dim == 3 ? "volume" : "surface") +
                             " for a " + std::to_string(dim) + "D model."));
      Point3 low, high;
      gmsh::model::getBoundingBox(
        -1, -1, low[0], low[1], low[2], high[0], high[1], high[2]);
      for (unsigned int d = 0; d < 3; ++d)
        {
          domain.origin[d] = d < dim ? low[d] : 0.;
          domain.size[d]   = d < dim ? high[d] - low[d] : 0.;
        }
      domain.outer_origin = domain.origin;
      domain.outer_size   = domain.size;
      return entities;
    }

    /** What the joints cut: the box, the slope above its toe, the file's. */
    DimTags
    add_domain(Domain &domain, const unsigned int dim)
    {
      namespace occ = gmsh::model::occ;
      if (domain.parameters->domain == "file")
        return read_geometry(domain, dim);
      const auto &o = domain.origin;
      const auto &s = domain.size;
      if (domain.parameters->domain == "box")
        return {
          dim == 2 ?
            std::make_pair(2, occ::addRectangle(o[0], o[1], 0., s[0], s[1])) :
            std::make_pair(3, occ::addBox(o[0], o[1], o[2], s[0], s[1], s[2]))};
      const RockMassParameters &p   = *domain.parameters;
      const double              toe = toe_of(p), h = p.slope_height;
      return {add_profile({{0., 0.}, {toe, 0.}, {p.crest_width, h}, {0., h}},
                          domain,
                          dim)};
    }

    /**
     * The slope's base, under it and behind it up to the crest's level
     * (tag 0 where it has none), fragmented with the blocks so that the
     * faces they share match.
     */
    int
    add_base(const Domain &domain, const unsigned int dim)
    {
      const RockMassParameters &p = *domain.parameters;
      if (p.domain != "slope" || p.base[0] == 0.)
        return 0;
      const double toe = toe_of(p), h = p.slope_height, depth = p.base[0],
                   behind = p.base[1], front = toe + p.base[2];
      std::vector<std::pair<double, double>> outline = {{-behind, -depth},
                                                        {front, -depth},
                                                        {front, 0.},
                                                        {0., 0.}};
      if (behind > 0.)
        {
          outline.emplace_back(0., h);
          outline.emplace_back(-behind, h);
        }
      const std::pair<int, int> base = add_profile(outline, domain, dim);
      DimTags                   blocks, pieces;
      gmsh::model::getEntities(blocks, dim);
      blocks.erase(std::find(blocks.begin(), blocks.end(), base));
      std::vector<DimTags> map;
      gmsh::model::occ::fragment(blocks, {base}, pieces, map);
      gmsh::model::occ::synchronize();
      AssertThrow(map.back().size() == 1,
                  ExcMessage("gmsh split the slope's base."));
      return map.back()[0].second;
    }

    /** The sum of the measures of @p entities. */
    double
    measure_of(const DimTags &entities)
    {
      double sum = 0.;
      for (const auto &[d, tag] : entities)
        {
          double m = 0.;
          gmsh::model::occ::getMass(d, tag, m);
          sum += m;
        }
      return sum;
    }

    /** Cuts the domain by the planes and builds the base: the blocks. */
    int
    cut_blocks(Domain                         &domain,
               const std::vector<JointPlanes> &sets,
               const unsigned int              dim,
               RockMassSummary                &summary)
    {
      namespace occ        = gmsh::model::occ;
      const DimTags body   = add_domain(domain, dim);
      const DimTags planes = add_planes(domain, sets, dim, summary);
      occ::synchronize();
      summary.domain_measure = measure_of(body);
      if (!planes.empty())
        {
          DimTags              pieces;
          std::vector<DimTags> map;
          occ::fragment(body, planes, pieces, map);
        }
      occ::synchronize();
      remove_outside_pieces(dim);
      const int base = add_base(domain, dim);
      if (base != 0)
        summary.domain_measure += measure_of({{dim, base}});
      return base;
    }
  } // namespace



  template <int dim>
  RockMassSummary
  build_rock_mass(const RockMassParameters       &parameters,
                  const std::vector<JointPlanes> &sets,
                  const std::string              &msh_file)
  {
    Domain            domain = domain_of(parameters, dim);
    RockMassSummary   summary;
    const GmshSession session;
    try
      {
        const int base = cut_blocks(domain, sets, dim, summary);
        add_block_groups(domain, dim, base, summary);
        add_boundary_groups(domain, dim);
        add_joint_groups(domain, sets, dim);
        set_mesh_options(domain, dim);
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

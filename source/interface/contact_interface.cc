#include <mbfem/base/text_input.h>
#include <mbfem/block/boundary_conditions.h>
#include <mbfem/interface/contact_interface.h>
#include <mbfem/interface/cross_points.h>
#include <mbfem/interface/joint_assignment.h>
#include <mbfem/interface/mortar.h>
#include <mbfem/interface/mortar_cross_points.h>
#include <mbfem/mesh/mesh.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <map>
#include <set>
#include <sstream>

namespace mbfem
{
  namespace
  {
    /**
     * Contact: the interfaces and their joint laws, one value per interface
     * or per joint set.
     */
    void
    declare_interface_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Interfaces",
        "",
        Patterns::Anything(),
        "Contact interfaces separated by ';'. 'blocks 1:2' is the surface "
        "that blocks (material ids) 1 and 2 share in the mesh; 'boundaries "
        "3:4' pairs the faces with boundary id 3 (side a) with those with "
        "id 4 (side b), which may be separated by a gap. 'all' is every "
        "surface two blocks share (a jointed rock mass, a wall of blocks: "
        "one interface per pair of neighbouring blocks, side a the lower "
        "block id), with the law of its joint set ('Joint sets') or the "
        "values below; it may be followed by 'boundaries' entries. Pairs "
        "are formed at the support points of the elements; where three or "
        "more blocks meet, one pair of each loop is merged into its "
        "neighbour (doc/jointed_rock.md).");
      prm.declare_entry("Friction coefficient",
                        "0.5",
                        Patterns::List(Patterns::Double(0.)),
                        "mu of each interface (one value for all, or one "
                        "per interface in order). With 'Interfaces = all' "
                        "one value: the default for joints no joint set "
                        "claims.");
      prm.declare_entry(
        "Joint sets",
        "",
        Patterns::Anything(),
        "Laws of the joint sets, for 'Interfaces = all': sets separated by "
        "';', each 'name: key value, ...' with the keys dip, dip direction, "
        "tolerance (degrees, default 5), friction, cohesion, tensile "
        "strength, e.g. 'bedding: dip 0, friction 0.7; cross: dip 90, dip "
        "direction 90, friction 0.5, cohesion 0.1'. An interface belongs to "
        "the first set whose plane is within the tolerance of its mean "
        "plane (whichever side is up); strengths not given, and interfaces "
        "no set claims, take 'Friction coefficient', 'Cohesion' and "
        "'Tensile strength'. Dip is from the horizontal, 0 to 90; dip "
        "direction the azimuth towards which the plane dips, clockwise from "
        "+y (north) in 3D; in 2D (x east, y up) 90 dips towards +x and 270 "
        "towards -x. With 'Mesh/Source = rock mass' the keys spacing (the "
        "distance between the set's planes) and point (one of them passes "
        "through it: 2 or 3 numbers separated by spaces; default the "
        "rock mass's origin) make the set cut the domain into blocks; a "
        "point without a spacing is one plane, a fault "
        "(doc/rock_mass.md). The key group (a name) makes the set the "
        "joints of a gmsh mesh's physical group of that name (curves in 2D, "
        "surfaces in 3D, lying between the cells of two blocks): their "
        "faces take the set's law whatever their orientation, before the "
        "sets by orientation claim the rest (doc/jointed_rock.md).");
      prm.declare_entry("Cohesion",
                        "0",
                        Patterns::List(Patterns::Double(0.)),
                        "Cohesion c (stress) of each interface: a pair "
                        "sticks while |r_T| < c A + mu max(r_N, 0).");
      prm.declare_entry(
        "Tensile strength",
        "0",
        Patterns::List(Patterns::Double(0.)),
        "Tensile strength sigma_t (stress) of each interface: a pair carries "
        "tension up to sigma_t A; beyond it the pair breaks and keeps "
        "sigma_t = c = 0 for the rest of the run.");
    }

    /** Contact: how pairs are found. */
    void
    declare_search_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Search distance",
        "0",
        Patterns::Double(0.),
        "Largest initial gap between the nodes of a pair. 0: only "
        "coincident nodes are paired.");
      prm.declare_entry(
        "Mortar side",
        "coarser",
        Patterns::Selection("coarser|finer"),
        "Which side of a mortar interface carries the contact forces (one "
        "pair per node of it): the side with fewer nodes on the interface "
        "or the one with more (side a where both have as many). The "
        "coarser side gives smooth tractions and a state iteration that "
        "settles; the finer one resolves the pressure better but its "
        "shear oscillates where pairs stick (doc/mortar.md).");
    }

    /** Contact/Exact traction: 2D tractions to measure the pairs' against. */
    void
    declare_exact_traction_entries(ParameterHandler &prm)
    {
      prm.enter_subsection("Exact traction");
      {
        prm.declare_entry(
          "Compute errors",
          "false",
          Patterns::Bool(),
          "2D: at the end of the run, measure the pairs' normal traction p "
          "and tangential traction q (force / tributary area, on side b, "
          "tangent t = (-n_y, n_x)) against the functions below, as relative "
          "L2 errors weighted by the pairs' areas, per interface (q relative to "
          "the norm of p where the exact q is zero).");
        prm.enter_subsection("Normal");
        Functions::ParsedFunction<2>::declare_parameters(prm, 1);
        prm.leave_subsection();
        prm.enter_subsection("Tangential");
        Functions::ParsedFunction<2>::declare_parameters(prm, 1);
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }
  } // namespace



  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    {
      declare_interface_entries(prm);
      declare_search_entries(prm);
      declare_exact_traction_entries(prm);
    }
    prm.leave_subsection();
  }



  namespace
  {
    std::vector<double>
    per_interface(const std::string &text,
                  const unsigned int n,
                  const std::string &entry)
    {
      std::vector<double> values;
      for (const auto &value : split_list(text, ',', "Contact/" + entry))
        values.push_back(parse_finite_number(value, "'Contact/" + entry + "'"));
      if (values.size() == 1)
        values.resize(n, values[0]);
      AssertThrow(values.size() == n,
                  ExcMessage("Contact/" + entry + " has " +
                             std::to_string(values.size()) + " values for " +
                             std::to_string(n) +
                             " interfaces: give one, or one per interface."));
      return values;
    }

    /**
     * Contact/Interfaces: 'all' and the 'blocks a:b' and 'boundaries a:b'
     * entries, each checked with a message naming it.
     */
    void
    parse_interface_list(const std::string                 &text,
                         std::vector<InterfaceDeclaration> &interfaces,
                         bool                              &all_shared_faces)
    {
      interfaces.clear();
      all_shared_faces = false;
      for (const auto &entry : split_list(text, ';', "Contact/Interfaces"))
        {
          if (entry == "all")
            {
              AssertThrow(!all_shared_faces && interfaces.empty(),
                          ExcMessage("Contact/Interfaces: 'all' comes "
                                     "first and once, then 'boundaries' "
                                     "entries if any."));
              all_shared_faces = true;
              continue;
            }
          InterfaceDeclaration declaration;
          declaration.description = entry;
          std::istringstream in(entry);
          std::string        kind, sides, coupling, rest;
          in >> kind >> sides >> coupling >> rest;
          const auto ids = Utilities::split_string_list(sides, ':');
          AssertThrow((kind == "blocks" || kind == "boundaries") &&
                        ids.size() == 2 &&
                        (coupling.empty() || coupling == "mortar") &&
                        rest.empty(),
                      ExcMessage("Contact/Interfaces: cannot read '" + entry +
                                 "'; write 'blocks 1:2' or 'boundaries 3:4', "
                                 "followed by 'mortar' where the meshes of "
                                 "the two sides do not match."));
          declaration.mortar    = (coupling == "mortar");
          declaration.by_blocks = (kind == "blocks");
          AssertThrow(!(all_shared_faces && declaration.by_blocks),
                      ExcMessage("Contact/Interfaces: '" + entry +
                                 "' after 'all', which has every surface "
                                 "two blocks share already; give joints "
                                 "their laws with 'Joint sets'."));
          declaration.side_a = Utilities::string_to_int(ids[0]);
          declaration.side_b = Utilities::string_to_int(ids[1]);
          interfaces.push_back(declaration);
        }
    }
  } // namespace



  void
  ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    {
      parse_interface_list(prm.get("Interfaces"), interfaces, all_shared_faces);
      // With 'all', one value for every interface: the declared ones and
      // the default of the found ones.
      const unsigned int n =
        (all_shared_faces ? 1 : std::max<unsigned int>(interfaces.size(), 1));
      const auto mu = per_interface(prm.get("Friction coefficient"),
                                    n,
                                    "Friction coefficient");
      const auto c  = per_interface(prm.get("Cohesion"), n, "Cohesion");
      const auto st =
        per_interface(prm.get("Tensile strength"), n, "Tensile strength");
      for (unsigned int i = 0; i < interfaces.size(); ++i)
        {
          const unsigned int j                     = (all_shared_faces ? 0 : i);
          interfaces[i].joint.friction_coefficient = mu[j];
          interfaces[i].joint.cohesion             = c[j];
          interfaces[i].joint.tensile_strength     = st[j];
        }
      default_joint.friction_coefficient = mu[0];
      default_joint.cohesion             = c[0];
      default_joint.tensile_strength     = st[0];
      joint_sets = parse_joint_sets(prm.get("Joint sets"), default_joint);
      AssertThrow(joint_sets.empty() || all_shared_faces,
                  ExcMessage("Contact/Joint sets are the laws of the "
                             "interfaces found by 'Interfaces = all'; "
                             "declared interfaces take 'Friction "
                             "coefficient' etc. one by one."));
      search_distance      = prm.get_double("Search distance");
      mortar_on_finer_side = (prm.get("Mortar side") == "finer");
      prm.enter_subsection("Exact traction");
      {
        compute_traction_errors = prm.get_bool("Compute errors");
        prm.enter_subsection("Normal");
        exact_normal_traction =
          parse_function<2>(prm, 1, "Contact/Exact traction/Normal");
        prm.leave_subsection();
        prm.enter_subsection("Tangential");
        exact_tangential_traction =
          parse_function<2>(prm, 1, "Contact/Exact traction/Tangential");
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }



  template <int dim>
  Tensor<2, dim>
  frame_of_normal(const Tensor<1, dim> &normal)
  {
    Tensor<2, dim> frame;
    frame[0] = normal / normal.norm();
    if (dim == 2)
      {
        frame[1][0] = -frame[0][1];
        frame[1][1] = frame[0][0];
      }
    else
      {
        // First tangent: normal x (the axis least aligned with it).
        unsigned int axis = 0;
        for (unsigned int d = 1; d < dim; ++d)
          if (std::abs(frame[0][d]) < std::abs(frame[0][axis]))
            axis = d;
        Tensor<1, dim> e;
        e[axis]           = 1.;
        Tensor<1, dim> t1 = cross_product_3d(frame[0], e);
        t1 /= t1.norm();
        frame[1] = t1;
        frame[2] = cross_product_3d(frame[0], t1);
      }
    return frame;
  }



  namespace
  {
    /** A support point on one side of an interface, with its DoFs. */
    template <int dim>
    struct InterfaceNode
    {
      unsigned int                             block;
      std::array<types::global_dof_index, dim> dofs;
      Point<dim>                               point;
      Tensor<1, dim>                           normal; // outward, summed
      double                                   area = 0.;
      /** Its area on the faces of each mesh joint group (JointFaces). */
      std::map<unsigned int, double> area_of_group;
    };

    /**
     * The nodes of @p block on faces with @p boundary_id, with the area
     * each has on the faces of each group of @p joint_faces.
     */
    template <int dim>
    void
    collect_nodes(const Block<dim>                &block,
                  const unsigned int               block_index,
                  const types::boundary_id         boundary_id,
                  const JointFaces<dim>           &joint_faces,
                  std::vector<InterfaceNode<dim>> &nodes)
    {
      const auto &fe = block.get_fe();
      // Gauss-Lobatto points are FE_Q's support points: the quadrature
      // weight at a node is its lumped share of the face.
      const QGaussLobatto<dim - 1>         quadrature(fe.degree + 1);
      FEFaceValues<dim>                    fe_face_values(block.get_mapping(),
                                       fe,
                                       quadrature,
                                       update_values | update_JxW_values |
                                         update_normal_vectors |
                                         update_quadrature_points);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      std::map<types::global_dof_index, unsigned int> node_of_dof;

      for (const auto &cell : block.get_dof_handler().active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == boundary_id)
            {
              fe_face_values.reinit(cell, f);
              cell->get_dof_indices(dof_indices);
              const unsigned int group =
                joint_faces.group_of(cell->face(f)->center());
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  {
                    const auto [component, base] =
                      fe.system_to_component_index(i);
                    if (component != 0 ||
                        std::abs(fe_face_values.shape_value_component(i, q, 0) -
                                 1.) > 1e-10)
                      continue;
                    // Shape function i is 1 at quadrature point q: this is
                    // its node.
                    const auto [it, inserted] =
                      node_of_dof.emplace(dof_indices[i], nodes.size());
                    if (inserted)
                      {
                        InterfaceNode<dim> node;
                        node.block = block_index;
                        for (unsigned int d = 0; d < dim; ++d)
                          node.dofs[d] =
                            dof_indices[fe.component_to_system_index(d, base)];
                        node.point = fe_face_values.quadrature_point(q);
                        nodes.push_back(node);
                      }
                    nodes[it->second].area += fe_face_values.JxW(q);
                    nodes[it->second].area_of_group[group] +=
                      fe_face_values.JxW(q);
                    nodes[it->second].normal += fe_face_values.normal_vector(q);
                  }
            }
    }



    template <int dim>
    std::string
    list_points(const std::vector<Point<dim>> &points)
    {
      std::ostringstream out;
      for (unsigned int i = 0; i < std::min<std::size_t>(points.size(), 8); ++i)
        out << " (" << points[i] << ")";
      if (points.size() > 8)
        out << " ...";
      return out.str();
    }


    /**
     * The nodes of both sides of @p declaration: side[0] on side a, side[1]
     * on side b. Throws if a side has no faces.
     */
    template <int dim>
    void
    collect_sides(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                  const InterfaceDeclaration                     &declaration,
                  const JointFaces<dim>                          &joint_faces,
                  std::vector<InterfaceNode<dim>>                 side[2])
    {
      for (unsigned int s = 0; s < 2; ++s)
        {
          const unsigned int own =
            (s == 0 ? declaration.side_a : declaration.side_b);
          const unsigned int other =
            (s == 0 ? declaration.side_b : declaration.side_a);
          for (unsigned int b = 0; b < blocks.size(); ++b)
            if (!declaration.by_blocks)
              collect_nodes(*blocks[b], b, own, joint_faces, side[s]);
            else if (blocks[b]->get_id() == own)
              collect_nodes(*blocks[b],
                            b,
                            interface_boundary_id(other),
                            joint_faces,
                            side[s]);
          AssertThrow(!side[s].empty(),
                      ExcMessage(
                        "Contact interface '" + declaration.description +
                        "': side " + std::to_string(own) +
                        " has no faces in the mesh" +
                        (declaration.by_blocks ?
                           " shared with block " + std::to_string(other) :
                           std::string(" with that boundary id")) +
                        "."));
        }
    }



    /**
     * Partner of every node on each side: among the nodes within @p reach,
     * the one that faces it best, i.e. whose joining line deviates least
     * from the common normal of the two surfaces (the bisector of the two
     * outward normals). For coincident nodes this is the nearest one;
     * across a gap between curved surfaces the nearest node can be a
     * neighbour of the facing one.
     */
    template <int dim>
    void
    find_partners(const std::vector<InterfaceNode<dim>> side[2],
                  const double                          reach,
                  const double                          coincident,
                  std::vector<unsigned int>             nearest[2],
                  std::vector<double>                   distance[2])
    {
      for (unsigned int s = 0; s < 2; ++s)
        {
          const auto &mine   = side[s];
          const auto &theirs = side[1 - s];
          nearest[s].assign(mine.size(), numbers::invalid_unsigned_int);
          distance[s].assign(mine.size(), std::numeric_limits<double>::max());
          for (unsigned int i = 0; i < mine.size(); ++i)
            {
              double best_offset       = std::numeric_limits<double>::max();
              const Tensor<1, dim> n_i = mine[i].normal / mine[i].normal.norm();
              for (unsigned int j = 0; j < theirs.size(); ++j)
                {
                  const Tensor<1, dim> d      = theirs[j].point - mine[i].point;
                  const double         length = d.norm();
                  if (length > reach)
                    continue;
                  Tensor<1, dim> common =
                    n_i - theirs[j].normal / theirs[j].normal.norm();
                  common /= common.norm();
                  const double offset =
                    (length <= coincident ? 0. :
                                            (d - (d * common) * common).norm());
                  if (offset < best_offset - 1e-12 * reach ||
                      (offset < best_offset + 1e-12 * reach &&
                       length < distance[s][i]))
                    {
                      best_offset    = offset;
                      nearest[s][i]  = j;
                      distance[s][i] = length;
                    }
                }
            }
        }
    }



    /** The pair of nodes @p a and @p b at distance @p d, on interface @p k. */
    template <int dim>
    ContactPair<dim>
    make_pair_of_nodes(const InterfaceNode<dim> &a,
                       const InterfaceNode<dim> &b,
                       const double              d,
                       const double              coincident,
                       const unsigned int        k)
    {
      ContactPair<dim> pair;
      pair.interface = k;
      pair.a.block   = a.block;
      pair.a.nodes   = {{a.dofs, 1.}};
      pair.a.point   = a.point;
      pair.b.block   = b.block;
      pair.b.nodes   = {{b.dofs, 1.}};
      pair.b.point   = b.point;
      if (d <= coincident)
        {
          pair.frame       = frame_of_normal(a.normal);
          pair.initial_gap = 0.;
        }
      else
        {
          pair.frame       = frame_of_normal<dim>(b.point - a.point);
          pair.initial_gap = d;
        }
      pair.area = 0.5 * (a.area + b.area);
      return pair;
    }



    /**
     * The mesh joint group of @p node: that of most of its area, and the
     * area of each group on side a into @p groups.
     */
    template <int dim>
    unsigned int
    group_of_node(const InterfaceNode<dim> &node, PairGroups &groups)
    {
      unsigned int group = numbers::invalid_unsigned_int;
      double       most  = 0.;
      for (const auto &[g, area] : node.area_of_group)
        {
          if (g != numbers::invalid_unsigned_int)
            groups.area_between_blocks[g] += area;
          if (area > most)
            {
              most  = area;
              group = g;
            }
        }
      return group;
    }



    /**
     * The pairs of interface @p k, appended to @p pairs (their joint
     * groups to @p groups); throws with the nodes left without a partner or
     * matched ambiguously.
     */
    template <int dim>
    void
    pair_interface(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                   const ContactParameters                        &parameters,
                   const JointFaces<dim>                          &joint_faces,
                   const unsigned int                              k,
                   const double                                    coincident,
                   std::vector<ContactPair<dim>>                  &pairs,
                   PairGroups                                     &groups)
    {
      const InterfaceDeclaration     &declaration = parameters.interfaces[k];
      std::vector<InterfaceNode<dim>> side[2];
      collect_sides(blocks, declaration, joint_faces, side);
      const double reach = std::max(coincident, parameters.search_distance);
      std::vector<unsigned int> nearest[2];
      std::vector<double>       distance[2];
      find_partners(side, reach, coincident, nearest, distance);

      std::vector<Point<dim>> unmatched, ambiguous;
      std::vector<bool>       b_used(side[1].size(), false);
      for (unsigned int i = 0; i < side[0].size(); ++i)
        {
          const unsigned int j = nearest[0][i];
          if (j == numbers::invalid_unsigned_int)
            unmatched.push_back(side[0][i].point);
          else if (nearest[1][j] != i)
            ambiguous.push_back(side[0][i].point);
          else
            {
              b_used[j] = true;
              pairs.push_back(make_pair_of_nodes(
                side[0][i], side[1][j], distance[0][i], coincident, k));
              groups.of_pair.push_back(group_of_node(side[0][i], groups));
            }
        }
      for (unsigned int j = 0; j < side[1].size(); ++j)
        if (!b_used[j])
          unmatched.push_back(side[1][j].point);

      AssertThrow(unmatched.empty() && ambiguous.empty(),
                  ExcMessage(
                    "Contact interface '" + declaration.description +
                    "': " + std::to_string(unmatched.size()) +
                    " node(s) have no partner within the search distance " +
                    std::to_string(parameters.search_distance) +
                    (unmatched.empty() ? "" : ":" + list_points(unmatched)) +
                    "; " + std::to_string(ambiguous.size()) +
                    " node(s) are not the nearest of their nearest node" +
                    (ambiguous.empty() ? "" : ":" + list_points(ambiguous)) +
                    ". Both sides need nodes facing each other one to one "
                    "(matching meshes), and 'Contact/Search distance' at "
                    "least the largest initial gap."));
    }



    /**
     * 'Interfaces = all': adds to @p parameters, before the declared
     * 'boundaries' entries, one interface per pair of blocks that share
     * faces in the mesh (side a the lower block id).
     */
    template <int dim>
    void
    add_shared_faces(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                     ContactParameters                              &parameters)
    {
      // Only neighbours that are blocks of the model: an excavated one is
      // not, and the faces it leaves are free surfaces.
      std::set<unsigned int> ids;
      for (const auto &block : blocks)
        ids.insert(block->get_id());
      std::set<std::pair<unsigned int, unsigned int>> neighbours;
      for (const auto &block : blocks)
        for (const auto id : boundary_ids_of(block->get_triangulation()))
          if (id >= interface_boundary_id(0) &&
              ids.count(id - interface_boundary_id(0)) > 0)
            {
              const unsigned int other = id - interface_boundary_id(0);
              neighbours.emplace(std::min<unsigned int>(block->get_id(), other),
                                 std::max<unsigned int>(block->get_id(),
                                                        other));
            }
      std::vector<InterfaceDeclaration> found;
      for (const auto &[a, b] : neighbours)
        {
          InterfaceDeclaration declaration;
          declaration.by_blocks = true;
          declaration.side_a    = a;
          declaration.side_b    = b;
          declaration.found     = true;
          declaration.joint     = parameters.default_joint;
          declaration.description =
            "blocks " + std::to_string(a) + ":" + std::to_string(b);
          found.push_back(declaration);
        }
      AssertThrow(!found.empty(),
                  ExcMessage("Contact/Interfaces = all, but no two blocks "
                             "share a face in the mesh."));
      parameters.interfaces.insert(parameters.interfaces.begin(),
                                   found.begin(),
                                   found.end());
    }



    /**
     * One line per interface; with many found ones, a count per set.
     * @p unpaired: per interface, the mortar side's nodes without a pair.
     */
    template <int dim>
    void
    print_interfaces(const ContactParameters                    &parameters,
                     const std::vector<ContactPair<dim>>        &pairs,
                     const std::vector<std::vector<Point<dim>>> &unpaired,
                     ConditionalOStream                         &pcout)
    {
      const unsigned int        n = parameters.interfaces.size();
      std::vector<unsigned int> n_pairs(n, 0), n_gap(n, 0);
      std::vector<double>       area(n, 0.);
      for (const auto &pair : pairs)
        {
          ++n_pairs[pair.interface];
          n_gap[pair.interface] += (pair.initial_gap > 0.);
          area[pair.interface] += pair.area;
        }
      std::map<std::string, std::array<double, 2>> per_set;
      for (unsigned int k = 0; k < n; ++k)
        {
          const auto &declaration = parameters.interfaces[k];
          if (declaration.found && n > 20)
            {
              auto &entry = per_set[declaration.joint_set];
              entry[0] += 1;
              entry[1] += n_pairs[k];
              continue;
            }
          pcout << "  interface " << k + 1 << " (" << declaration.description
                << (declaration.joint_set.empty() ?
                      "" :
                      ", joint set " + declaration.joint_set)
                << "): " << n_pairs[k] << " pairs (" << n_pairs[k] - n_gap[k]
                << " coincident, " << n_gap[k] << " with a gap), area "
                << area[k]
                << ", mu = " << declaration.joint.friction_coefficient
                << ", c = " << declaration.joint.cohesion
                << ", sigma_t = " << declaration.joint.tensile_strength << "\n";
          if (!unpaired[k].empty())
            pcout << "    " << unpaired[k].size()
                  << " node(s) of its mortar side get no pair, the first at ("
                  << unpaired[k][0]
                  << "): they face too little of the other side (beyond its "
                     "ends, or farther than 'Contact/Search distance' = "
                  << parameters.search_distance
                  << "), so contact there goes unseen\n";
        }
      for (const auto &[name, count] : per_set)
        pcout << "  " << count[0] << " interfaces between blocks ("
              << (name.empty() ? "no joint set: the default law" :
                                 "joint set " + name)
              << "), " << count[1] << " pairs\n";
    }



    /**
     * A pair whose two nodes are both fixed in one global direction that
     * is oblique to the pair's frame (an inclined fault meeting a roller
     * boundary) has fewer free relative motions than contact conditions.
     * It is tied (ContactPair::tied), and said so.
     */
    template <int dim>
    void
    tie_oblique_pairs(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                      std::vector<ContactPair<dim>>                  &pairs,
                      ConditionalOStream                             &pcout)
    {
      unsigned int n_tied     = 0;
      const auto   fixed_side = [&](const PairSide<dim> &side,
                                  const unsigned int   c) {
        const auto &constraints =
          blocks[side.block]->get_physical_constraints();
        return std::all_of(
          side.nodes.begin(), side.nodes.end(), [&](const auto &node) {
            return constraints.is_constrained(node.dofs[c]) &&
                   constraints.get_constraint_entries(node.dofs[c])->empty();
          });
      };
      for (auto &pair : pairs)
        {
          bool oblique_support = false;
          for (unsigned int c = 0; c < dim; ++c)
            {
              const bool fixed = fixed_side(pair.a, c) && fixed_side(pair.b, c);
              bool       aligned = false;
              for (unsigned int i = 0; i < dim; ++i)
                aligned |= std::abs(std::abs(pair.frame[i][c]) - 1.) < 1e-10;
              oblique_support |= fixed && !aligned;
            }
          if (oblique_support)
            {
              ++n_tied;
              pair.tied  = true;
              pair.frame = unit_symmetric_tensor<dim>();
            }
        }
      if (n_tied > 0)
        pcout << "  " << n_tied
              << " pair(s) tied: both nodes on a support fixing a direction "
                 "oblique to the interface; they stick in the free direction "
                 "and the support carries the rest\n";
    }
  } // namespace



  template <int dim>
  std::vector<ContactPair<dim>>
  find_contact_pairs(const std::vector<std::unique_ptr<Block<dim>>> &blocks,
                     ContactParameters                              &parameters,
                     const JointFaces<dim> &joint_faces,
                     ConditionalOStream    &pcout)
  {
    if (parameters.all_shared_faces &&
        std::none_of(parameters.interfaces.begin(),
                     parameters.interfaces.end(),
                     [](const auto &i) { return i.found; }))
      add_shared_faces(blocks, parameters);

    double size = 0.;
    for (const auto &block : blocks)
      size = std::max(size, diameter(block->get_triangulation()));
    const double coincident = 1e-8 * size;

    std::vector<ContactPair<dim>>        pairs;
    std::vector<std::vector<Point<dim>>> unpaired(parameters.interfaces.size());
    PairGroups                           groups;
    groups.area_between_blocks.assign(joint_faces.n_groups(), 0.);
    for (unsigned int k = 0; k < parameters.interfaces.size(); ++k)
      {
        if (parameters.interfaces[k].mortar)
          unpaired[k] =
            mortar_pairs(blocks,
                         parameters.interfaces[k],
                         k,
                         std::max(coincident, parameters.search_distance),
                         coincident,
                         parameters.mortar_on_finer_side,
                         pairs);
        else
          pair_interface(
            blocks, parameters, joint_faces, k, coincident, pairs, groups);
        // Mortar pairs tie a node to a segment: no joint group of their own.
        groups.of_pair.resize(pairs.size(), numbers::invalid_unsigned_int);
      }
    assign_joint_sets(parameters, joint_faces, groups, pairs, pcout);
    print_interfaces(parameters, pairs, unpaired, pcout);
    check_mortar_cross_points(
      blocks, pairs, parameters.interfaces, coincident, pcout);

    // Node-to-node interfaces first, the mortar ones after them (the order
    // of the pair files). The loops of cross-points are loops of nodes
    // paired one to one: node-to-node pairs, and mortar pairs where the
    // meshes match; a mortar pair that ties one node to several stays out.
    std::stable_partition(pairs.begin(), pairs.end(), [&](const auto &pair) {
      return !parameters.interfaces[pair.interface].mortar;
    });
    const CrossPointReport report =
      resolve_cross_points(pairs, parameters.interfaces);
    if (report.n_merged > 0)
      pcout << "  " << report.n_points
            << " point(s) shared by three or more blocks: " << report.n_merged
            << " pair(s) closing a loop merged into their neighbours\n";

    tie_oblique_pairs(blocks, pairs, pcout);
    return pairs;
  }



  template <int dim>
  Tensor<1, dim>
  ContactPair<dim>::relative_displacement(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks) const
  {
    Tensor<1, dim> v;
    for (const int sign : {-1, 1})
      {
        const auto           &side = this->side(sign);
        const Vector<double> &u    = blocks[side.block]->get_solution();
        for (const auto &node : side.nodes)
          for (unsigned int c = 0; c < dim; ++c)
            v[c] += sign * node.weight * u(node.dofs[c]);
      }
    return v;
  }



  template struct ContactPair<2>;
  template struct ContactPair<3>;
  template Tensor<2, 2>
  frame_of_normal(const Tensor<1, 2> &);
  template Tensor<2, 3>
  frame_of_normal(const Tensor<1, 3> &);
  template std::vector<ContactPair<2>>
  find_contact_pairs(const std::vector<std::unique_ptr<Block<2>>> &,
                     ContactParameters &,
                     const JointFaces<2> &,
                     ConditionalOStream &);
  template std::vector<ContactPair<3>>
  find_contact_pairs(const std::vector<std::unique_ptr<Block<3>>> &,
                     ContactParameters &,
                     const JointFaces<3> &,
                     ConditionalOStream &);
} // namespace mbfem

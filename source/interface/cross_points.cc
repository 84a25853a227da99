#include <mbfem/interface/cross_points.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

namespace mbfem
{
  namespace
  {
    /** Union-find over the interface nodes, for the spanning forest. */
    class Forest
    {
    public:
      explicit Forest(const unsigned int n)
        : parent(n)
      {
        std::iota(parent.begin(), parent.end(), 0u);
      }

      unsigned int
      root(unsigned int i)
      {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      }

      /** Joins the trees of @p i and @p j; false if they were one already. */
      bool
      join(const unsigned int i, const unsigned int j)
      {
        const unsigned int a = root(i), b = root(j);
        if (a == b)
          return false;
        parent[std::max(a, b)] = std::min(a, b);
        return true;
      }

    private:
      std::vector<unsigned int> parent;
    };



    /**
     * The pairs that would close a loop of the node graph, in a
     * deterministic order. The graph's edges are the pairs that tie one
     * node to one node; a mortar pair that weights several nodes is no
     * edge. @p vertex receives the two vertices of each edge, @p degree the
     * number of edges at each vertex, and @p loops one vertex of each
     * connected group of nodes that has a loop (a cross-point).
     */
    template <int dim>
    std::vector<unsigned int>
    find_chords(const std::vector<ContactPair<dim>>      &pairs,
                std::vector<std::array<unsigned int, 2>> &vertex,
                std::vector<unsigned int>                &degree,
                std::set<unsigned int>                   &loops)
    {
      std::map<std::pair<unsigned int, types::global_dof_index>, unsigned int>
        index;
      vertex.assign(pairs.size(),
                    {{numbers::invalid_unsigned_int,
                      numbers::invalid_unsigned_int}});
      std::vector<unsigned int> order;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        if (ties_one_node_to_one(pairs[k]))
          {
            order.push_back(k);
            for (const int sign : {-1, 1})
              {
                const PairSide<dim> &side = pairs[k].side(sign);
                const auto [it, inserted] = index.emplace(
                  std::make_pair(side.block,
                                 side.nodes[dominant_node(side)].dofs[0]),
                  degree.size());
                if (inserted)
                  degree.push_back(0);
                ++degree[it->second];
                vertex[k][sign < 0 ? 0 : 1] = it->second;
              }
          }

      // Kruskal: pairs in the order of their interfaces (then of their
      // creation), so that a loop is closed by the pair of the interface
      // declared last.
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const unsigned int i, const unsigned int j) {
                         return pairs[i].interface < pairs[j].interface;
                       });
      Forest                    forest(degree.size());
      std::vector<unsigned int> chords;
      for (const unsigned int k : order)
        if (!forest.join(vertex[k][0], vertex[k][1]))
          chords.push_back(k);
      for (const unsigned int k : chords)
        loops.insert(forest.root(vertex[k][0]));
      return chords;
    }



    /**
     * The pair of @p chord's interface and blocks, nearest to it, that ties
     * one node to one node and whose two nodes are in no other such pair;
     * invalid if there is none.
     */
    template <int dim>
    unsigned int
    free_neighbour(const std::vector<ContactPair<dim>>            &pairs,
                   const unsigned int                              chord,
                   const std::vector<std::array<unsigned int, 2>> &vertex,
                   const std::vector<unsigned int>                &degree)
    {
      const ContactPair<dim> &c       = pairs[chord];
      unsigned int            best    = numbers::invalid_unsigned_int;
      double                  nearest = std::numeric_limits<double>::max();
      for (unsigned int k = 0; k < pairs.size(); ++k)
        if (pairs[k].interface == c.interface &&
            pairs[k].a.block == c.a.block && pairs[k].b.block == c.b.block &&
            vertex[k][0] != numbers::invalid_unsigned_int &&
            degree[vertex[k][0]] == 1 && degree[vertex[k][1]] == 1)
          {
            const double distance = (pairs[k].midpoint() - c.midpoint()).norm();
            if (distance < nearest)
              {
                nearest = distance;
                best    = k;
              }
          }
      return best;
    }



    /**
     * @p target with the nodes of @p merged added, every node's weight
     * times its pair's area over the total.
     */
    template <int dim>
    void
    merge_into(ContactPair<dim>                            &target,
               const std::vector<const ContactPair<dim> *> &merged)
    {
      std::vector<const ContactPair<dim> *> all      = {nullptr};
      ContactPair<dim>                      original = target;
      all[0]                                         = &original;
      all.insert(all.end(), merged.begin(), merged.end());
      for (const auto *pair : all)
        target.cross_point_pairs.push_back(*pair);
      double total = 0.;
      for (const auto *pair : all)
        total += pair->area;
      target.area        = total;
      target.initial_gap = 0.;
      for (const int sign : {-1, 1})
        {
          PairSide<dim> &side = (sign < 0 ? target.a : target.b);
          side.nodes.clear();
          side.point = Point<dim>();
          for (const auto *pair : all)
            {
              const double w = pair->area / total;
              for (auto node : pair->side(sign).nodes)
                {
                  node.weight *= w;
                  side.nodes.push_back(node);
                }
              side.point += w * pair->side(sign).point;
            }
        }
      for (const auto *pair : all)
        target.initial_gap += pair->area / total * pair->initial_gap;
    }
  } // namespace



  template <int dim>
  unsigned int
  dominant_node(const PairSide<dim> &side)
  {
    double largest = 0.;
    for (const auto &node : side.nodes)
      largest = std::max(largest, std::abs(node.weight));
    unsigned int dominant = numbers::invalid_unsigned_int;
    for (unsigned int i = 0; i < side.nodes.size(); ++i)
      if (std::abs(side.nodes[i].weight) > 1e-6 * largest)
        {
          if (dominant != numbers::invalid_unsigned_int)
            return numbers::invalid_unsigned_int;
          dominant = i;
        }
    return dominant;
  }



  template <int dim>
  bool
  ties_one_node_to_one(const ContactPair<dim> &pair)
  {
    return dominant_node(pair.a) != numbers::invalid_unsigned_int &&
           dominant_node(pair.b) != numbers::invalid_unsigned_int;
  }



  template <int dim>
  CrossPointReport
  resolve_cross_points(std::vector<ContactPair<dim>>           &pairs,
                       const std::vector<InterfaceDeclaration> &interfaces)
  {
    std::vector<std::array<unsigned int, 2>> vertex;
    std::vector<unsigned int>                degree;
    std::set<unsigned int>                   points;
    const std::vector<unsigned int>          chords =
      find_chords(pairs, vertex, degree, points);

    CrossPointReport report;
    if (chords.empty())
      return report;

    std::map<unsigned int, std::vector<const ContactPair<dim> *>> merged;
    for (const unsigned int c : chords)
      {
        const unsigned int target = free_neighbour(pairs, c, vertex, degree);
        const auto        &chord  = pairs[c];
        AssertThrow(
          target != numbers::invalid_unsigned_int,
          ExcMessage(
            "Contact interface '" + interfaces[chord.interface].description +
            "': the pairs at (" + Utilities::to_string(chord.midpoint()[0]) +
            ", " + Utilities::to_string(chord.midpoint()[1]) +
            (dim == 3 ? ", " + Utilities::to_string(chord.midpoint()[2]) :
                        std::string()) +
            "), a point shared by three or more blocks, close a loop, and "
            "this interface has no node outside such points to take the "
            "pair over (see doc/jointed_rock.md). " +
            (interfaces[chord.interface].mortar ?
               std::string(
                 "Its mortar pairs there weight several nodes; with "
                 "'Contact/Mortar side = finer' choose 'coarser', else "
                 "refine the mesh or raise the polynomial degree.") :
               std::string("Refine the mesh ('Mesh/Initial global "
                           "refinement') or raise the polynomial degree."))));
        merged[target].push_back(&chord);
      }
    for (const auto &[target, chords_of_target] : merged)
      merge_into(pairs[target], chords_of_target);

    std::vector<bool> is_chord(pairs.size(), false);
    for (const unsigned int c : chords)
      is_chord[c] = true;
    std::vector<ContactPair<dim>> kept;
    kept.reserve(pairs.size() - chords.size());
    for (unsigned int k = 0; k < pairs.size(); ++k)
      if (!is_chord[k])
        kept.push_back(std::move(pairs[k]));
    pairs.swap(kept);

    report.n_points = points.size();
    report.n_merged = chords.size();
    return report;
  }



  template unsigned int
  dominant_node(const PairSide<2> &);
  template unsigned int
  dominant_node(const PairSide<3> &);
  template bool
  ties_one_node_to_one(const ContactPair<2> &);
  template bool
  ties_one_node_to_one(const ContactPair<3> &);
  template CrossPointReport
  resolve_cross_points(std::vector<ContactPair<2>> &,
                       const std::vector<InterfaceDeclaration> &);
  template CrossPointReport
  resolve_cross_points(std::vector<ContactPair<3>> &,
                       const std::vector<InterfaceDeclaration> &);
} // namespace mbfem

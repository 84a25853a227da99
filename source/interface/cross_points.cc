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
     * deterministic order. @p vertex receives the two vertices of each pair,
     * @p degree the number of pairs at each vertex, and @p loops one vertex
     * of each connected group of nodes that has a loop (a cross-point).
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
      vertex.resize(pairs.size());
      for (unsigned int k = 0; k < pairs.size(); ++k)
        for (const int sign : {-1, 1})
          {
            const PairSide<dim> &side = pairs[k].side(sign);
            Assert(side.nodes.size() == 1, ExcInternalError());
            const auto [it, inserted] =
              index.emplace(std::make_pair(side.block, side.nodes[0].dofs[0]),
                            degree.size());
            if (inserted)
              degree.push_back(0);
            ++degree[it->second];
            vertex[k][sign < 0 ? 0 : 1] = it->second;
          }

      // Kruskal: pairs in the order of their interfaces (then of their
      // creation), so that a loop is closed by the pair of the interface
      // declared last.
      std::vector<unsigned int> order(pairs.size());
      std::iota(order.begin(), order.end(), 0u);
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
     * The pair of @p chord's interface and blocks, nearest to it, whose two
     * nodes are in no other pair; invalid if there is none.
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
     * @p target with the nodes of @p merged added, every node weighted by
     * its pair's area over the total.
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
              const double w    = pair->area / total;
              auto         node = pair->side(sign).nodes[0];
              node.weight       = w;
              side.nodes.push_back(node);
              side.point += w * pair->side(sign).point;
            }
        }
      for (const auto *pair : all)
        target.initial_gap += pair->area / total * pair->initial_gap;
    }
  } // namespace



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
            "pair over (see doc/jointed_rock.md). Refine the mesh ('Mesh/"
            "Initial global refinement') or raise the polynomial degree."));
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



  template CrossPointReport
  resolve_cross_points(std::vector<ContactPair<2>> &,
                       const std::vector<InterfaceDeclaration> &);
  template CrossPointReport
  resolve_cross_points(std::vector<ContactPair<3>> &,
                       const std::vector<InterfaceDeclaration> &);
} // namespace mbfem

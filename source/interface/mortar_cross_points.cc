#include <mbfem/interface/cross_points.h>
#include <mbfem/interface/mortar_cross_points.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace mbfem
{
  namespace
  {
    /** A point rounded to @p h, as a key. */
    template <int dim>
    std::array<long long, dim>
    point_key(const Point<dim> &x, const double h)
    {
      std::array<long long, dim> key;
      for (unsigned int d = 0; d < dim; ++d)
        key[d] = std::llround(x[d] / h);
      return key;
    }
  } // namespace



  namespace
  {
    /** Whether blocks @p a and @p b are joined through @p edges. */
    bool
    joined(const std::set<std::pair<unsigned int, unsigned int>> &edges,
           const unsigned int                                     a,
           const unsigned int                                     b)
    {
      std::set<unsigned int> reached{a};
      for (bool grew = true; grew;)
        {
          grew = false;
          for (const auto &[u, v] : edges)
            if (reached.count(u) != reached.count(v))
              grew = reached.insert(reached.count(u) ? v : u).second || grew;
        }
      return reached.count(b) > 0;
    }



    /** At one point: the interfaces joining its blocks, by block pair. */
    struct CrossPoint
    {
      std::string where;
      std::map<std::pair<unsigned int, unsigned int>, std::set<unsigned int>>
        interfaces;
      /**
       * The mortar interfaces with a pair here that weights several nodes
       * (the meshes do not match): the cross-point rule does not take it.
       */
      std::set<unsigned int> several;
    };
  } // namespace



  template <int dim>
  void
  check_mortar_cross_points(
    const std::vector<std::unique_ptr<Block<dim>>> &blocks,
    const std::vector<ContactPair<dim>>            &pairs,
    const std::vector<InterfaceDeclaration>        &interfaces,
    const double                                    coincident,
    ConditionalOStream                             &pcout)
  {
    if (std::none_of(interfaces.begin(), interfaces.end(), [](const auto &i) {
          return i.mortar;
        }))
      return;
    std::map<unsigned int, std::vector<Point<dim>>> points_of;
    const auto points = [&](const unsigned int b) -> const auto &
    {
      auto found = points_of.find(b);
      if (found == points_of.end())
        found = points_of.emplace(b, blocks[b]->support_points()).first;
      return found->second;
    };
    std::map<std::array<long long, dim>, CrossPoint> at;
    const double h = std::max(coincident, 1e-300);
    for (const auto &pair : pairs)
      for (const PairSide<dim> *side : {&pair.a, &pair.b})
        for (const auto &node : side->nodes)
          if (std::abs(node.weight) > 1e-6)
            {
              const Point<dim>  &x     = points(side->block)[node.dofs[0]];
              CrossPoint        &entry = at[point_key(x, h)];
              std::ostringstream where;
              where << x;
              entry.where = where.str();
              entry
                .interfaces[{std::min(pair.a.block, pair.b.block),
                             std::max(pair.a.block, pair.b.block)}]
                .insert(pair.interface);
              if (interfaces[pair.interface].mortar &&
                  !ties_one_node_to_one(pair))
                entry.several.insert(pair.interface);
            }

    // A mortar interface whose pairs at the point weight several nodes, on
    // a loop of interfaces there (its blocks are joined there also through
    // the others): the cross-point rule, which takes pairs of one node
    // against one, leaves that loop as it is.
    std::vector<std::pair<const CrossPoint *, std::string>> close;
    for (const auto &[key, entry] : at)
      for (const auto &[blocks_ab, ks] : entry.interfaces)
        {
          const auto mortar = std::find_if(ks.begin(), ks.end(), [&](auto k) {
            return entry.several.count(k) > 0;
          });
          if (mortar == ks.end())
            continue;
          std::set<std::pair<unsigned int, unsigned int>> others;
          for (const auto &[edge, k] : entry.interfaces)
            if (edge != blocks_ab)
              others.insert(edge);
          if (!joined(others, blocks_ab.first, blocks_ab.second))
            continue;
          close.emplace_back(&entry, interfaces[*mortar].description);
          break;
        }

    if (!close.empty())
      pcout << "  " << close.size() << " point(s) where a mortar interface ('"
            << close[0].second << "' at (" << close[0].first->where
            << ")) closes a loop of interfaces of three or more blocks with "
               "pairs that weight several nodes (the meshes do not match "
               "there): the cross-point rule takes pairs of one node against "
               "one only, so that loop stays, and the interface system may "
               "be nearly singular there; 'Contact/Formulation = both' checks "
               "the answer\n";
  }



  template void
  check_mortar_cross_points(const std::vector<std::unique_ptr<Block<2>>> &,
                            const std::vector<ContactPair<2>> &,
                            const std::vector<InterfaceDeclaration> &,
                            const double,
                            ConditionalOStream &);
  template void
  check_mortar_cross_points(const std::vector<std::unique_ptr<Block<3>>> &,
                            const std::vector<ContactPair<3>> &,
                            const std::vector<InterfaceDeclaration> &,
                            const double,
                            ConditionalOStream &);
} // namespace mbfem

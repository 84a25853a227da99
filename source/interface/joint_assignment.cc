#include <mbfem/interface/joint_assignment.h>

#include <deal.II/base/exceptions.h>

#include <map>
#include <string>

namespace mbfem
{
  namespace
  {
    /**
     * The joint set that names mesh group @p g ('group NAME'), or else the
     * set without a group whose own name is the group's (a rock mass's
     * groups carry their sets' names), or nullptr.
     */
    template <int dim>
    const JointSet *
    set_of_group(const ContactParameters &parameters,
                 const JointFaces<dim>   &joint_faces,
                 const unsigned int       g)
    {
      if (g == numbers::invalid_unsigned_int)
        return nullptr;
      for (const auto &set : parameters.joint_sets)
        if (!set.group.empty() && set.group == joint_faces.name(g))
          return &set;
      for (const auto &set : parameters.joint_sets)
        if (set.group.empty() && set.name == joint_faces.name(g))
          return &set;
      return nullptr;
    }

    /** Every set's group is a group of the mesh's joints. */
    template <int dim>
    void
    check_groups_named(const ContactParameters &parameters,
                       const JointFaces<dim>   &joint_faces)
    {
      std::string known;
      for (unsigned int g = 0; g < joint_faces.n_groups(); ++g)
        known += (g > 0 ? ", '" : "'") + joint_faces.name(g) + "'";
      for (const auto &set : parameters.joint_sets)
        {
          bool found = set.group.empty();
          for (unsigned int g = 0; g < joint_faces.n_groups(); ++g)
            found |= (set.group == joint_faces.name(g));
          AssertThrow(
            found,
            ExcMessage(
              "Contact/Joint sets: the set '" + set.name +
              "' names the group '" + set.group +
              "', but the mesh has no such physical group of " +
              (dim == 2 ? "curves" : "surfaces") + " between two cells (" +
              (known.empty() ? std::string("it has none") : "it has " + known) +
              "). A joint group is a physical " +
              (dim == 2 ? "curve" : "surface") +
              " whose faces lie between the cells of two blocks."));
        }
    }

    /**
     * The laws of the pairs @p first to @p last of found interface @p k;
     * returns the area of its pairs per set name ("" the default law).
     */
    template <int dim>
    std::map<std::string, double>
    assign_interface(ContactParameters             &parameters,
                     const JointFaces<dim>         &joint_faces,
                     const PairGroups              &groups,
                     const unsigned int             first,
                     const unsigned int             last,
                     std::vector<ContactPair<dim>> &pairs)
    {
      std::map<std::string, double> area_of_set;
      std::vector<unsigned int>     others;
      Tensor<1, dim>                normal;
      for (unsigned int p = first; p < last; ++p)
        if (const JointSet *set =
              set_of_group(parameters, joint_faces, groups.of_pair[p]))
          {
            pairs[p].joint     = set->joint;
            pairs[p].joint_set = set - parameters.joint_sets.data();
            area_of_set[set->name] += pairs[p].area;
          }
        else
          {
            others.push_back(p);
            normal += pairs[p].area * pairs[p].frame[0];
          }
      if (others.empty())
        return area_of_set;
      const JointSet *by_plane = nullptr;
      for (const auto &set : parameters.joint_sets)
        if (set.group.empty() && set.contains(normal))
          {
            by_plane = &set;
            break;
          }
      for (const unsigned int p : others)
        {
          pairs[p].joint =
            (by_plane ? by_plane->joint : parameters.default_joint);
          if (by_plane)
            pairs[p].joint_set = by_plane - parameters.joint_sets.data();
          area_of_set[by_plane ? by_plane->name : ""] += pairs[p].area;
        }
      return area_of_set;
    }

    /** The set of the largest area in @p area_of_set, "" the default. */
    std::string
    largest(const std::map<std::string, double> &area_of_set)
    {
      std::string name;
      double      most = -1.;
      for (const auto &[set, area] : area_of_set)
        if (area > most)
          {
            most = area;
            name = set;
          }
      return name;
    }

    /** A line per mesh joint group: its set, and its area between blocks. */
    template <int dim>
    void
    print_groups(const ContactParameters &parameters,
                 const JointFaces<dim>   &joint_faces,
                 const PairGroups        &groups,
                 ConditionalOStream      &pcout)
    {
      for (unsigned int g = 0; g < joint_faces.n_groups(); ++g)
        {
          const JointSet *set = set_of_group(parameters, joint_faces, g);
          pcout << "  joint group '" << joint_faces.name(g) << "' of the mesh: "
                << (set ? "joint set " + set->name :
                          std::string("no joint set names it (its faces "
                                      "take a set by orientation)"))
                << ", " << (dim == 2 ? "length " : "area ")
                << joint_faces.area(g);
          const double between = groups.area_between_blocks[g];
          if (between < (1. - 1e-6) * joint_faces.area(g))
            pcout << ", of which " << between
                  << " between two blocks (the rest lies inside a block, "
                     "where there is no joint: the cells on its two sides "
                     "need different blocks)";
          pcout << "\n";
        }
    }
  } // namespace



  template <int dim>
  void
  assign_joint_sets(ContactParameters             &parameters,
                    const JointFaces<dim>         &joint_faces,
                    const PairGroups              &groups,
                    std::vector<ContactPair<dim>> &pairs,
                    ConditionalOStream            &pcout)
  {
    check_groups_named(parameters, joint_faces);
    std::vector<std::string> mixed;
    for (unsigned int first = 0; first < pairs.size();)
      {
        const unsigned int k    = pairs[first].interface;
        unsigned int       last = first;
        while (last < pairs.size() && pairs[last].interface == k)
          ++last;
        InterfaceDeclaration &declaration = parameters.interfaces[k];
        if (!declaration.found)
          for (unsigned int p = first; p < last; ++p)
            pairs[p].joint = declaration.joint;
        else
          {
            const auto area_of_set = assign_interface(
              parameters, joint_faces, groups, first, last, pairs);
            declaration.joint_set = largest(area_of_set);
            for (const auto &set : parameters.joint_sets)
              if (set.name == declaration.joint_set)
                declaration.joint = set.joint;
            if (area_of_set.size() > 1)
              mixed.push_back(declaration.description);
          }
        first = last;
      }
    print_groups(parameters, joint_faces, groups, pcout);
    if (!mixed.empty())
      pcout << "  " << mixed.size()
            << " interface(s) with pairs in more than one joint set (each "
               "pair has its set's law; 'Water pressure' names the "
               "interface by the set of most of its area), the first "
            << mixed[0] << "\n";
  }



  template void
  assign_joint_sets(ContactParameters &,
                    const JointFaces<2> &,
                    const PairGroups &,
                    std::vector<ContactPair<2>> &,
                    ConditionalOStream &);
  template void
  assign_joint_sets(ContactParameters &,
                    const JointFaces<3> &,
                    const PairGroups &,
                    std::vector<ContactPair<3>> &,
                    ConditionalOStream &);
} // namespace mbfem

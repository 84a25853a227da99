#include <mbfem/mesh/gmsh_check.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

namespace mbfem
{
  using namespace dealii;

  namespace
  {
    /** Longer lines are no gmsh ASCII mesh (and /dev/zero has no end). */
    constexpr std::size_t max_line_length = 1 << 16;

    /** A file that large is no mesh mbfem can solve (2e6 cells). */
    constexpr std::uintmax_t max_file_size = std::uintmax_t(2) << 30;

    struct Line
    {
      unsigned int number;
      std::string  text;
    };

    /** The lines between $Name and $EndName, and where $Name stands. */
    struct Section
    {
      unsigned int      opened_at = 0;
      std::vector<Line> lines;
    };

    struct Element
    {
      unsigned int      line;
      int               type;
      bool              in_physical_group;
      std::vector<long> nodes;
      /** Its physical tag (0: none). */
      long group = 0;
      /** Version 4.1: the line of the head of its block of $Elements. */
      unsigned int block_line = 0;
    };

    /** What the checks need of a file: its nodes and its elements. */
    struct GmshFile
    {
      std::string                           path;
      std::map<std::string, Section>        sections;
      std::map<long, std::array<double, 3>> nodes;
      std::vector<Element>                  elements;
      /** Physical names by (dimension, tag). */
      std::map<std::pair<long, long>, std::string> names;

      [[noreturn]] void
      fail(const unsigned int line, const std::string &what) const
      {
        throw ExcMessage("The gmsh file <" + path + ">, line " +
                         std::to_string(line) + ": " + what);
      }
    };

    /** Nodes of gmsh's element types, and the dimension of each. */
    const std::map<int, std::pair<unsigned int, int>> element_types = {
      {1, {2, 1}},
      {2, {3, 2}},
      {3, {4, 2}},
      {4, {4, 3}},
      {5, {8, 3}},
      {6, {6, 3}},
      {7, {5, 3}},
      {8, {3, 1}},
      {9, {6, 2}},
      {10, {9, 2}},
      {11, {10, 3}},
      {12, {27, 3}},
      {15, {1, 0}},
      {16, {8, 2}},
      {17, {20, 3}}};

    std::vector<std::string>
    fields_of(const std::string &text)
    {
      std::istringstream       in(text);
      std::vector<std::string> fields;
      for (std::string field; in >> field;)
        fields.push_back(field);
      return fields;
    }

    double
    number(const GmshFile &file, const Line &line, const std::string &text)
    {
      char *end          = nullptr;
      errno              = 0;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || errno == ERANGE ||
          !std::isfinite(value))
        file.fail(line.number, "'" + text + "' is not a finite number.");
      return value;
    }

    long
    whole_number(const GmshFile    &file,
                 const Line        &line,
                 const std::string &text)
    {
      const double value = number(file, line, text);
      if (value != std::floor(value) || std::abs(value) > 9e15)
        file.fail(line.number, "'" + text + "' is not a whole number.");
      return static_cast<long>(value);
    }

    /** The line after @p i of @p section, or a failure: a count said more. */
    const Line &
    line_at(const GmshFile &file, const std::string &name, const std::size_t i)
    {
      const Section &section = file.sections.at(name);
      if (i >= section.lines.size())
        file.fail(section.lines.empty() ? section.opened_at :
                                          section.lines.back().number,
                  "the section $" + name + " (line " +
                    std::to_string(section.opened_at) +
                    ") ends before the count it gives at its start: is the "
                    "file cut off or edited?");
      return section.lines[i];
    }

    /** Field @p i of @p line, or a failure naming what the line needs. */
    const std::string &
    field(const GmshFile                 &file,
          const Line                     &line,
          const std::vector<std::string> &fields,
          const std::size_t               i)
    {
      if (i >= fields.size())
        file.fail(line.number,
                  "the line has " + std::to_string(fields.size()) +
                    " fields where at least " + std::to_string(i + 1) +
                    " are needed.");
      return fields[i];
    }

    /** The first number of line @p i of @p section (a count). */
    long
    count_at(const GmshFile &file, const std::string &section, std::size_t i)
    {
      const Line &line   = line_at(file, section, i);
      const auto  fields = fields_of(line.text);
      return whole_number(file, line, field(file, line, fields, 0));
    }

    /**
     * The four numbers that open a block of $Nodes or $Elements in version
     * 4.1 ('dim tag parametric count', 'dim tag type count').
     */
    std::array<long, 4>
    block_head(const GmshFile &file, const std::string &section, std::size_t i)
    {
      const Line &line   = line_at(file, section, i);
      const auto  fields = fields_of(line.text);
      if (fields.size() != 4)
        file.fail(line.number,
                  "a block of $" + section + " starts with 4 numbers.");
      return {{whole_number(file, line, fields[0]),
               whole_number(file, line, fields[1]),
               whole_number(file, line, fields[2]),
               whole_number(file, line, fields[3])}};
    }

    /** Reads @p path into sections, with bounded lines and size. */
    void
    read_sections(GmshFile &file)
    {
      namespace fs = std::filesystem;
      std::error_code ec;
      AssertThrow(fs::is_regular_file(file.path, ec),
                  ExcMessage("The mesh file <" + file.path +
                             "> named by 'Mesh/Mesh file' is not a regular "
                             "file (a folder or a device); name a gmsh .msh "
                             "file."));
      AssertThrow(fs::file_size(file.path, ec) <= max_file_size,
                  ExcMessage("The mesh file <" + file.path + "> has " +
                             std::to_string(fs::file_size(file.path, ec)) +
                             " bytes, more than a mesh mbfem can solve "
                             "(2 GiB)."));
      std::ifstream     in(file.path);
      std::string       current;
      std::vector<char> buffer(max_line_length + 1);
      for (unsigned int number = 1;; ++number)
        {
          in.getline(buffer.data(), buffer.size());
          if (in.fail() && !in.eof())
            file.fail(number,
                      "the line is longer than " +
                        std::to_string(max_line_length) +
                        " characters: this is no gmsh ASCII mesh file.");
          // A file saved on Windows ends its lines with "\r\n".
          std::string text(buffer.data());
          if (!text.empty() && text.back() == '\r')
            text.pop_back();
          if (in.eof() && text.empty())
            break;
          if (!text.empty() && text[0] == '$')
            {
              const std::string name =
                text.substr(1, text.find_last_not_of(" \t\r"));
              if (name.rfind("End", 0) == 0)
                {
                  if (name.substr(3) != current)
                    file.fail(number,
                              "$" + name + " closes no open section" +
                                (current.empty() ?
                                   "" :
                                   " ($" + current + " is open)") +
                                ".");
                  current.clear();
                }
              else
                {
                  if (!current.empty())
                    file.fail(
                      number,
                      "$" + name + " opens inside $" + current + " (line " +
                        std::to_string(file.sections[current].opened_at) +
                        "), which has no $End" + current + ".");
                  current                       = name;
                  file.sections[name].opened_at = number;
                  file.sections[name].lines.clear();
                }
            }
          else if (!current.empty())
            file.sections[current].lines.push_back({number, text});
          if (in.eof())
            {
              if (!current.empty())
                file.fail(number,
                          "the file ends inside the section $" + current +
                            " opened at line " +
                            std::to_string(file.sections[current].opened_at) +
                            ": is it cut off?");
              break;
            }
        }
      for (const char *name : {"MeshFormat", "Nodes", "Elements"})
        if (file.sections.count(name) == 0)
          file.fail(1,
                    std::string("the file has no section $") + name +
                      ": it is no gmsh mesh, or it is cut off.");
    }

    /** The version, 2 or 4, of an ASCII file. */
    int
    check_format(const GmshFile &file)
    {
      const Line &line   = line_at(file, "MeshFormat", 0);
      const auto  fields = fields_of(line.text);
      if (fields.size() != 3)
        file.fail(line.number,
                  "$MeshFormat needs 'version file-type "
                  "data-size'.");
      const double version = number(file, line, fields[0]);
      if (fields[1] != "0")
        file.fail(line.number,
                  "the mesh is stored in binary; save it as ASCII "
                  "(gmsh: Mesh.Binary = 0).");
      if (!(version >= 2. && version < 3.) && version != 4.1)
        file.fail(line.number,
                  "gmsh format " + fields[0] +
                    ": mbfem reads versions 2.2 and 4.1 (gmsh: "
                    "Mesh.MshFileVersion = 2.2).");
      return version < 3. ? 2 : 4;
    }

    void
    read_physical_names(GmshFile &file)
    {
      if (file.sections.count("PhysicalNames") == 0)
        return;
      const Line             &first = line_at(file, "PhysicalNames", 0);
      const long              n     = whole_number(file, first, first.text);
      static const std::regex entry(R"(\s*[0-3]\s+[0-9]+\s+"[^"]*"\s*)");
      for (long i = 1; i <= n; ++i)
        {
          const Line &line = line_at(file, "PhysicalNames", i);
          if (!std::regex_match(line.text, entry))
            file.fail(line.number,
                      "a physical name needs 'dimension tag \"name\"' "
                      "(with both quotes).");
          std::istringstream in(line.text);
          long               dim = 0, tag = 0;
          in >> dim >> tag;
          const auto quote = line.text.find('"');
          file.names[{dim, tag}] =
            line.text.substr(quote + 1, line.text.rfind('"') - quote - 1);
        }
    }

    std::array<double, 3>
    coordinates(const GmshFile                 &file,
                const Line                     &line,
                const std::vector<std::string> &fields,
                const std::size_t               first)
    {
      if (fields.size() < first + 3)
        file.fail(line.number, "a node needs x, y and z.");
      return {{number(file, line, fields[first]),
               number(file, line, fields[first + 1]),
               number(file, line, fields[first + 2])}};
    }

    void
    add_node(GmshFile                    &file,
             const Line                  &line,
             const long                   tag,
             const std::array<double, 3> &x)
    {
      if (!file.nodes.emplace(tag, x).second)
        file.fail(line.number,
                  "node " + std::to_string(tag) + " is given twice.");
    }

    void
    add_element(GmshFile                       &file,
                const Line                     &line,
                const long                      type,
                const long                      group,
                const std::vector<std::string> &fields,
                const std::size_t               first_node)
    {
      const bool in_physical_group = group > 0;
      const auto t                 = element_types.find(static_cast<int>(
        std::max(std::min(type, long(INT_MAX)), long(INT_MIN))));
      if (t == element_types.end())
        file.fail(line.number,
                  "element type " + std::to_string(type) +
                    " is none mbfem reads (quadrilaterals, "
                    "hexahedra and their faces).");
      if (fields.size() != first_node + t->second.first)
        file.fail(line.number,
                  "an element of type " + std::to_string(type) + " needs " +
                    std::to_string(t->second.first) + " nodes.");
      Element element{line.number, t->first, in_physical_group, {}, group};
      for (std::size_t i = first_node; i < fields.size(); ++i)
        element.nodes.push_back(whole_number(file, line, fields[i]));
      file.elements.push_back(element);
    }

    /** Version 2.2: $Nodes and $Elements, each a count and one line each. */
    void
    read_version_2(GmshFile &file)
    {
      for (long i = 1, n = count_at(file, "Nodes", 0); i <= n; ++i)
        {
          const Line &line   = line_at(file, "Nodes", i);
          const auto  fields = fields_of(line.text);
          add_node(file,
                   line,
                   whole_number(file, line, field(file, line, fields, 0)),
                   coordinates(file, line, fields, 1));
        }
      for (long i = 1, n = count_at(file, "Elements", 0); i <= n; ++i)
        {
          const Line &line   = line_at(file, "Elements", i);
          const auto  fields = fields_of(line.text);
          const long  n_tags =
            whole_number(file, line, field(file, line, fields, 2));
          if (n_tags < 0 || fields.size() < 3 + std::size_t(n_tags))
            file.fail(line.number, "the element has fewer tags than it says.");
          const long group =
            n_tags > 0 ? std::max(whole_number(file, line, fields[3]), 0l) : 0;
          add_element(file,
                      line,
                      whole_number(file, line, fields[1]),
                      group,
                      fields,
                      3 + n_tags);
        }
    }

    /** Version 4.1, $Entities: the first physical tag of each (dim, tag). */
    std::map<std::pair<long, long>, long>
    read_entities(const GmshFile &file)
    {
      std::map<std::pair<long, long>, long> physical;
      if (file.sections.count("Entities") == 0)
        return physical;
      const Line &counts = line_at(file, "Entities", 0);
      const auto  n      = fields_of(counts.text);
      std::size_t i      = 1;
      for (long dim = 0; dim < 4; ++dim)
        for (long e = whole_number(file, counts, field(file, counts, n, dim));
             e > 0;
             --e, ++i)
          {
            const Line &line   = line_at(file, "Entities", i);
            const auto  fields = fields_of(line.text);
            // A point: tag x y z; curves and up: tag and a bounding box.
            const std::size_t at = (dim == 0 ? 4 : 7);
            const long        tag =
              whole_number(file, line, field(file, line, fields, 0));
            physical[{dim, tag}] =
              whole_number(file, line, field(file, line, fields, at)) > 0 ?
                std::max(whole_number(file,
                                      line,
                                      field(file, line, fields, at + 1)),
                         0l) :
                0;
          }
      return physical;
    }

    /** Version 4.1: $Entities gives the physical groups, then blocks. */
    void
    read_version_4(GmshFile &file)
    {
      auto        physical = read_entities(file);
      std::size_t i        = 1;
      for (long b = count_at(file, "Nodes", 0); b > 0; --b)
        {
          // The block's node tags, one a line, then their coordinates.
          const long        count = block_head(file, "Nodes", i++)[3];
          const std::size_t tags  = i;
          i += std::max(count, 0l);
          for (long k = 0; k < count; ++k, ++i)
            {
              const Line &tag = line_at(file, "Nodes", tags + k);
              const Line &x   = line_at(file, "Nodes", i);
              add_node(file,
                       x,
                       whole_number(file, tag, tag.text),
                       coordinates(file, x, fields_of(x.text), 0));
            }
        }
      i = 1;
      for (long b = count_at(file, "Elements", 0); b > 0; --b)
        {
          const unsigned int head_line = line_at(file, "Elements", i).number;
          const auto         head      = block_head(file, "Elements", i++);
          for (long k = head[3]; k > 0; --k, ++i)
            {
              const Line &line = line_at(file, "Elements", i);
              add_element(file,
                          line,
                          head[2],
                          physical[{head[0], head[1]}],
                          fields_of(line.text),
                          1);
              file.elements.back().block_line = head_line;
            }
        }
    }



    /**
     * The largest |Jacobian determinant| at a corner of a quadrilateral or
     * hexahedron (the cross or triple product of the edges that meet
     * there): zero only if the whole cell is flat. A bow-tie or a
     * collapsed node has corners of either sign or some of zero; those
     * pass here and mesh_checks.h names them after deal.II has read them.
     */
    double
    largest_corner_jacobian(const GmshFile    &file,
                            const Element     &cell,
                            const unsigned int dim)
    {
      const unsigned int                 n = (dim == 2 ? 4 : 8);
      std::vector<std::array<double, 3>> x;
      for (unsigned int v = 0; v < n; ++v)
        x.push_back(file.nodes.at(cell.nodes[v]));
      const auto edge = [&](const unsigned int from, const unsigned int to) {
        return std::array<double, 3>{{x[to][0] - x[from][0],
                                      x[to][1] - x[from][1],
                                      x[to][2] - x[from][2]}};
      };
      double largest = 0.;
      for (unsigned int v = 0; v < n; ++v)
        {
          const unsigned int base = (v / 4) * 4, i = v % 4;
          const auto         a = edge(v, base + (i + 1) % 4);
          const auto         b = edge(v, base + (i + 3) % 4);
          double             j = a[0] * b[1] - a[1] * b[0];
          if (dim == 3)
            {
              const auto c = edge(v, v < 4 ? v + 4 : v - 4);
              j            = c[0] * (a[1] * b[2] - a[2] * b[1]) -
                  c[1] * (a[0] * b[2] - a[2] * b[0]) +
                  c[2] * (a[0] * b[1] - a[1] * b[0]);
            }
          largest = std::max(largest, std::abs(j));
        }
      return largest;
    }



    /** The elements against the nodes, the groups and the geometry. */
    void
    check_elements(const GmshFile    &file,
                   const unsigned int dim,
                   const bool         groups_give_blocks)
    {
      std::map<long, bool> used;
      const Element       *cell_outside_groups = nullptr;
      bool                 some_in_groups      = false;
      unsigned int         n_cells             = 0;
      for (const auto &element : file.elements)
        {
          for (const long node : element.nodes)
            if (file.nodes.count(node) == 0)
              file.fail(element.line,
                        "the element names node " + std::to_string(node) +
                          ", which $Nodes does not have.");
            else
              used[node] = true;
          if (element_types.at(element.type).second != int(dim))
            continue;
          ++n_cells;
          some_in_groups = some_in_groups || element.in_physical_group;
          if (!element.in_physical_group && cell_outside_groups == nullptr)
            cell_outside_groups = &element;
          if (element.nodes.size() < (dim == 2 ? 4u : 8u))
            continue; // a triangle or tetrahedron: refused after reading
          const double size     = largest_corner_jacobian(file, element, dim);
          double       diameter = 0.;
          for (const long a : element.nodes)
            for (unsigned int d = 0; d < 3; ++d)
              diameter = std::max(diameter,
                                  std::abs(file.nodes.at(a)[d] -
                                           file.nodes.at(element.nodes[0])[d]));
          if (size <= 1e-12 * std::pow(diameter, dim))
            file.fail(element.line,
                      std::string("the cell has zero ") +
                        (dim == 2 ? "area" : "volume") +
                        " (its corners coincide or lie on a line or plane).");
        }
      if (n_cells == 0)
        file.fail(file.sections.at("Elements").opened_at,
                  "the file has no " + std::to_string(dim) +
                    "D cells: is 'Dimension' right, and were the " +
                    (dim == 2 ? "surfaces" : "volumes") + " meshed?");
      if (groups_give_blocks && some_in_groups &&
          cell_outside_groups != nullptr)
        file.fail(cell_outside_groups->line,
                  "the cell belongs to no physical group while others do; it "
                  "would become block 0. Put every " +
                    std::string(dim == 2 ? "surface" : "volume") +
                    " in a physical group (its block).");
      if (used.size() < file.nodes.size())
        file.fail(file.sections.at("Nodes").opened_at,
                  std::to_string(file.nodes.size() - used.size()) + " of the " +
                    std::to_string(file.nodes.size()) +
                    " nodes belong to no element: were elements removed "
                    "from the file?");
    }



    /** The corners of the faces of a quadrilateral or hexahedron (gmsh). */
    const std::vector<std::vector<unsigned int>> &
    corners_of_faces(const unsigned int dim)
    {
      static const std::vector<std::vector<unsigned int>> lines = {{0, 1},
                                                                   {1, 2},
                                                                   {2, 3},
                                                                   {3, 0}};
      static const std::vector<std::vector<unsigned int>> quads = {
        {0, 1, 2, 3},
        {4, 5, 6, 7},
        {0, 1, 5, 4},
        {1, 2, 6, 5},
        {2, 3, 7, 6},
        {3, 0, 4, 7}};
      return dim == 2 ? lines : quads;
    }

    /** A face by its corner nodes, in any order. */
    using FaceKey = std::array<long, 4>;

    FaceKey
    face_key(const std::vector<long> &nodes, const unsigned int n_corners)
    {
      FaceKey key{{-1, -1, -1, -1}};
      std::copy(nodes.begin(), nodes.begin() + n_corners, key.begin());
      std::sort(key.begin(), key.begin() + n_corners);
      return key;
    }

    /**
     * The elements of dimension dim-1 in a physical group that lie between
     * two cells: joints of a hand-made mesh, which deal.II's GridIn refuses
     * ("a boundary id for an internal face").
     */
    std::vector<const Element *>
    interior_group_elements(const GmshFile &file, const unsigned int dim)
    {
      const unsigned int     n_cell_corners = (dim == 2 ? 4 : 8);
      const unsigned int     n_face_corners = (dim == 2 ? 2 : 4);
      std::map<FaceKey, int> cells_at;
      for (const auto &element : file.elements)
        if (element_types.at(element.type).second == int(dim) &&
            element.nodes.size() >= n_cell_corners)
          for (const auto &face : corners_of_faces(dim))
            {
              std::vector<long> corners;
              for (const unsigned int v : face)
                corners.push_back(element.nodes[v]);
              ++cells_at[face_key(corners, n_face_corners)];
            }
      std::vector<const Element *> interior;
      for (const auto &element : file.elements)
        if (element.group > 0 &&
            element_types.at(element.type).second == int(dim) - 1 &&
            element.nodes.size() >= n_face_corners)
          {
            const auto at =
              cells_at.find(face_key(element.nodes, n_face_corners));
            if (at != cells_at.end() && at->second >= 2)
              interior.push_back(&element);
          }
      return interior;
    }

    /**
     * The text of @p file without the elements on the lines @p removed,
     * with the counts of $Elements (and of its blocks, version 4.1) reduced
     * to match.
     */
    std::string
    text_without(const GmshFile                     &file,
                 const std::vector<const Element *> &removed)
    {
      std::set<unsigned int>       lines;
      std::map<unsigned int, long> per_block;
      for (const Element *element : removed)
        {
          lines.insert(element->line);
          ++per_block[element->block_line];
        }
      std::vector<std::pair<unsigned int, std::string>> order;
      for (const auto &[name, section] : file.sections)
        order.emplace_back(section.opened_at, name);
      std::sort(order.begin(), order.end());
      std::ostringstream out;
      for (const auto &[opened_at, name] : order)
        {
          out << '$' << name << '\n';
          const Section &section = file.sections.at(name);
          for (std::size_t i = 0; i < section.lines.size(); ++i)
            {
              const Line &line = section.lines[i];
              if (name != "Elements")
                out << line.text << '\n';
              else if (lines.count(line.number) > 0)
                continue;
              else if (i == 0 || per_block.count(line.number) > 0)
                {
                  // The count of all elements (first field in 2.2, second
                  // in 4.1), or the count of a block (its fourth field).
                  auto         fields = fields_of(line.text);
                  const size_t at = (i > 0 ? 3 : fields.size() == 1 ? 0 : 1);
                  const long   n =
                    (i > 0 ? per_block.at(line.number) : long(removed.size()));
                  fields[at] = std::to_string(std::stol(fields[at]) - n);
                  for (const auto &f : fields)
                    out << f << ' ';
                  out << '\n';
                }
              else
                out << line.text << '\n';
            }
          out << "$End" << name << '\n';
        }
      return out.str();
    }

    /** The joints of @p file: names, corners, and the text GridIn reads. */
    GmshJointElements
    joint_elements(const GmshFile &file, const unsigned int dim)
    {
      GmshJointElements joints;
      const auto        interior = interior_group_elements(file, dim);
      if (interior.empty())
        return joints;
      const unsigned int n_face_corners = (dim == 2 ? 2 : 4);
      for (const Element *element : interior)
        {
          const auto name = file.names.find({dim - 1, element->group});
          joints.names[element->group] =
            (name != file.names.end() ? name->second :
                                        std::to_string(element->group));
          std::vector<std::array<double, 3>> corners;
          for (unsigned int v = 0; v < n_face_corners; ++v)
            corners.push_back(file.nodes.at(element->nodes[v]));
          joints.elements.emplace_back(element->group, corners);
        }
      joints.text_for_grid_in = text_without(file, interior);
      return joints;
    }
  } // namespace



  GmshJointElements
  check_gmsh_file(const std::string &path,
                  const unsigned int dim,
                  const bool         groups_give_blocks)
  {
    GmshFile file;
    file.path = path;
    read_sections(file);
    const int version = check_format(file);
    read_physical_names(file);
    if (version == 2)
      read_version_2(file);
    else
      read_version_4(file);
    check_elements(file, dim, groups_give_blocks);
    return joint_elements(file, dim);
  }
} // namespace mbfem

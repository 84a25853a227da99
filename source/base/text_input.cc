#include <mbfem/base/text_input.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <set>

namespace mbfem
{
  using namespace dealii;

  double
  parse_finite_number(const std::string &text, const std::string &where)
  {
    const std::string trimmed = Utilities::trim(text);
    char             *end     = nullptr;
    errno                     = 0;
    const double value        = std::strtod(trimmed.c_str(), &end);
    AssertThrow(!trimmed.empty() && end == trimmed.c_str() + trimmed.size() &&
                  errno != ERANGE && std::isfinite(value),
                ExcMessage(where + ": '" + trimmed +
                           "' is not a finite number (write one number, "
                           "without operators or trailing text)."));
    return value;
  }



  std::vector<std::string>
  split_list(const std::string &text,
             const char         delimiter,
             const std::string &where)
  {
    std::vector<std::string> entries;
    if (Utilities::trim(text).empty())
      return entries;
    std::size_t begin = 0;
    while (true)
      {
        const std::size_t end = text.find(delimiter, begin);
        entries.push_back(Utilities::trim(text.substr(begin, end - begin)));
        AssertThrow(!entries.back().empty(),
                    ExcMessage("'" + where + "' = '" + text + "': entry " +
                               std::to_string(entries.size()) +
                               " is empty; remove the extra '" +
                               std::string(1, delimiter) +
                               "' or write the missing value."));
        if (end == std::string::npos)
          return entries;
        begin = end + 1;
      }
  }



  std::vector<unsigned int>
  parse_id_list(const std::string &text,
                const std::string &where,
                const unsigned int max)
  {
    std::vector<unsigned int> ids;
    for (const auto &entry : split_list(text, ',', where))
      {
        const double id = parse_finite_number(entry, "'" + where + "'");
        AssertThrow(id >= 0. && id <= max && id == std::floor(id),
                    ExcMessage("'" + where + "': '" + entry +
                               "' is not an id (a whole number from 0 to " +
                               std::to_string(max) + ")."));
        AssertThrow(std::find(ids.begin(), ids.end(), id) == ids.end(),
                    ExcMessage("'" + where + "' = '" + text + "': id " + entry +
                               " is named twice."));
        ids.push_back(static_cast<unsigned int>(id));
      }
    return ids;
  }



  std::map<unsigned int, unsigned int>
  parse_id_values(const std::string &text,
                  const std::string &where,
                  const unsigned int min,
                  const unsigned int max)
  {
    std::map<unsigned int, unsigned int> values;
    for (const auto &entry : split_list(text, ';', where))
      {
        const auto parts = split_list(entry, ':', where);
        AssertThrow(parts.size() == 2,
                    ExcMessage("'" + where + "': cannot read '" + entry +
                               "'; write 'id: value', entries separated by "
                               "';'."));
        const auto ids = parse_id_list(parts[0], where);
        AssertThrow(ids.size() == 1,
                    ExcMessage("'" + where + "': '" + entry +
                               "' needs one block id before ':' (give each "
                               "block its own entry, separated by ';')."));
        const double value = parse_finite_number(parts[1], "'" + where + "'");
        AssertThrow(value >= min && value <= max && value == std::floor(value),
                    ExcMessage("'" + where + "': '" + entry + "': " + parts[1] +
                               " is not a whole number from " +
                               std::to_string(min) + " to " +
                               std::to_string(max) + "."));
        AssertThrow(
          values.emplace(ids[0], static_cast<unsigned int>(value)).second,
          ExcMessage("'" + where + "': block " + parts[0] +
                     " is listed twice; give each block once."));
      }
    return values;
  }


  namespace
  {
    /** A name muparser takes for a variable or constant. */
    bool
    is_name(const std::string &name)
    {
      static const std::regex pattern("[A-Za-z_][A-Za-z0-9_]*");
      return std::regex_match(name, pattern);
    }
  } // namespace



  void
  check_variable_names(const std::string &variables,
                       const unsigned int dim,
                       const std::string &where)
  {
    const std::string entry = "'" + where + "/Variable names'";
    const auto        names = split_list(variables, ',', entry);
    AssertThrow(names.size() == dim || names.size() == dim + 1,
                ExcMessage(
                  entry + " = '" + variables + "': a " + std::to_string(dim) +
                  "D function needs " + std::to_string(dim) +
                  " names of coordinates and optionally one of "
                  "time, separated by ',' (e.g. '" +
                  std::string(dim == 2 ? "x,y,t" : "x,y,z,t") + "')."));
    for (unsigned int i = 0; i < names.size(); ++i)
      {
        AssertThrow(is_name(names[i]),
                    ExcMessage(entry + " = '" + variables + "': '" + names[i] +
                               "' is not a name (a letter or '_', then "
                               "letters, digits or '_')."));
        AssertThrow(std::find(names.begin(), names.begin() + i, names[i]) ==
                      names.begin() + i,
                    ExcMessage(entry + " = '" + variables + "': '" + names[i] +
                               "' is named twice."));
      }
  }



  void
  check_function_constants(const std::string &constants,
                           const std::string &variables,
                           const std::string &where)
  {
    const std::string entry   = "'" + where + "/Function constants'";
    const auto variable_names = Utilities::split_string_list(variables, ',');
    for (const auto &constant : split_list(constants, ',', entry))
      {
        const auto parts = Utilities::split_string_list(constant, '=');
        AssertThrow(parts.size() == 2,
                    ExcMessage(entry + ": cannot read '" + constant +
                               "'; write 'name=value'."));
        AssertThrow(is_name(parts[0]),
                    ExcMessage(entry + ": in '" + constant + "', '" + parts[0] +
                               "' is not a name (a letter or '_', then "
                               "letters, digits or '_')."));
        AssertThrow(
          std::find(variable_names.begin(), variable_names.end(), parts[0]) ==
            variable_names.end(),
          ExcMessage(entry + ": '" + parts[0] +
                     "' is one of the function's variables ('" + variables +
                     "'); give the constant another name."));
        parse_finite_number(parts[1], entry + ", constant '" + parts[0] + "'");
      }
  }



  void
  check_boundary_id(const types::boundary_id            id,
                    const std::string                  &entry,
                    const std::set<types::boundary_id> &present)
  {
    std::string ids_text;
    for (const auto present_id : present)
      ids_text += (ids_text.empty() ? "" : ", ") + std::to_string(present_id);
    AssertThrow(present.count(id) == 1,
                ExcMessage("Boundary id " + std::to_string(id) + " named in '" +
                           entry +
                           "' is not on the boundary of the mesh, whose "
                           "boundary ids are: " +
                           ids_text + "."));
  }
} // namespace mbfem

#include <mbfem/base/text_input.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

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
} // namespace mbfem

#ifndef mbfem_base_text_input_h
#define mbfem_base_text_input_h

#include <deal.II/base/types.h>

#include <map>
#include <set>
#include <string>
#include <vector>

/**
 * @file Reading numbers and lists from the text of a parameter, strictly:
 * deal.II's own conversions read the first number of '2/3', accept inf and
 * nan, and drop a trailing delimiter. Every error names the parameter
 * (@p where) and the text.
 */

namespace mbfem
{
  /**
   * @p text as one finite number, or an error naming @p where: a value such
   * as '2/3' or '1 2' would otherwise be read as its first number.
   */
  double
  parse_finite_number(const std::string &text, const std::string &where);

  /**
   * The entries of the list @p text separated by @p delimiter, trimmed.
   * An empty entry ('0.5,', '1,,2', ', 1') is refused naming @p where:
   * deal.II's split_string_list drops a trailing delimiter, so '0.5,' for
   * two interfaces would silently become one value for both.
   */
  std::vector<std::string>
  split_list(const std::string &text,
             const char         delimiter,
             const std::string &where);

  /**
   * The whole numbers of the list @p text (',' between them), each from 0
   * to @p max (by default below deal.II's reserved ids), none twice: a
   * boundary id named twice ('1, 1') is a slip of the keyboard that would
   * otherwise pass.
   */
  std::vector<unsigned int>
  parse_id_list(const std::string &text,
                const std::string &where,
                const unsigned int max = 4294967294u);

  /**
   * The entries 'id: n' of the list @p text (';' between them), each id a
   * block's material id given once and each n a whole number from @p min
   * to @p max: 'Finite element/Block degrees = 1: 3; 2: 1'.
   */
  std::map<unsigned int, unsigned int>
  parse_id_values(const std::string &text,
                  const std::string &where,
                  const unsigned int min,
                  const unsigned int max);

  /** @name Checks of parameter text that every area uses */
  /** @{ */

  /**
   * The 'Function constants' entry of a ParsedFunction ('P=1, D=2'):
   * every name must be a name muparser accepts and not one of the
   * function's variables, every value one finite number. deal.II reads
   * the first number of the text ('2/3' becomes 2) and accepts inf and
   * nan; muparser rejects a bad name with an exception that is no
   * std::exception ('unknown error').
   */
  void
  check_function_constants(const std::string &constants,
                           const std::string &variables,
                           const std::string &where);

  /**
   * The 'Variable names' entry of a ParsedFunction in @p dim dimensions:
   * @p dim names of coordinates and optionally one of time, each a name
   * muparser accepts, none twice.
   */
  void
  check_variable_names(const std::string &variables,
                       const unsigned int dim,
                       const std::string &where);

  /**
   * @p id, named in the entry @p entry, is one of the boundary ids
   * @p present, or the error lists them.
   */
  void
  check_boundary_id(const dealii::types::boundary_id            id,
                    const std::string                          &entry,
                    const std::set<dealii::types::boundary_id> &present);
  /** @} */
} // namespace mbfem

#endif

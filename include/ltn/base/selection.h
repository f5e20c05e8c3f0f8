#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>

#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The names a parameter gives the values of the enum @p Kind it selects,
   * in the order its pattern lists them. A choice is parsed from its text
   * once, where the parameter is read, and compared as an enum everywhere
   * else (ASPECT's `parameters.h` does the same).
   */
  template <typename Kind>
  using SelectionNames = std::vector<std::pair<Kind, std::string>>;

  /** The pattern `a|b|c` of the names @p names. */
  template <typename Kind>
  Patterns::Selection
  selection_pattern(const SelectionNames<Kind> &names)
  {
    std::string pattern;
    for (const auto &[kind, name] : names)
      pattern += (pattern.empty() ? "" : "|") + name;
    return Patterns::Selection(pattern);
  }

  /**
   * The value named @p text: one of @p names, which the parameter's pattern
   * has checked already.
   */
  template <typename Kind>
  Kind
  parse_selection(const SelectionNames<Kind> &names, const std::string &text)
  {
    for (const auto &[kind, name] : names)
      if (name == text)
        return kind;
    AssertThrow(false, ExcMessage("'" + text + "' is not a choice"));
    return names.front().first;
  }

  /** The name of @p kind in @p names. */
  template <typename Kind>
  const std::string &
  selection_name(const SelectionNames<Kind> &names, const Kind kind)
  {
    for (const auto &[k, name] : names)
      if (k == kind)
        return name;
    AssertThrow(false, ExcInternalError());
    return names.front().second;
  }
} // namespace ltn

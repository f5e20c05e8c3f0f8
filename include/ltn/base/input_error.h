#pragma once

#include <stdexcept>
#include <string>

namespace ltn
{
  /**
   * An error in what the user gave us: a parameter with a value that is not
   * allowed. The message names the parameter (with its subsection path, as
   * written in a `.prm` file), the value given, and what is allowed. Raised
   * before anything is written, so a bad scene leaves no output behind.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &parameter,
               const std::string &value,
               const std::string &allowed);

    /** The parameter's path, e.g. "Geometry/Overlap width". */
    const std::string parameter;
  };

  /**
   * Throw an InputError unless @p condition holds.
   */
  void
  check_input(const bool         condition,
              const std::string &parameter,
              const std::string &value,
              const std::string &allowed);

  /** Format a double for error messages (shortest round-trip form). */
  std::string
  to_string(const double value);
} // namespace ltn

#include <ltn/base/input_error.h>

#include <sstream>

namespace ltn
{
  InputError::InputError(const std::string &parameter,
                         const std::string &value,
                         const std::string &allowed)
    : std::runtime_error("parameter '" + parameter + "' = '" + value +
                         "' is not allowed: " + allowed)
    , parameter(parameter)
  {}



  void
  check_input(const bool         condition,
              const std::string &parameter,
              const std::string &value,
              const std::string &allowed)
  {
    if (!condition)
      throw InputError(parameter, value, allowed);
  }



  std::string
  to_string(const double value)
  {
    std::ostringstream s;
    s.precision(12);
    s << value;
    return s.str();
  }
} // namespace ltn

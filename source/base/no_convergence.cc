#include <ltn/base/input_error.h>
#include <ltn/base/no_convergence.h>

namespace ltn
{
  std::runtime_error
  no_convergence(const std::string &solver,
                 const std::string &tolerance_parameter,
                 const double       tolerance,
                 const unsigned int max_iterations,
                 const double       relative_residual)
  {
    return std::runtime_error(
      solver + " did not reduce the residual by " + tolerance_parameter +
      " = " + to_string(tolerance) + " within Coupling/Maximum iterations = " +
      std::to_string(max_iterations) + " (relative residual " +
      to_string(relative_residual) + ")");
  }
} // namespace ltn

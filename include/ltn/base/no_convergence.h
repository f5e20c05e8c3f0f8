#pragma once

#include <stdexcept>
#include <string>

namespace ltn
{
  /**
   * The error of an iterative solver that stopped at its iteration limit:
   * "@p solver did not reduce the residual by @p tolerance_parameter = ...
   * within Coupling/Maximum iterations = ... (relative residual ...)", so
   * that the user sees which parameters to change.
   */
  std::runtime_error
  no_convergence(const std::string &solver,
                 const std::string &tolerance_parameter,
                 const double       tolerance,
                 const unsigned int max_iterations,
                 const double       relative_residual);
} // namespace ltn

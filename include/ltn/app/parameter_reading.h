#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** Declare every parameter of LtN, each by the class that uses it. */
  void
  declare_all_parameters(ParameterHandler &prm);

  /**
   * Read a scene: the `.prm` file @p filename, then the overrides @p sets,
   * each `"Subsection/.../name=value"`. Unknown parameters, values that do
   * not match a parameter's pattern and malformed lines become InputErrors.
   */
  void
  read_parameters(ParameterHandler               &prm,
                  const std::string              &filename,
                  const std::vector<std::string> &sets);
} // namespace ltn

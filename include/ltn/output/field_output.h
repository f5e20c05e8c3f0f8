#pragma once

#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/vector.h>

#include <ltn/scene/geometry.h>

#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * Write a finite element field to VTU with the fields a user looks at in
   * ParaView: `u`, and when an exact solution is given `u_exact` and the
   * pointwise `error = u - u_exact` (at the nodes), plus the `region` tag of
   * each node (see Region).
   */
  template <int dim>
  void
  write_field_vtu(const DoFHandler<dim>     &dof_handler,
                  const Vector<double>      &field,
                  const Function<dim>       *exact_solution,
                  const std::vector<Region> &regions,
                  const std::string         &filename);

  /**
   * Write a ParaView collection that lists one file per refinement level
   * (the level is the "time" of each entry).
   */
  void
  write_level_collection(
    const std::string                                 &filename,
    const std::vector<std::pair<double, std::string>> &level_files);
} // namespace ltn

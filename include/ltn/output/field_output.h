#pragma once

#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/problem/geometry.h>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The nodal interpolant of @p exact on @p dof_handler and the error
   * `field - exact` at the nodes, both with the values of the locally
   * relevant degrees of freedom (for DataOut).
   */
  template <int dim>
  std::array<TrilinosWrappers::MPI::Vector, 2>
  nodal_exact_and_error(const DoFHandler<dim>               &dof_handler,
                        const TrilinosWrappers::MPI::Vector &field,
                        const Function<dim>                 &exact);

  /**
   * Write a distributed finite element field as `directory/name.pvtu` (see
   * write_parallel_vtu()) with the fields a user looks at in ParaView: `u`,
   * and when an exact solution is given `u_exact` and the pointwise
   * `error = u - u_exact` (at the nodes), plus the `region` tag of each node
   * (see Region), which @p region_of gives for a node's position. @p field
   * holds the values of the locally relevant degrees of freedom. Return the
   * name of the `.pvtu` record.
   */
  template <int dim>
  std::string
  write_field_vtu(const DoFHandler<dim>               &dof_handler,
                  const TrilinosWrappers::MPI::Vector &field,
                  const Function<dim>                 *exact_solution,
                  const std::function<Region(const Point<dim> &)> &region_of,
                  const std::string                               &directory,
                  const std::string                               &name);

  /**
   * Write a ParaView collection that lists one file per refinement level
   * (the level is the "time" of each entry), on the first rank only.
   */
  void
  write_level_collection(
    const std::string                                 &filename,
    const std::vector<std::pair<double, std::string>> &level_files);

  /**
   * Write a ParaView collection that groups several series, one part each
   * (e.g. the particles and the local mesh), level by level, so that one
   * file opens the whole scene; on the first rank only.
   */
  void
  write_grouped_collection(
    const std::string                                              &filename,
    const std::vector<std::vector<std::pair<double, std::string>>> &parts);
} // namespace ltn

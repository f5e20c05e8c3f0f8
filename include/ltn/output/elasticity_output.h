#pragma once

#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/problem/geometry.h>
#include <ltn/problem/material.h>

#include <functional>
#include <string>

namespace ltn
{
  using namespace dealii;

  /**
   * Write a distributed displacement field (an `FESystem` of `dim`
   * components) as `directory/name.pvtu` (see write_parallel_vtu()) with
   * what a user looks at in ParaView: the vector `displacement` (for Warp
   * By Vector), the tensors `strain` and `stress` (Hooke's law with the
   * Lamé constants of @p material in the dimension), the scalar `von_mises`
   * stress (in 2D of the plane state: `sigma_zz = lambda tr(eps)` in plane
   * strain, zero in plane stress), the `region` tag (see
   * Region) that @p region_of gives for a point, and when @p exact (with
   * `dim` components) is given, the vectors `displacement_exact` and
   * `error = u - u_exact` (at the nodes). @p ghosted_field holds the values
   * of the locally relevant degrees of freedom. Return the name of the
   * `.pvtu` record.
   */
  template <int dim>
  std::string
  write_elasticity_vtu(
    const DoFHandler<dim>                           &dof_handler,
    const TrilinosWrappers::MPI::Vector             &ghosted_field,
    const Material                                  &material,
    const Function<dim>                             *exact,
    const std::function<Region(const Point<dim> &)> &region_of,
    const std::string                               &directory,
    const std::string                               &name);
} // namespace ltn

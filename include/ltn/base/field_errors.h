#pragma once

#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/vector.h>

#include <functional>

namespace ltn
{
  using namespace dealii;

  /** L2 and max norms of an error, combinable over several pieces. */
  struct ErrorNorms
  {
    double l2_squared = 0;
    double linf       = 0;

    /** The norms over the union of this piece and @p other. */
    void
    add(const ErrorNorms &other);

    /** Account for a pointwise error in the max norm (NaN propagates). */
    void
    add_pointwise(const double error);

    double
    l2() const;
  };

  /**
   * The error of a finite element field against @p exact over the cells
   * whose centre satisfies @p in_region: L2 by Gauss quadrature of degree
   * `p + 3`, max over an iterated trapezoidal grid that contains every node.
   */
  template <int dim>
  ErrorNorms
  field_errors(const DoFHandler<dim>                         &dof_handler,
               const Vector<double>                          &field,
               const Function<dim>                           &exact,
               const std::function<bool(const Point<dim> &)> &in_region);
} // namespace ltn

#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

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

    /** The norms over the pieces of all ranks of @p communicator. */
    ErrorNorms
    over_all_ranks(const MPI_Comm communicator) const;
  };

  /**
   * The error of a finite element field against @p exact over the locally
   * owned cells whose centre satisfies @p in_region, summed over all ranks:
   * L2 by Gauss quadrature of degree `p + 3`, max over an iterated
   * trapezoidal grid that contains every node. @p field must hold the
   * values of the locally relevant degrees of freedom. For a vector-valued
   * field (an FESystem; @p exact with as many components) the L2 norm is
   * that of `|u_h - u|`, the max norm the largest error of any component.
   */
  template <int dim>
  ErrorNorms
  field_errors(const DoFHandler<dim>                         &dof_handler,
               const TrilinosWrappers::MPI::Vector           &field,
               const Function<dim>                           &exact,
               const std::function<bool(const Point<dim> &)> &in_region);
} // namespace ltn

#pragma once

#include <deal.II/base/quadrature.h>

namespace ltn
{
  using namespace dealii;

  /**
   * The n-point Gauss-Jacobi rule on (0,1) for the weight `t^alpha`,
   * `alpha > -1`: `int_0^1 f(t) t^alpha dt = sum_q w_q f(t_q)`, exact for
   * polynomials `f` of degree up to `2n - 1`. Built by the Golub-Welsch
   * algorithm from the three-term recurrence of the Jacobi polynomials
   * (weights `(1-s)^0 (1+s)^alpha` on (-1,1), then mapped to (0,1)).
   *
   * It integrates the singular kernels (`|xi|^-beta` times a polynomial that
   * vanishes to second order at `xi = 0`) to round-off.
   */
  Quadrature<1>
  gauss_jacobi_unit_interval(const unsigned int n_points, const double alpha);
} // namespace ltn

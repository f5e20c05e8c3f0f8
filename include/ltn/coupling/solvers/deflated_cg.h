#pragma once

#include <deal.II/lac/solver_control.h>

#include <ltn/coupling/solvers/deflation_space.h>
#include <ltn/coupling/solvers/ritz_values.h>
#include <ltn/coupling/system/normal_equations.h>

#include <functional>

namespace ltn
{
  using namespace dealii;

  /**
   * Deflated preconditioned CG (Saad, Yeung, Erhel and Guyomarc'h 2000) on
   * @p equations, with the coarse space @p coarse and the preconditioner
   * @p precondition (`dst = P^{-1} src`, symmetric positive definite): the
   * iterates start from the coarse solution and move only A-orthogonally to
   * `Z`. Each iteration costs one product with `F` (of the preconditioned
   * residual: forward solves) and one with `F^T W` (of the search direction,
   * whose observation is updated by the same recurrence as the direction:
   * adjoint solves), as plain CG does; the start costs one product with
   * `F^T W`. In exact arithmetic the iterates are those of CG with the
   * balancing preconditioner of ControlCoarseSpace started from the coarse
   * solution, which needs `A Z`: an adjoint solve per column more.
   *
   * The right-hand side is `b = -F^T W d` for the observation @p data (the
   * mismatch of the models' states without controls, in the reduced
   * space): the start needs no product with `F^T W` of `b` beside that of
   * the start's residual. @p x is overwritten. The iteration stops as
   * @p control says of the residual norm `|b - A x|` (in its recursive
   * form), so its tolerance is the caller's, given `|b|`; before each
   * iteration's products, @p before_products is called with that norm (an
   * outer method relaxes its inner solves with it). Throws
   * SolverControl::NoConvergence as deal.II's solvers do.
   *
   * If @p states is given (both models' vectors), `V x` is added to it: the
   * states of the iterates follow from those the iterations' forward solves
   * give, by the recurrences of the iterates, so they are exact to the inner
   * solves' tolerances, and a final solve for `x` starting from them has
   * little left to do.
   *
   * If @p ritz_values is given, it records each step length and direction
   * coefficient: the Ritz values of the preconditioned, deflated operator.
   */
  void
  solve_deflated_cg(
    const NormalEquations &equations,
    const DeflationSpace  &coarse,
    const std::function<void(NormalEquations::BlockVectorType &,
                             const NormalEquations::BlockVectorType &)>
                                                    &precondition,
    const NormalEquations::Observation              &data,
    NormalEquations::BlockVectorType                &x,
    SolverControl                                   &control,
    const std::function<void(double residual_norm)> &before_products,
    NormalEquations::States                         *states      = nullptr,
    RitzValues                                      *ritz_values = nullptr);
} // namespace ltn

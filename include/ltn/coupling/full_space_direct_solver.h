#pragma once

#include <ltn/coupling/coupling_system.h>

namespace ltn
{
  /**
   * Solve the full-space optimality system (states, controls and Lagrange
   * multipliers of both models at once)
   *
   *   [ H + alpha R   C^T ] [ x      ]   [ -B^T W r_0 ]
   *   [ C             0   ] [ lambda ] = [  F         ]
   *
   * with a sparse direct solver (UMFPACK): `x = [x_n; x_l]` the states and
   * controls, `H = B^T W B` with `B = [E, -P]`, `C = diag(A_n, A_l)` on the
   * free rows, `r_0` the mismatch of the fixed data alone, and `R` the
   * identity on the controls. The solution is improved by iterative
   * refinement with the same factors; the reported residual is
   * `|K z - b| / |b|` of this system, and `iterations` counts one solve
   * plus the refinement steps. A residual above 1e-8 is an error.
   */
  template <int dim>
  CouplingSolution
  solve_full_space_direct(const CouplingSystem<dim> &system);
} // namespace ltn

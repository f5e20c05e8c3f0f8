#pragma once

#include <ltn/coupling/system/coupling_system.h>

namespace ltn
{
  /**
   * Solve the full-space optimality system (fields and Lagrange multipliers
   * of both models at once)
   *
   *   [ B^T W B + alpha R   C^T ] [ x  ]   [ 0 ]
   *   [ C                   D   ] [ mu ] = [ r ]
   *
   * with a distributed sparse direct solver (DirectSolver): `x = [u_n; u_l]`
   * all degrees of freedom of both models, `B = [E, -P]` the overlap rows,
   * `R` the identity on the controls, `C = diag(M_n, M_l)` with the control
   * rows left empty and `D` the identity on them (so their multipliers
   * vanish and the controls are free), `r` the models' data. The solution
   * is improved by iterative refinement with the same factors; the reported
   * residual is `|K z - b| / |b|` of this system, and `iterations` counts
   * one solve plus the refinement steps. A residual above 1e-8 is an error.
   *
   * The unknowns are numbered `[u_n | u_l | mu_n | mu_l]`, each block in its
   * model's numbering, and each rank owns the rows of its models' owned
   * degrees of freedom.
   */
  template <int dim>
  CouplingSolution
  solve_full_space_direct(const CouplingSystem<dim> &system);

  /**
   * The matrix `K` and right-hand side `b` of the system above, assembled:
   * each rank's rows those of its models' owned degrees of freedom, in the
   * numbering `[u_n | u_l | mu_n | mu_l]` (offsets 0, `N_n`, `N_n + N_l`,
   * `2 N_n + N_l`, with `N_k` model `k`'s number of degrees of freedom).
   * The models must be assembled (not matrix-free).
   */
  template <int dim>
  void
  assemble_full_space_system(const CouplingSystem<dim>      &system,
                             TrilinosWrappers::SparseMatrix &K,
                             TrilinosWrappers::MPI::Vector  &b);
} // namespace ltn

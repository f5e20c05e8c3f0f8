#pragma once

#include <ltn/base/progress.h>
#include <ltn/coupling/system/coupling_system.h>
#include <ltn/model_solvers/model_solver.h>

namespace ltn
{
  /**
   * A baseline coupling, not LtN's optimization: overlapping alternating
   * Schwarz, Dirichlet–Dirichlet (doc/baseline_couplings.md, 'Alternating
   * Schwarz'). Each sweep solves the local model with its controls
   * `theta_l` on `Gamma_c`, gives the nonlocal model the local field's
   * trace at its control collar, solves it, and takes the nonlocal field's
   * trace on `Gamma_c` as `G(theta_l)`; the residual `r = G(theta_l) -
   * theta_l`, the mismatch on `Gamma_c`, updates `theta_l += omega r` with
   * `omega = 1`, or with @p aitken Aitken's dynamic relaxation. The traces
   * are @p system's overlap's control traces (add_control_traces()).
   *
   * Stops when `|r|` has fallen by @p relative_tolerance from its first
   * value; throws when it grew ten thousand times or is not finite
   * (diverged), or when at its rate over the last ten sweeps it cannot
   * reach the tolerance within @p max_iterations sweeps (stalled). Each
   * model is solved by its own ModelSolver with @p model_solvers (the local
   * model's settings ModelSolverSettings::local()), each sweep starting
   * from the previous sweep's fields.
   */
  template <int dim>
  CouplingSolution
  solve_alternating_schwarz(const CouplingSystem<dim> &system,
                            const bool                 aitken,
                            const double               relative_tolerance,
                            const unsigned int         max_iterations,
                            const ModelSolverSettings &model_solvers,
                            Progress                  &progress);
} // namespace ltn

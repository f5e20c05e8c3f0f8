#pragma once

#include <ltn/coupling/preconditioners/control_preconditioner.h>
#include <ltn/coupling/system/coupling_system.h>


namespace ltn
{
  /**
   * Solve the full-space optimality system of solve_full_space_direct()
   * without assembling it: flexible GMRES on the KktOperator, right
   * preconditioned by the KktPreconditioner (doc/discretization.md,
   * 'The full-space system without a matrix'), whose model solves are as
   * @p model_solvers say (for
   * iterative ones, GMRES or CG to `model_solvers.relative_tolerance`) and
   * whose reduced Hessian is approximated by the ControlPreconditioner (its
   * local block and coarse products built with tight solves; as
   * @p settings say, two-level and with the surrogate nonlocal block). The
   * iteration stops when the residual has
   * dropped by @p relative_tolerance.
   */
  template <int dim>
  CouplingSolution
  solve_full_space_gmres(const CouplingSystem<dim> &system,
                         const double               relative_tolerance,
                         const unsigned int         max_iterations,
                         const ModelSolverSettings &model_solvers,
                         const ControlPreconditionerSettings &settings);
} // namespace ltn

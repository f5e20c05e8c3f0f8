#pragma once

#include <ltn/base/progress.h>
#include <ltn/coupling/preconditioners/control_preconditioner.h>
#include <ltn/coupling/system/coupling_system.h>

namespace ltn
{
  /**
   * Solve the optimality system in the reduced space: the states are
   * eliminated through each model's own solver (ModelSolver), and the normal
   * equations of the controls `theta = [theta_n; theta_l]`,
   *
   *   (V^T B^T W B V + alpha I) theta = -V^T B^T W d_0,
   *
   * are solved by conjugate gradients; `V` is the control-to-state map and
   * `d_0` the mismatch of the states with zero controls. Each CG iteration
   * costs one forward and one adjoint solve per model. The iteration stops
   * when the residual has dropped by @p relative_tolerance. The models'
   * solvers are as @p model_solvers say, their tolerance relaxed as the
   * residual falls (doc/discretization.md, 'A coarse level for the
   * controls'). CG is preconditioned
   * by the block-diagonal ControlPreconditioner and, with a coarse degree in
   * @p controls, deflated by the polynomial control fields (DeflationSpace:
   * one forward solve per coarse column, no adjoint solve). The final fields
   * are solved from the states the CG tracked. With
   * @p time_standalone_solves, each model is then solved once more alone,
   * from zero, with its data and the final controls, and the model solvers'
   * setup and these solves are timed as CouplingSolution::standalone_seconds.
   * Each phase and each
   * iteration is reported to @p progress, with the relative residual.
   */
  template <int dim>
  CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<dim> &system,
                         const double               relative_tolerance,
                         const unsigned int         max_iterations,
                         const ModelSolverSettings &model_solvers,
                         const ControlPreconditionerSettings &controls,
                         const bool time_standalone_solves,
                         Progress  &progress);
} // namespace ltn

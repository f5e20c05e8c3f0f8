#pragma once

#include <ltn/coupling/preconditioners/control_preconditioner.h>
#include <ltn/coupling/system/kkt_operator.h>
#include <ltn/model_solvers/model_solver.h>

#include <array>

namespace ltn
{
  using namespace dealii;

  /**
   * An approximate inverse of the KktOperator: block elimination in the
   * order of the reduced space (doc/discretization.md, 'The full-space
   * system without a matrix'), with
   * each model's inverses replaced by its solver @p solvers (typically
   * GMRES to a loose tolerance) and the reduced Hessian's by the
   * ControlPreconditioner @p controls. For `[f; s g]` (the multipliers'
   * scale `s` of the KktOperator undone first, and applied to `mu` last):
   *
   *   x_g   = M^{-1} Z g                               (forward, per model)
   *   theta = P^{-1} S^T M^{-T} (f - B^T W B x_g)      (adjoint, then P)
   *   x     = M^{-1} (Z g + S theta)                   (forward)
   *   mu    = Z M^{-T} Z (f - B^T W B x) + (I - Z) g   (adjoint)
   *
   * With exact solves and `P` the reduced Hessian this is the exact inverse.
   * Two forward and two adjoint solves per model per application; with
   * inexact solves the operator changes between applications (flexible
   * GMRES).
   */
  template <int dim>
  class KktPreconditioner
  {
  public:
    using BlockVectorType = TrilinosWrappers::MPI::BlockVector;

    KktPreconditioner(const KktOperator<dim>                   &kkt,
                      const std::array<const ModelSolver *, 2> &solvers,
                      const ControlPreconditioner<dim>         &controls);

    void
    vmult(BlockVectorType &dst, const BlockVectorType &src) const;

  private:
    const KktOperator<dim>                  &kkt;
    const std::array<const ModelSolver *, 2> solvers;
    const ControlPreconditioner<dim>        &controls;
  };
} // namespace ltn

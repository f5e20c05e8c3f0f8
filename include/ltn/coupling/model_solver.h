#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/coupling/direct_solver.h>

#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * One model's own solver, as the reduced-space method sees it: a black box
   * that solves the model's equations for given controls (forward) and the
   * transposed equations (adjoint). The model's field for controls `theta`
   * solves `M x = r + S theta` (see DiscreteModel); `M` and `M^T` are
   * factorized once.
   *
   * Controls are numbered `0 .. n_controls - 1` over all ranks, each rank
   * owning a contiguous range: those of its own control degrees of freedom,
   * in their order.
   */
  class ModelSolver
  {
  public:
    /** Factorize the model's matrix, and @p with_adjoint its transpose. */
    ModelSolver(const DiscreteModel &model, const bool with_adjoint);

    /** A zero vector of controls. */
    TrilinosWrappers::MPI::Vector
    new_control_vector() const;

    /**
     * The model's field for controls @p theta; with @p with_data, the load
     * and fixed data enter, otherwise they are taken as zero (the linear part
     * of the control-to-state map).
     */
    TrilinosWrappers::MPI::Vector
    forward(const TrilinosWrappers::MPI::Vector &theta,
            const bool                           with_data) const;

    /**
     * The adjoint of the control-to-state map of forward() (without data):
     * for a gradient @p z with respect to all degrees of freedom, the
     * gradient with respect to the controls, `S^T M^{-T} z`.
     */
    TrilinosWrappers::MPI::Vector
    adjoint(const TrilinosWrappers::MPI::Vector &z) const;

  private:
    const DiscreteModel                 &model;
    std::vector<types::global_dof_index> control_dofs;
    /** The number of this rank's first control. */
    types::global_dof_index first_control;
    IndexSet                control_partition;
    DirectSolver            direct;
  };
} // namespace ltn

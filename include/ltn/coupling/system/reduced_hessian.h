#pragma once

#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ltn/coupling/system/coupling_system.h>
#include <ltn/coupling/system/normal_equations.h>
#include <ltn/model_solvers/model_solver.h>

#include <array>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The reduced Hessian `V^T B^T W B V + alpha I` of the optimality system as
   * an operator on the controls `theta = [theta_n; theta_l]`, one block per
   * model (doc/discretization.md, 'Preconditioning the reduced Hessian'):
   * `V` maps the controls to the
   * states through each model's own solver, `B = [E, -P]` takes the states
   * to the overlap mismatch.
   */
  template <int dim>
  class ReducedHessian
  {
  public:
    using BlockVectorType = TrilinosWrappers::MPI::BlockVector;

    ReducedHessian(const CouplingSystem<dim>                &system,
                   const std::array<const ModelSolver *, 2> &solvers);

    /** A zero vector of controls. */
    BlockVectorType
    new_control_vector() const;

    /** `V^T B^T W d` for a mismatch @p d at this rank's points. */
    BlockVectorType
    reduced_gradient(const std::vector<double> &d) const;

    /** `V^T g` for the states' gradients @p state_gradients (adjoint solves). */
    BlockVectorType
    adjoint(const std::array<TrilinosWrappers::MPI::Vector, 2> &state_gradients)
      const;

    /** The mismatch of the fields for controls @p theta. */
    std::vector<double>
    mismatch(const BlockVectorType &theta, const bool with_data) const;

    void
    vmult(BlockVectorType &dst, const BlockVectorType &theta) const;

    /**
     * The Hessian as NormalEquations, for the deflated CG: its forward,
     * observation and adjoint maps, the models' zero states and observed
     * unknowns, and the forward solves of several controls at once (the
     * optional observe_alone left empty). Valid while this object lives.
     */
    NormalEquations
    normal_equations() const;

    const CouplingSystem<dim>               &system;
    const std::array<const ModelSolver *, 2> solvers;
  };
} // namespace ltn

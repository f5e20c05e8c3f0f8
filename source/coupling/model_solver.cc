#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <ltn/base/partition.h>
#include <ltn/coupling/model_solver.h>
#include <ltn/coupling/no_convergence.h>

namespace ltn
{
  ModelSolver::ModelSolver(const DiscreteModel       &model,
                           const bool                 with_adjoint,
                           const ModelSolverSettings &settings)
    : model(model)
    , settings(settings)
    , tolerance(settings.relative_tolerance)
    , control_dofs(model.controls.begin(), model.controls.end())
  {
    control_partition =
      contiguous_partition(control_dofs.size(), model.communicator);
    first_control =
      control_partition.is_empty() ? 0 : control_partition.nth_index_in_set(0);
    if (settings.iterative)
      {
        preconditioner = std::make_unique<ModelPreconditioner>(model);
        forward_system = std::make_unique<SchurComplement>(model, false);
        counts.memory  = preconditioner->memory_consumption() +
                        forward_system->memory_consumption();
        if (with_adjoint)
          {
            adjoint_system = std::make_unique<SchurComplement>(model, true);
            counts.memory += adjoint_system->memory_consumption();
          }
      }
    else
      {
        AssertThrow(!model.matrix_free,
                    ExcMessage("a direct solver needs the assembled matrix"));
        direct = std::make_unique<DirectSolver>(model.matrix, with_adjoint);
      }
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::new_control_vector() const
  {
    return TrilinosWrappers::MPI::Vector(control_partition, model.communicator);
  }



  void
  ModelSolver::solve(const bool                           transpose,
                     TrilinosWrappers::MPI::Vector       &x,
                     const TrilinosWrappers::MPI::Vector &b,
                     WarmStart                           *last) const
  {
    ++counts.solves;
    if (direct)
      {
        if (transpose)
          direct->solve_transposed(x, b);
        else
          direct->solve(x, b);
        return;
      }

    const double b_norm = b.l2_norm();
    x                   = 0.;
    if (b_norm == 0)
      return;
    if (last && last->rhs.size() > 0)
      {
        const double last_norm = last->rhs.l2_norm();
        if (last_norm > 0)
          x.add((b * last->rhs) / (last_norm * last_norm), last->solution);
      }
    const SchurComplement &system =
      transpose ? *adjoint_system : *forward_system;
    // Right preconditioning: the tolerance is on the true residual, which
    // is that of the Schur complement's system.
    SolverControl control(settings.max_iterations, tolerance * b_norm);
    SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
      control,
      SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(50, true));
    try
      {
        gmres.solve(system, x, system.reduce(b), *preconditioner);
      }
    catch (const SolverControl::NoConvergence &)
      {
        throw no_convergence("a model's GMRES",
                             "Coupling/Model solver tolerance",
                             tolerance,
                             settings.max_iterations,
                             control.last_value() / b_norm);
      }
    system.recover(x, b);
    counts.iterations += control.last_step();
    if (last)
      {
        last->rhs      = b;
        last->solution = x;
      }
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::forward(const TrilinosWrappers::MPI::Vector &theta,
                       const bool                           with_data) const
  {
    // The control rows of `r` are zero.
    TrilinosWrappers::MPI::Vector rhs = extend_controls(theta);
    if (with_data)
      rhs += model.rhs;

    TrilinosWrappers::MPI::Vector field = model.new_vector();
    solve(false, field, rhs, with_data ? nullptr : &last_forward);
    return field;
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::adjoint(const TrilinosWrappers::MPI::Vector &z) const
  {
    TrilinosWrappers::MPI::Vector multiplier = model.new_vector();
    solve(true, multiplier, z, &last_adjoint);
    return restrict_to_controls(multiplier);
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::restrict_to_controls(
    const TrilinosWrappers::MPI::Vector &x) const
  {
    TrilinosWrappers::MPI::Vector restricted = new_control_vector();
    for (std::size_t c = 0; c < control_dofs.size(); ++c)
      restricted(first_control + c) = x(control_dofs[c]);
    restricted.compress(VectorOperation::insert);
    return restricted;
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::extend_controls(const TrilinosWrappers::MPI::Vector &theta) const
  {
    TrilinosWrappers::MPI::Vector extended = model.new_vector();
    for (std::size_t c = 0; c < control_dofs.size(); ++c)
      extended(control_dofs[c]) = theta(first_control + c);
    extended.compress(VectorOperation::insert);
    return extended;
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::solve(const bool                           transpose,
                     const TrilinosWrappers::MPI::Vector &b) const
  {
    TrilinosWrappers::MPI::Vector x = model.new_vector();
    solve(transpose, x, b, &last_general[transpose ? 1 : 0]);
    return x;
  }



  void
  ModelSolver::set_relative_tolerance(const double relative_tolerance) const
  {
    tolerance = relative_tolerance;
  }



  ModelSolverStatistics
  ModelSolver::statistics() const
  {
    return counts;
  }
} // namespace ltn

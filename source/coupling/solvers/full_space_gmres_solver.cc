#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <ltn/base/no_convergence.h>
#include <ltn/coupling/preconditioners/kkt_preconditioner.h>
#include <ltn/coupling/solvers/full_space_gmres_solver.h>

namespace ltn
{
  template <int dim>
  CouplingSolution
  solve_full_space_gmres(const CouplingSystem<dim> &system,
                         const double               relative_tolerance,
                         const unsigned int         max_iterations,
                         const ModelSolverSettings &model_solvers,
                         const ControlPreconditionerSettings &settings)
  {
    const ModelSolver nonlocal_solver(*system.models[nonlocal_model],
                                      true,
                                      model_solvers);
    const ModelSolver local_solver(*system.models[local_model],
                                   true,
                                   model_solvers.local());
    const std::array<const ModelSolver *, 2> solvers = {
      {&nonlocal_solver, &local_solver}};
    // The control preconditioner's explicit blocks are formed from Hessian
    // products and must be the Hessian's, whatever the inner tolerance.
    for (const ModelSolver *solver : solvers)
      solver->set_relative_tolerance(
        std::min(model_solvers.relative_tolerance, 1e-12));
    CouplingSolution                 solution;
    Timer                            setup_timer;
    const ControlPreconditioner<dim> controls(ReducedHessian<dim>(system,
                                                                  solvers),
                                              settings.coarse_degree,
                                              true,
                                              settings.surrogate_nonlocal_block,
                                              settings.collar_layer_weight);
    for (const ModelSolver *solver : solvers)
      solver->set_relative_tolerance(model_solvers.relative_tolerance);
    solution.preconditioner_setup_seconds = setup_timer.wall_time();
    solution.explicit_controls            = controls.n_explicit_controls();
    solution.coarse_modes                 = controls.n_coarse_modes();
    solution.nonlocal_block_unknowns = controls.n_nonlocal_block_unknowns();

    const KktOperator<dim>       kkt(system);
    const KktPreconditioner<dim> preconditioner(kkt, solvers, controls);
    const auto                   b      = kkt.rhs();
    auto                         x      = kkt.new_vector();
    const double                 b_norm = b.l2_norm();
    if (b_norm > 0)
      {
        SolverControl control(max_iterations, relative_tolerance * b_norm);
        // FGMRES keeps the preconditioned vectors: the preconditioner's
        // inner GMRES makes it change from one application to the next.
        SolverFGMRES<TrilinosWrappers::MPI::BlockVector> fgmres(
          control,
          SolverFGMRES<TrilinosWrappers::MPI::BlockVector>::AdditionalData(
            100));
        try
          {
            fgmres.solve(kkt, x, b, preconditioner);
          }
        catch (const SolverControl::NoConvergence &)
          {
            throw no_convergence("the full-space GMRES",
                                 "Coupling/Relative tolerance",
                                 relative_tolerance,
                                 max_iterations,
                                 control.last_value() / b_norm);
          }
        solution.iterations = control.last_step();
        solution.residual   = control.last_value() / b_norm;
      }
    for (const unsigned int k : {0u, 1u})
      solution.fields[k] = x.block(k);
    solution.model_solvers = {
      {nonlocal_solver.statistics(), local_solver.statistics()}};
    return solution;
  }

  template CouplingSolution
  solve_full_space_gmres(const CouplingSystem<1> &,
                         double,
                         unsigned int,
                         const ModelSolverSettings &,
                         const ControlPreconditionerSettings &);
  template CouplingSolution
  solve_full_space_gmres(const CouplingSystem<2> &,
                         double,
                         unsigned int,
                         const ModelSolverSettings &,
                         const ControlPreconditionerSettings &);
  template CouplingSolution
  solve_full_space_gmres(const CouplingSystem<3> &,
                         double,
                         unsigned int,
                         const ModelSolverSettings &,
                         const ControlPreconditionerSettings &);
} // namespace ltn

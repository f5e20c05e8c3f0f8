#include <deal.II/base/timer.h>

#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ltn/coupling/control_preconditioner.h>
#include <ltn/coupling/model_solver.h>
#include <ltn/coupling/no_convergence.h>
#include <ltn/coupling/reduced_hessian.h>
#include <ltn/coupling/reduced_space_solver.h>

#include <algorithm>
#include <limits>

namespace ltn
{
  namespace
  {
    using BlockVectorType = TrilinosWrappers::MPI::BlockVector;

    /** The loosest tolerance a relaxed inner solve is given. */
    constexpr double loosest_model_tolerance = 1e-1;
  } // namespace



  template <int dim>
  CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<dim> &system,
                         const double               relative_tolerance,
                         const unsigned int         max_iterations,
                         const ModelSolverSettings &model_solvers,
                         const ControlPreconditionerSettings &controls)
  {
    Timer        solver_setup;
    ModelSolver  nonlocal_solver(*system.models[nonlocal_model],
                                true,
                                model_solvers);
    ModelSolver  local_solver(*system.models[local_model], true, model_solvers);
    const double solver_setup_seconds = solver_setup.wall_time();
    const ReducedHessian<dim> hessian(system,
                                      {{&nonlocal_solver, &local_solver}});

    BlockVectorType theta = hessian.new_control_vector();
    BlockVectorType rhs =
      hessian.reduced_gradient(hessian.mismatch(theta, true));
    rhs *= -1.;

    CouplingSolution solution;
    const double     rhs_norm = rhs.l2_norm();
    if (rhs_norm > 0)
      {
        ReductionControl control(max_iterations, 0., relative_tolerance);
        SolverCG<BlockVectorType> cg(control);
        // Relaxed inner solves (doc/discretization.md, section 19): the
        // error of the Hessian's products may grow as the residual falls.
        cg.connect([&](const unsigned int,
                       const double residual,
                       const BlockVectorType &) {
          const double relaxed =
            model_solvers.relative_tolerance * rhs_norm /
            std::max(residual, std::numeric_limits<double>::min());
          for (const ModelSolver *solver : hessian.solvers)
            solver->set_relative_tolerance(
              std::clamp(relaxed,
                         model_solvers.relative_tolerance,
                         std::max(loosest_model_tolerance,
                                  model_solvers.relative_tolerance)));
          return SolverControl::success;
        });
        try
          {
            if (controls.enabled)
              {
                Timer                            setup_timer;
                const ControlPreconditioner<dim> preconditioner(
                  hessian, controls.coarse_degree);
                solution.preconditioner_setup_seconds = setup_timer.wall_time();
                solution.explicit_controls =
                  preconditioner.n_explicit_controls();
                solution.coarse_modes = preconditioner.n_coarse_modes();
                cg.solve(hessian, theta, rhs, preconditioner);
              }
            else
              cg.solve(hessian, theta, rhs, PreconditionIdentity());
          }
        catch (const SolverControl::NoConvergence &)
          {
            throw no_convergence("the reduced-space CG",
                                 "Coupling/Relative tolerance",
                                 relative_tolerance,
                                 max_iterations,
                                 control.last_value() / rhs_norm);
          }
        for (const ModelSolver *solver : hessian.solvers)
          solver->set_relative_tolerance(model_solvers.relative_tolerance);
        solution.iterations = control.last_step();
        solution.residual   = control.last_value() / rhs_norm;
      }
    Timer final_solves;
    solution.fields[nonlocal_model] =
      nonlocal_solver.forward(theta.block(0), true);
    solution.fields[local_model] = local_solver.forward(theta.block(1), true);
    solution.standalone_seconds =
      solver_setup_seconds + final_solves.wall_time();
    solution.model_solvers = {
      {nonlocal_solver.statistics(), local_solver.statistics()}};
    return solution;
  }

  template CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<1> &,
                         double,
                         unsigned int,
                         const ModelSolverSettings &,
                         const ControlPreconditionerSettings &);
  template CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<2> &,
                         double,
                         unsigned int,
                         const ModelSolverSettings &,
                         const ControlPreconditionerSettings &);
  template CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<3> &,
                         double,
                         unsigned int,
                         const ModelSolverSettings &,
                         const ControlPreconditionerSettings &);
} // namespace ltn

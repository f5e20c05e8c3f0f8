#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>

#include <ltn/base/discrete_model.h>
#include <ltn/base/progress.h>
#include <ltn/coupling/solvers/coupling_parameters.h>
#include <ltn/coupling/system/coupling_system.h>
#include <ltn/coupling/system/overlap_quadrature.h>
#include <ltn/output/run_summary.h>
#include <ltn/problem/geometry.h>

#include <string>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * Solve the models of one level, whatever their physics: coupled by the
   * optimality system on @p overlap when both exist (@p nonlocal and
   * @p local not null), else the one model alone by its direct solver.
   * Record the solver's statistics (controls, method, iterations, residual,
   * mismatch) in @p record; throw if the solution is not finite. The coupled
   * solve reports its progress to @p progress.
   */
  template <int dim>
  CouplingSolution
  solve_level(const DiscreteModel          *nonlocal,
              const DiscreteModel          *local,
              const OverlapQuadrature<dim> &overlap,
              const CouplingParameters     &parameters,
              LevelRecord                  &record,
              Progress                     &progress);

  /**
   * Record the errors of a level against @p exact: the nonlocal model's
   * (@p nonlocal_errors, null when the scene has none), the local model's
   * over its whole mesh (@p local_dofs null when none; @p local_field
   * ghosted), and those of the coupled solution, `u_n` on @p nonlocal_region
   * and `u_l` on the rest. A missing model's errors are NaN (null in the
   * summary).
   */
  template <int dim>
  void
  record_errors(const ErrorNorms                    *nonlocal_errors,
                const DoFHandler<dim>               *local_dofs,
                const TrilinosWrappers::MPI::Vector &local_field,
                const Function<dim>                 &exact,
                const NonlocalRegion<dim>           &nonlocal_region,
                const double                         tolerance,
                LevelRecord                         &record);

  /** The phases every scene reports, in order. */
  const std::vector<std::string> &
  level_phases();

  /** Copy the wall time of each of level_phases() from @p timer. */
  void
  record_timings(const TimerOutput &timer, LevelRecord &record);
} // namespace ltn

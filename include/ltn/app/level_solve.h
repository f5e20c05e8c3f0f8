#pragma once

#include <deal.II/base/timer.h>

#include <ltn/base/discrete_model.h>
#include <ltn/coupling/coupling_parameters.h>
#include <ltn/coupling/coupling_system.h>
#include <ltn/coupling/overlap_quadrature.h>
#include <ltn/output/run_summary.h>

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
   * mismatch) in @p record; throw if the solution is not finite.
   */
  template <int dim>
  CouplingSolution
  solve_level(const DiscreteModel          *nonlocal,
              const DiscreteModel          *local,
              const OverlapQuadrature<dim> &overlap,
              const CouplingParameters     &parameters,
              LevelRecord                  &record);

  /** The phases every scene reports, in order. */
  const std::vector<std::string> &
  level_phases();

  /** Copy the wall time of each of level_phases() from @p timer. */
  void
  record_timings(const TimerOutput &timer, LevelRecord &record);
} // namespace ltn

#pragma once

#include <ltn/base/progress.h>
#include <ltn/coupling/solvers/coupling_parameters.h>
#include <ltn/coupling/system/coupling_system.h>

namespace ltn
{
  /**
   * Solve the optimality system @p system by the method that @p parameters
   * select (`Coupling/Method`), with their tolerances, model solvers and
   * control preconditioner; the reduced-space CG reports its phases and
   * iterations to @p progress. The one place that maps a method to its
   * solver: a new coupled solver is one file in this folder, one value of
   * CouplingMethod and one case here.
   */
  template <int dim>
  CouplingSolution
  solve_optimality_system(const CouplingSystem<dim> &system,
                          const CouplingParameters  &parameters,
                          Progress                  &progress);
} // namespace ltn

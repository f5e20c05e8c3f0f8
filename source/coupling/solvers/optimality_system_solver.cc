#include <ltn/coupling/solvers/energy_blending_solver.h>
#include <ltn/coupling/solvers/force_blending_solver.h>
#include <ltn/coupling/solvers/full_space_direct_solver.h>
#include <ltn/coupling/solvers/full_space_gmres_solver.h>
#include <ltn/coupling/solvers/optimality_system_solver.h>
#include <ltn/coupling/solvers/reduced_space_solver.h>
#include <ltn/coupling/solvers/schwarz_solver.h>

namespace ltn
{
  template <int dim>
  CouplingSolution
  solve_optimality_system(const CouplingSystem<dim> &system,
                          const CouplingParameters  &parameters,
                          Progress                  &progress)
  {
    switch (parameters.method)
      {
        case CouplingMethod::reduced_space_cg:
          return solve_reduced_space_cg(system,
                                        parameters.relative_tolerance,
                                        parameters.max_iterations,
                                        parameters.model_solvers,
                                        parameters.controls,
                                        parameters.time_standalone_solves,
                                        progress);
        case CouplingMethod::full_space_gmres:
          return solve_full_space_gmres(system,
                                        parameters.relative_tolerance,
                                        parameters.max_iterations,
                                        parameters.model_solvers,
                                        parameters.controls);
        case CouplingMethod::full_space_direct:
          return solve_full_space_direct(system);
        case CouplingMethod::alternating_schwarz:
        case CouplingMethod::alternating_schwarz_aitken:
          return solve_alternating_schwarz(
            system,
            parameters.method == CouplingMethod::alternating_schwarz_aitken,
            parameters.relative_tolerance,
            parameters.max_iterations,
            parameters.model_solvers,
            progress);
        case CouplingMethod::force_blending:
          return solve_force_blending(system);
        case CouplingMethod::energy_blending:
          return solve_energy_blending(system);
        case CouplingMethod::automatic:
          break;
      }
    AssertThrow(false,
                ExcMessage("Coupling/Method = auto reached the solver: the "
                           "scene resolves it first (choose_solvers())"));
    return {};
  }

  template CouplingSolution
  solve_optimality_system(const CouplingSystem<1> &,
                          const CouplingParameters &,
                          Progress &);
  template CouplingSolution
  solve_optimality_system(const CouplingSystem<2> &,
                          const CouplingParameters &,
                          Progress &);
  template CouplingSolution
  solve_optimality_system(const CouplingSystem<3> &,
                          const CouplingParameters &,
                          Progress &);
} // namespace ltn

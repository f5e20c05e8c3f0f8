#include <ltn/coupling/solvers/full_space_direct_solver.h>
#include <ltn/coupling/solvers/full_space_gmres_solver.h>
#include <ltn/coupling/solvers/optimality_system_solver.h>
#include <ltn/coupling/solvers/reduced_space_solver.h>

namespace ltn
{
  template <int dim>
  CouplingSolution
  solve_optimality_system(const CouplingSystem<dim> &system,
                          const CouplingParameters  &parameters)
  {
    switch (parameters.method)
      {
        case CouplingMethod::reduced_space_cg:
          return solve_reduced_space_cg(system,
                                        parameters.relative_tolerance,
                                        parameters.max_iterations,
                                        parameters.model_solvers,
                                        parameters.controls,
                                        parameters.time_standalone_solves);
        case CouplingMethod::full_space_gmres:
          return solve_full_space_gmres(system,
                                        parameters.relative_tolerance,
                                        parameters.max_iterations,
                                        parameters.model_solvers,
                                        parameters.controls);
        case CouplingMethod::full_space_direct:
          return solve_full_space_direct(system);
      }
    AssertThrow(false, ExcInternalError());
    return {};
  }

  template CouplingSolution
  solve_optimality_system(const CouplingSystem<1> &,
                          const CouplingParameters &);
  template CouplingSolution
  solve_optimality_system(const CouplingSystem<2> &,
                          const CouplingParameters &);
  template CouplingSolution
  solve_optimality_system(const CouplingSystem<3> &,
                          const CouplingParameters &);
} // namespace ltn

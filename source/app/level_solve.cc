#include <ltn/app/level_solve.h>
#include <ltn/coupling/model_solver.h>

#include <cmath>

namespace ltn
{
  template <int dim>
  CouplingSolution
  solve_level(const DiscreteModel          *nonlocal,
              const DiscreteModel          *local,
              const OverlapQuadrature<dim> &overlap,
              const CouplingParameters     &parameters,
              LevelRecord                  &record)
  {
    CouplingSolution solution;
    if (nonlocal != nullptr && local != nullptr)
      {
        const CouplingSystem<dim> system(*nonlocal,
                                         *local,
                                         overlap,
                                         parameters.tikhonov_parameter);
        solution             = parameters.solve(system);
        record.n_controls    = system.n_controls();
        record.solver_method = parameters.method;
        record.mismatch_J =
          system.objective(solution.fields[0], solution.fields[1]);
      }
    else
      {
        // One model on the whole body: its own direct solve.
        const unsigned int   k     = nonlocal ? nonlocal_model : local_model;
        const DiscreteModel &model = nonlocal ? *nonlocal : *local;
        const ModelSolver    solver(model, false);
        solution.fields[k]  = solver.forward(solver.new_control_vector(), true);
        solution.iterations = 1;
        record.solver_method = "direct";
      }
    record.iterations = solution.iterations;
    record.residual   = solution.residual;

    bool finite = true;
    for (const auto &field : solution.fields)
      for (const double value : field)
        finite = finite && std::isfinite(value);
    AssertThrow(Utilities::MPI::min(finite ? 1 : 0, MPI_COMM_WORLD) == 1,
                ExcMessage(
                  "The solution is not finite: an expression of Problem "
                  "data has values that are not (a division by zero, a "
                  "logarithm of a negative number, ...)."));
    return solution;
  }



  const std::vector<std::string> &
  level_phases()
  {
    static const std::vector<std::string> phases = {"setup meshes",
                                                    "assemble nonlocal",
                                                    "assemble local",
                                                    "assemble coupling",
                                                    "solve",
                                                    "postprocess",
                                                    "output"};
    return phases;
  }



  void
  record_timings(const TimerOutput &timer, LevelRecord &record)
  {
    const auto times = timer.get_summary_data(TimerOutput::total_wall_time);
    for (const std::string &phase : level_phases())
      {
        const auto entry = times.find(phase);
        record.timings.emplace_back(phase,
                                    entry == times.end() ? 0. : entry->second);
      }
  }

  template CouplingSolution
  solve_level(const DiscreteModel *,
              const DiscreteModel *,
              const OverlapQuadrature<1> &,
              const CouplingParameters &,
              LevelRecord &);
  template CouplingSolution
  solve_level(const DiscreteModel *,
              const DiscreteModel *,
              const OverlapQuadrature<2> &,
              const CouplingParameters &,
              LevelRecord &);
  template CouplingSolution
  solve_level(const DiscreteModel *,
              const DiscreteModel *,
              const OverlapQuadrature<3> &,
              const CouplingParameters &,
              LevelRecord &);
} // namespace ltn

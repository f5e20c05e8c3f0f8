#include <ltn/base/field_errors.h>
#include <ltn/coupling/solvers/optimality_system_solver.h>
#include <ltn/model_solvers/model_solver.h>
#include <ltn/scene/level_solve.h>

#include <cmath>
#include <limits>

namespace ltn
{
  template <int dim>
  CouplingSolution
  solve_level(const DiscreteModel          *nonlocal,
              const DiscreteModel          *local,
              const OverlapQuadrature<dim> &overlap,
              const CouplingParameters     &parameters,
              LevelRecord                  &record,
              Progress                     &progress)
  {
    // Are all entries of these vectors finite, on every rank?
    const auto all_finite =
      [](const std::vector<const TrilinosWrappers::MPI::Vector *> &vectors) {
        bool finite = true;
        for (const auto *vector : vectors)
          if (vector != nullptr)
            for (const double value : *vector)
              finite = finite && std::isfinite(value);
        return Utilities::MPI::min(finite ? 1 : 0, MPI_COMM_WORLD) == 1;
      };
    // Data that are not finite are the user's error, not the solver's:
    // said so before a direct solver reports the system as singular.
    AssertThrow(all_finite({nonlocal ? &nonlocal->rhs : nullptr,
                            local ? &local->rhs : nullptr}),
                ExcMessage(
                  "The data are not finite: an expression of the scene's "
                  "data has values that are not finite at some particle or "
                  "quadrature point (a division by zero, a logarithm of a "
                  "negative number, ...)."));

    CouplingSolution solution;
    if (nonlocal != nullptr && local != nullptr)
      {
        const CouplingSystem<dim> system(*nonlocal,
                                         *local,
                                         overlap,
                                         parameters.tikhonov_parameter);
        solution = solve_optimality_system(system, parameters, progress);
        record.n_controls = system.n_controls();
        record.solver_method =
          selection_name(coupling_method_names(), parameters.method);
        record.mismatch_J =
          system.objective(solution.fields[0], solution.fields[1]);
      }
    else
      {
        // One model on the whole body: its own solver.
        const unsigned int   k     = nonlocal ? nonlocal_model : local_model;
        const DiscreteModel &model = nonlocal ? *nonlocal : *local;
        const ModelSolver    solver(model, false, parameters.model_solvers);
        solution.fields[k] = solver.forward(solver.new_control_vector(), true);
        solution.model_solvers[k] = solver.statistics();
        solution.iterations       = solution.model_solvers[k].iterations;
        record.solver_method =
          selection_name(model_solver_names(), parameters.model_solvers.kind);
      }
    record.solver              = solution;
    record.collar_layer_weight = parameters.controls.collar_layer_weight;
    const std::array<const DiscreteModel *, 2> models = {{nonlocal, local}};
    for (const unsigned int k : {0u, 1u})
      {
        if (models[k])
          record.model_bytes[k] =
            Utilities::MPI::sum(static_cast<double>(
                                  models[k]->memory_consumption() +
                                  solution.model_solvers[k].memory),
                                models[k]->communicator);
      }

    // The data were finite (checked above): this is the solver's failure.
    AssertThrow(all_finite({&solution.fields[0], &solution.fields[1]}),
                ExcMessage("The solution is not finite although the data "
                           "are: the solver failed (a singular or badly "
                           "scaled system)."));
    return solution;
  }



  template <int dim>
  void
  record_errors(const ErrorNorms                    *nonlocal_errors,
                const DoFHandler<dim>               *local_dofs,
                const TrilinosWrappers::MPI::Vector &local_field,
                const Function<dim>                 &exact,
                const NonlocalRegion<dim>           &nonlocal_region,
                const double                         tolerance,
                LevelRecord                         &record)
  {
    const ErrorNorms none{std::numeric_limits<double>::quiet_NaN(),
                          std::numeric_limits<double>::quiet_NaN()};
    record.has_errors      = true;
    record.nonlocal_errors = nonlocal_errors ? *nonlocal_errors : none;
    record.local_errors =
      local_dofs ? field_errors<dim>(*local_dofs,
                                     local_field,
                                     exact,
                                     [](const Point<dim> &) { return true; }) :
                   none;
    record.coupled_errors = nonlocal_errors ? *nonlocal_errors : ErrorNorms();
    if (local_dofs)
      record.coupled_errors.add(field_errors<dim>(
        *local_dofs, local_field, exact, [&](const Point<dim> &p) {
          return !nonlocal_errors || !nonlocal_region.contains(p, tolerance);
        }));
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

#define LTN_INSTANTIATE(dim)                                                     \
  template void             record_errors(const ErrorNorms *,                    \
                                          const DoFHandler<dim> *,               \
                                          const TrilinosWrappers::MPI::Vector &, \
                                          const Function<dim> &,                 \
                                          const NonlocalRegion<dim> &,           \
                                          double,                                \
                                          LevelRecord &);                        \
  template CouplingSolution solve_level(const DiscreteModel *,                   \
                                        const DiscreteModel *,                   \
                                        const OverlapQuadrature<dim> &,          \
                                        const CouplingParameters &,              \
                                        LevelRecord &,                           \
                                        Progress &);
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

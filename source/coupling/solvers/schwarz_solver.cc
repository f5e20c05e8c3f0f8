#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ltn/base/input_error.h>
#include <ltn/base/no_convergence.h>
#include <ltn/coupling/solvers/schwarz_solver.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace ltn
{
  namespace
  {
    using VectorType = TrilinosWrappers::MPI::Vector;

    /**
     * `T`: the traces of one model's field at the other model's controls,
     * as two distributed matrices over this rank's traces (numbered over
     * all ranks like CouplingSystem's overlap points): `values` evaluates
     * the sending field at each trace, `placement` puts each trace at its
     * control's degree of freedom, so that `T x = placement^T values x`
     * reaches controls owned by any rank.
     */
    class TraceOperator
    {
    public:
      TraceOperator(const std::vector<ControlTrace> &traces,
                    const DiscreteModel             &from,
                    const DiscreteModel             &to)
        : to(to)
      {
        const MPI_Comm communicator = to.communicator;
        entries = Utilities::MPI::create_ascending_partitioning(
          communicator,
          traces.size())[Utilities::MPI::this_mpi_process(communicator)];
        const auto first = entries.is_empty() ? 0 : *entries.begin();
        DynamicSparsityPattern value_pattern(entries.size(),
                                             from.owned.size(),
                                             entries);
        DynamicSparsityPattern place_pattern(entries.size(),
                                             to.owned.size(),
                                             entries);
        for (std::size_t t = 0; t < traces.size(); ++t)
          {
            place_pattern.add(first + t, traces[t].first);
            for (const auto &entry : traces[t].second)
              value_pattern.add(first + t, entry.first);
          }
        values.reinit(entries, from.owned, value_pattern, communicator);
        placement.reinit(entries, to.owned, place_pattern, communicator);
        for (std::size_t t = 0; t < traces.size(); ++t)
          {
            placement.set(first + t, traces[t].first, 1.);
            for (const auto &[j, weight] : traces[t].second)
              values.add(first + t, j, weight);
          }
        values.compress(VectorOperation::add);
        placement.compress(VectorOperation::insert);
        at_traces.reinit(entries, communicator);
      }

      /** `T x`, over the receiving model's degrees of freedom. */
      VectorType
      operator()(const VectorType &x) const
      {
        values.vmult(at_traces, x);
        VectorType result = to.new_vector();
        placement.Tvmult(result, at_traces);
        return result;
      }

    private:
      const DiscreteModel           &to;
      IndexSet                       entries;
      TrilinosWrappers::SparseMatrix values, placement;
      mutable VectorType             at_traces;
    };
  } // namespace



  template <int dim>
  CouplingSolution
  solve_alternating_schwarz(const CouplingSystem<dim> &system,
                            const bool                 aitken,
                            const double               relative_tolerance,
                            const unsigned int         max_iterations,
                            const ModelSolverSettings &model_solvers,
                            Progress                  &progress)
  {
    const DiscreteModel &nonlocal     = *system.models[nonlocal_model];
    const DiscreteModel &local        = *system.models[local_model];
    const MPI_Comm       communicator = system.communicator();
    AssertThrow(
      Utilities::MPI::sum(system.overlap.local_control_traces.size(),
                          communicator) == local.n_controls() &&
        Utilities::MPI::sum(system.overlap.nonlocal_control_traces.size(),
                            communicator) == nonlocal.n_controls(),
      ExcMessage("alternating Schwarz needs a trace for every "
                 "control of both models (add_control_traces())"));
    const ModelSolver   nonlocal_solver(nonlocal, false, model_solvers);
    const ModelSolver   local_solver(local, false, model_solvers.local());
    const TraceOperator to_nonlocal(system.overlap.nonlocal_control_traces,
                                    local,
                                    nonlocal);
    const TraceOperator to_local(system.overlap.local_control_traces,
                                 nonlocal,
                                 local);

    CouplingSolution    solution;
    VectorType         &x_n     = solution.fields[nonlocal_model];
    VectorType         &x_l     = solution.fields[local_model];
    VectorType          theta_l = local_solver.new_control_vector();
    VectorType          residual, previous_residual, difference;
    double              omega = 1, first_norm = 0;
    std::vector<double> norms;
    const std::string   name = aitken ?
                                 "alternating Schwarz with Aitken relaxation" :
                                 "alternating Schwarz";
    for (unsigned int sweep = 0;; ++sweep)
      {
        x_l = local_solver.forward(theta_l, true, sweep > 0 ? &x_l : nullptr);
        const VectorType theta_n =
          nonlocal_solver.restrict_to_controls(to_nonlocal(x_l));
        x_n =
          nonlocal_solver.forward(theta_n, true, sweep > 0 ? &x_n : nullptr);
        residual = local_solver.restrict_to_controls(to_local(x_n));
        residual -= theta_l;
        const double norm = residual.l2_norm();
        norms.push_back(norm);
        if (sweep == 0)
          first_norm = norm;
        const double relative = first_norm > 0 ? norm / first_norm : 0.;
        solution.iterations   = sweep;
        solution.residual     = relative;
        progress.report([&] {
          std::ostringstream line;
          line << "coupled solve: sweep " << sweep
               << ", relative mismatch on Gamma_c " << std::scientific
               << std::setprecision(2) << relative;
          return line.str();
        });
        if (norm <= relative_tolerance * first_norm)
          break;
        AssertThrow(std::isfinite(norm) && norm <= 1e4 * first_norm,
                    ExcMessage(name +
                               " diverged: the mismatch on Gamma_c "
                               "grew to " +
                               to_string(relative) +
                               " times its first value at sweep " +
                               std::to_string(sweep)));
        if (sweep >= max_iterations)
          throw no_convergence(name,
                               "Coupling/Relative tolerance",
                               relative_tolerance,
                               max_iterations,
                               relative);
        // Stalled: at the rate of the last ten sweeps the tolerance is out
        // of reach within the sweeps left.
        if (sweep >= 10)
          {
            const double rate = std::pow(norm / norms[sweep - 10], 0.1);
            const bool   out_of_reach =
              rate >= 1 ||
              sweep + std::log(relative_tolerance / relative) / std::log(rate) >
                max_iterations;
            if (out_of_reach)
              {
                std::ostringstream message;
                message << name << " stalled at sweep " << sweep
                        << ": its mismatch on Gamma_c changed by a factor "
                        << std::setprecision(3) << rate
                        << " per sweep over the last ten, at which Coupling/"
                           "Relative tolerance = "
                        << relative_tolerance
                        << " is out of reach within Coupling/Maximum "
                           "iterations = "
                        << max_iterations << " (relative mismatch " << relative
                        << ")";
                throw std::runtime_error(message.str());
              }
          }
        if (aitken && sweep > 0)
          {
            difference = residual;
            difference -= previous_residual;
            const double squared = difference * difference;
            if (squared > 0)
              omega = -omega * (previous_residual * difference) / squared;
          }
        previous_residual = residual;
        theta_l.add(omega, residual);
      }
    solution.model_solvers[nonlocal_model] = nonlocal_solver.statistics();
    solution.model_solvers[local_model]    = local_solver.statistics();
    return solution;
  }

#define LTN_INSTANTIATE(dim)                           \
  template CouplingSolution solve_alternating_schwarz( \
    const CouplingSystem<dim> &,                       \
    bool,                                              \
    double,                                            \
    unsigned int,                                      \
    const ModelSolverSettings &,                       \
    Progress &);
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

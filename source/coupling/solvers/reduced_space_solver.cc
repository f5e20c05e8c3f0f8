#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ltn/base/no_convergence.h>
#include <ltn/coupling/preconditioners/control_coarse_space.h>
#include <ltn/coupling/preconditioners/control_preconditioner.h>
#include <ltn/coupling/solvers/deflated_cg.h>
#include <ltn/coupling/solvers/reduced_space_solver.h>
#include <ltn/coupling/system/reduced_hessian.h>
#include <ltn/model_solvers/model_solver.h>

#include <Epetra_MultiVector.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

namespace ltn
{
  namespace
  {
    using BlockVectorType = TrilinosWrappers::MPI::BlockVector;
    using VectorType      = TrilinosWrappers::MPI::Vector;

    /** The loosest tolerance a relaxed inner solve is given. */
    constexpr double loosest_model_tolerance = 1e-1;

    /**
     * The model solvers' tolerance for a gradient wanted only for its norm,
     * to a few digits: the right-hand side's, which scales the CG's
     * stopping test and its relaxed inner tolerances, and the true
     * residual's, which is reported.
     */
    constexpr double norm_tolerance = 1e-3;

    /** The loosest tolerance of the local model's coarse states. */
    constexpr double local_coarse_state_tolerance = 1e-12;
  } // namespace



  template <int dim>
  CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<dim> &system,
                         const double               relative_tolerance,
                         const unsigned int         max_iterations,
                         const ModelSolverSettings &model_solvers,
                         const ControlPreconditionerSettings &controls,
                         const bool time_standalone_solves,
                         Progress  &progress)
  {
    // Two levels (doc/discretization.md, 'A coarse level for the
    // controls'): deflation by the
    // nonlocal controls' polynomial fields and by every local control,
    // which makes the CG one on the nonlocal controls' Schur complement,
    // preconditioned by D_n; one level: P alone. E^{-1} amplifies the inner
    // solves' errors (H_ll is ill-conditioned): with inner solves to the
    // outer tolerance the 1e4 bar's CG broke down (to 1e-9: 14 iterations,
    // as with 1e-10), so they are solved to at most 1e-2 of it.
    const bool          two_level = controls.enabled && controls.coarse_degree;
    ModelSolverSettings inner     = model_solvers;
    if (two_level)
      inner.relative_tolerance =
        std::min(inner.relative_tolerance, 1e-2 * relative_tolerance);
    CouplingSolution solution;
    Timer            phase_timer;
    ModelSolver nonlocal_solver(*system.models[nonlocal_model], true, inner);
    ModelSolver local_solver(*system.models[local_model], true, inner.local());
    const ReducedHessian<dim> hessian(system,
                                      {{&nonlocal_solver, &local_solver}});
    // Each phase's wall time and the model solves in it, for the summary.
    std::array<ModelSolverStatistics, 2> phase_start;
    const auto end_phase = [&](const std::string &name) {
      progress.report([&] { return "coupled solve: " + name + " done"; });
      CouplingSolution::Phase phase{name, phase_timer.wall_time(), {}};
      for (const unsigned int k : {0u, 1u})
        {
          const ModelSolverStatistics now = hessian.solvers[k]->statistics();
          phase.model_solvers[k]          = now.since(phase_start[k]);
          phase_start[k]                  = now;
        }
      solution.phases.push_back(phase);
      phase_timer.restart();
    };
    end_phase("model solver setup");

    // The right-hand side is b = -V^T B^T W d, d the mismatch of the
    // models' states without controls. The CG forms its start's residual
    // from d, so b is wanted only for its norm, the CG's scale, and is
    // solved to the norm's own accuracy: at the model solvers' tolerance
    // it cost a nonlocal solve of 28 CG iterations of the 512 of the 1e5
    // bar of benchmarks/scaling.
    BlockVectorType theta = hessian.new_control_vector();
    // The models' states for their data alone; the CG adds those of its
    // controls, and the final solves start from the sum.
    NormalEquations::States states;
    for (const unsigned int k : {0u, 1u})
      states[k] = hessian.solvers[k]->forward(theta.block(k), true);
    const NormalEquations::Observation data =
      system.mismatch(states[0], states[1]);
    for (const ModelSolver *solver : hessian.solvers)
      solver->set_relative_tolerance(
        std::max(norm_tolerance, inner.relative_tolerance));
    const double rhs_norm = hessian.reduced_gradient(data).l2_norm();
    for (const ModelSolver *solver : hessian.solvers)
      solver->set_relative_tolerance(inner.relative_tolerance);
    end_phase("right-hand side");

    if (rhs_norm > 0)
      {
        SolverControl control(max_iterations, relative_tolerance * rhs_norm);
        // Relaxed inner solves (doc/discretization.md, 'A coarse level for
        // the controls'): the
        // error of the Hessian's products may grow as the residual falls.
        unsigned int iteration = 0;
        const auto   relax     = [&](const double residual) {
          ++iteration;
          progress.report([&] {
            std::ostringstream line;
            line << "coupled solve: iteration " << iteration
                 << ", relative residual " << std::scientific
                 << std::setprecision(2) << residual / rhs_norm;
            return line.str();
          });
          const double relaxed =
            inner.relative_tolerance * rhs_norm /
            std::max(residual, std::numeric_limits<double>::min());
          for (const ModelSolver *solver : hessian.solvers)
            solver->set_relative_tolerance(std::clamp(
              relaxed,
              inner.relative_tolerance,
              std::max(loosest_model_tolerance, inner.relative_tolerance)));
        };
        NormalEquations equations = hessian.normal_equations();
        // B_l^T W B_l assembled: each local coarse column's entries of E
        // are then a sparse product over the local unknowns, not a pass
        // over every overlap point and back (78 columns took about 4 s of
        // the 10^6 bar of benchmarks/scaling that way), and many columns
        // share one product, a pass over the matrix's rows for all of them.
        std::optional<TrilinosWrappers::SparseMatrix> local_gram;
        if (two_level)
          {
            local_gram.emplace(system.observation_gram(local_model));
            equations.observe_alone[local_model] = [&](const unsigned int n,
                                                       const double      *u,
                                                       double            *g) {
              const Epetra_CrsMatrix &gram = local_gram->trilinos_matrix();
              const int               size = gram.RowMap().NumMyElements();
              // Epetra's views need an address even for no entries.
              double             none = 0;
              Epetra_MultiVector states(View,
                                        gram.DomainMap(),
                                        size ? const_cast<double *>(u) : &none,
                                        std::max(size, 1),
                                        n);
              Epetra_MultiVector gradients(
                View, gram.RangeMap(), size ? g : &none, std::max(size, 1), n);
              AssertThrow(gram.Multiply(false, states, gradients) == 0,
                          ExcMessage("the local coarse columns' gradients"));
            };
          }
        try
          {
            std::unique_ptr<const ControlPreconditioner<dim>> preconditioner;
            if (controls.enabled)
              preconditioner = std::make_unique<ControlPreconditioner<dim>>(
                hessian,
                std::nullopt,
                !two_level,
                controls.surrogate_nonlocal_block,
                controls.collar_layer_weight);
            // Each column kept in its own model's controls only: a full
            // control vector per local column would be mostly the nonlocal
            // controls' zeros (78 x 768k values on the 10^6 bar).
            std::vector<DeflationSpace::Column> Z;
            if (two_level)
              {
                // Each field's forward solve starts from the field itself
                // at every particle: exact for rigid motions, and away from
                // cracks for any linear field (doc/discretization.md,
                // 'A coarse level for the controls').
                for (auto &z :
                     polynomial_control_fields(hessian,
                                               *controls.coarse_degree,
                                               {nonlocal_model},
                                               controls.nonlocal_coarse_fields))
                  {
                    solution.crack_opening_fields += z.given ? 1 : 0;
                    Z.push_back({z.model,
                                 z.controls.block(z.model),
                                 std::move(z.extension)});
                  }
                for (auto &z : unit_control_fields(hessian, local_model))
                  Z.push_back({local_model, std::move(z)});
              }
            // The nonlocal coarse states to the outer tolerance (section
            // 19, "The coarse states' tolerances"): to the inner one, 100
            // times tighter, they cost the 10^6 bar of benchmarks/scaling
            // 39 more CG iterations (2.5 s) for the same outer iterations,
            // true residual and opening; 100 times looser, its true
            // residual grew 8 times. The local ones need more than the
            // inner tolerance: E's local block is H_ll, whose condition
            // number grows like a power of 1/h ('Preconditioning the
            // reduced Hessian'), and E^{-1}
            // amplifies their errors. With local states to 1e-8 the 1e4
            // bar's CG stalled at 5e-4; local solves are cheap.
            const ModelSolver &nonlocal = *hessian.solvers[nonlocal_model];
            const ModelSolver &local    = *hessian.solvers[local_model];
            nonlocal.set_relative_tolerance(
              std::max(inner.relative_tolerance, relative_tolerance));
            local.set_relative_tolerance(
              std::min(inner.relative_tolerance, local_coarse_state_tolerance));
            const DeflationSpace coarse(std::move(Z), equations);
            nonlocal.set_relative_tolerance(inner.relative_tolerance);
            local.set_relative_tolerance(inner.relative_tolerance);
            end_phase("coarse space");
            solution.preconditioner_setup_seconds =
              solution.phases.back().seconds;
            if (preconditioner)
              {
                solution.explicit_controls =
                  preconditioner->n_explicit_controls();
                solution.nonlocal_block_unknowns =
                  preconditioner->n_nonlocal_block_unknowns();
              }
            solution.coarse_modes = coarse.size();
            RitzValues ritz_values;
            solve_deflated_cg(
              equations,
              coarse,
              [&](BlockVectorType &dst, const BlockVectorType &src) {
                if (preconditioner)
                  preconditioner->vmult(dst, src);
                else
                  dst = src;
              },
              data,
              theta,
              control,
              relax,
              &states,
              &ritz_values);
            end_phase("iterations");
            // What bounds the iterations ('A coarse level for the controls'):
            // on the cracked plate
            // an isolated smallest value, and a largest that grows like the
            // overlap's width over the horizon.
            const std::vector<double> ritz = ritz_values.values();
            if (!ritz.empty())
              {
                solution.smallest_ritz_value = ritz.front();
                solution.largest_ritz_value  = ritz.back();
              }
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
          solver->set_relative_tolerance(inner.relative_tolerance);
        solution.iterations = control.last_step();
        solution.residual   = control.last_value() / rhs_norm;
      }
    // To the inner solvers' full tolerance, from the states the CG tracked
    // to its relaxed ones: on the 1e5 bar of benchmarks/scaling the
    // nonlocal solve took 27 CG iterations from zero.
    for (const unsigned int k : {0u, 1u})
      solution.fields[k] =
        hessian.solvers[k]->forward(theta.block(k), true, &states[k]);
    end_phase("final solves");
    // The CG's residual is its recursion's; the relaxed products let the
    // true one, H theta - b = the gradient at the final controls, drift
    // from it (doc/discretization.md, 'A coarse level for the controls',
    // "The true residual").
    // Its adjoint solves cost a few CG iterations.
    if (rhs_norm > 0)
      {
        for (const ModelSolver *solver : hessian.solvers)
          solver->set_relative_tolerance(
            std::max(norm_tolerance, inner.relative_tolerance));
        BlockVectorType gradient = hessian.reduced_gradient(
          system.mismatch(solution.fields[0], solution.fields[1]));
        gradient.add(system.alpha, theta);
        solution.true_residual = gradient.l2_norm() / rhs_norm;
        for (const ModelSolver *solver : hessian.solvers)
          solver->set_relative_tolerance(inner.relative_tolerance);
        end_phase("true residual");
      }
    solution.model_solvers = {
      {nonlocal_solver.statistics(), local_solver.statistics()}};
    if (time_standalone_solves)
      {
        // What solving the two models alone once costs with the same
        // solvers and tolerances: the final solves no longer show it, as
        // they start from the CG's states. A phase of its own, outside the
        // model solvers' totals.
        for (const unsigned int k : {0u, 1u})
          hessian.solvers[k]->forward(theta.block(k), true);
        end_phase("standalone solves");
        solution.standalone_seconds =
          solution.phases.front().seconds + solution.phases.back().seconds;
      }
    return solution;
  }

#define LTN_INSTANTIATE(dim)                        \
  template CouplingSolution solve_reduced_space_cg( \
    const CouplingSystem<dim> &,                    \
    double,                                         \
    unsigned int,                                   \
    const ModelSolverSettings &,                    \
    const ControlPreconditionerSettings &,          \
    bool,                                           \
    Progress &);
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

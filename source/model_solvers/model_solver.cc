#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <ltn/base/no_convergence.h>
#include <ltn/base/partition.h>
#include <ltn/model_solvers/model_solver.h>

#include <algorithm>

namespace ltn
{
  namespace
  {
    /** Adds the wall time of its lifetime to @p seconds. */
    class ScopedTime
    {
    public:
      explicit ScopedTime(double &seconds)
        : seconds(seconds)
      {}

      ~ScopedTime()
      {
        seconds += timer.wall_time();
      }

    private:
      double &seconds;
      Timer   timer;
    };

    /**
     * A linear operator for deal.II's solvers: @p apply(dst, src), its wall
     * time added to @p seconds.
     */
    template <typename Apply>
    struct TimedOperator
    {
      Apply   apply;
      double &seconds;

      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        const ScopedTime time(seconds);
        apply(dst, src);
      }
    };

    template <typename Apply>
    TimedOperator<Apply>
    timed(double &seconds, Apply apply)
    {
      return {apply, seconds};
    }
  } // namespace



  ModelSolver::ModelSolver(const DiscreteModel       &model,
                           const bool                 with_adjoint,
                           const ModelSolverSettings &settings)
    : model(model)
    , settings(settings)
    // CG's preconditioner acts on the free block's entries alone, which
    // only the particle models' lattice surrogate offers: the FEM models
    // keep GMRES. CG's free block keeps the constraint rows of hanging
    // nodes, which are not symmetric.
    , use_cg(settings.kind == ModelSolverKind::preconditioned_cg &&
             model.symmetric_free_block && model.lattice &&
             Utilities::MPI::max(model.constrained.n_elements(),
                                 model.communicator) == 0)
    , tolerance(settings.relative_tolerance)
    , control_dofs(model.controls.begin(), model.controls.end())
  {
    control_partition =
      contiguous_partition(control_dofs.size(), model.communicator);
    controls_eliminated =
      Utilities::MPI::max(std::any_of(control_dofs.begin(),
                                      control_dofs.end(),
                                      [&](const types::global_dof_index i) {
                                        return model.eliminated.is_element(i);
                                      }) ?
                            1u :
                            0u,
                          model.communicator) > 0;
    first_control =
      control_partition.is_empty() ? 0 : control_partition.nth_index_in_set(0);
    if (settings.iterative())
      {
        forward_system = std::make_unique<SchurComplement>(model, false);
        preconditioner = std::make_unique<ModelPreconditioner>(
          model,
          use_cg ? forward_system->free_positions() :
                   std::vector<unsigned int>(),
          settings.multigrid);
        counts.memory = preconditioner->memory_consumption() +
                        forward_system->memory_consumption();
        if (with_adjoint)
          {
            adjoint_system =
              std::make_unique<SchurComplement>(model,
                                                true,
                                                forward_system.get());
            counts.memory += adjoint_system->memory_consumption();
          }
      }
    else
      direct = std::make_unique<ModelDirectSolver>(model);
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::new_control_vector() const
  {
    return TrilinosWrappers::MPI::Vector(control_partition, model.communicator);
  }



  void
  ModelSolver::solve(const bool                           transpose,
                     TrilinosWrappers::MPI::Vector       &x,
                     const TrilinosWrappers::MPI::Vector &b,
                     const bool                           with_eliminated) const
  {
    ++counts.solves;
    const ScopedTime time(counts.seconds);
    if (direct)
      {
        direct->solve(x, b, transpose);
        return;
      }

    const double b_norm = b.l2_norm();
    if (b_norm == 0)
      {
        x = 0.;
        return;
      }
    // The tolerance is on the true residual (GMRES: with right
    // preconditioning), relative to the free block's right-hand side:
    // solve_free_block sets it.
    SolverControl control(settings.max_iterations, 0.);
    try
      {
        solve_free_block(transpose, x, b, control, with_eliminated);
      }
    catch (const SolverControl::NoConvergence &)
      {
        throw no_convergence(use_cg ? "a model's CG" : "a model's GMRES",
                             "Coupling/Model solver tolerance",
                             tolerance,
                             settings.max_iterations,
                             control.last_value() / control.tolerance() *
                               tolerance);
      }
    counts.iterations += control.last_step();
  }



  void
  ModelSolver::solve_free_block(const bool                           transpose,
                                TrilinosWrappers::MPI::Vector       &x,
                                const TrilinosWrappers::MPI::Vector &b,
                                SolverControl                       &control,
                                const bool with_eliminated) const
  {
    // With O the kept degrees of freedom outside the free block (controls
    // and fixed data, identity rows), S = [[S_FF, S_FO], [0, I]], so
    //   S u = g:    u_O = g_O,  S_FF u_F = Z (g - S u_O),
    //   S^T y = g:  S_FF^T y_F = Z g,  y_O = g_O - (S^T y_F)_O:
    // the adjoint applies S^T around the iteration (here, in reduce() and in
    // recover()), not in it.
    const SchurComplement &system =
      transpose ? *adjoint_system : *forward_system;
    // CG iterates with S_FF for the adjoint too (S_FF^T = S_FF, and the
    // forward product is the cheaper one); GMRES with S_FF^T.
    const SchurComplement        &block = use_cg ? *forward_system : system;
    TrilinosWrappers::MPI::Vector g     = system.reduce(b);
    TrilinosWrappers::MPI::Vector rhs   = g;
    block.restrict_to_free_block(rhs);
    TrilinosWrappers::MPI::Vector outside = g;
    outside -= rhs;
    TrilinosWrappers::MPI::Vector product = model.new_vector();
    if (!transpose)
      {
        block.vmult_from_outside(product, outside);
        block.restrict_to_free_block(product);
        rhs -= product;
      }

    block.restrict_to_free_block(x);
    // Relative to the free block's own right-hand side, not to b: b's
    // control rows are displacements, the free block's rows forces, so a
    // tolerance on |b| tightened the forward solves by |S_FO theta| /
    // |theta|, about 400 on the 1e4 bar of benchmarks/scaling at E = 1, and
    // by 2e11 times more in pascals (doc/discretization.md, 'Iterative
    // model solvers').
    const double rhs_norm = rhs.l2_norm();
    control.set_tolerance(tolerance * rhs_norm);
    if (rhs_norm > 0 && use_cg)
      {
        // On the free block's own entries: CG's vector updates and inner
        // products then pass over them alone.
        TrilinosWrappers::MPI::Vector x_free   = block.new_free_vector();
        TrilinosWrappers::MPI::Vector rhs_free = block.new_free_vector();
        block.extract_free(x_free, x);
        block.extract_free(rhs_free, rhs);
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        // S_FF, and Z P Z^T, on vectors of the free block's entries.
        cg.solve(timed(counts.operator_seconds,
                       [&](auto &dst, const auto &src) {
                         block.vmult_free_vector(dst, src);
                       }),
                 x_free,
                 rhs_free,
                 timed(counts.preconditioner_seconds,
                       [&](auto &dst, const auto &src) {
                         preconditioner->vmult_subset(dst, src);
                       }));
        block.insert_free(x, x_free);
      }
    else if (rhs_norm > 0)
      {
        SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
          control,
          SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(50, true));
        // S_FF = Z S Z, and Z P Z, on vectors of all the model's entries.
        gmres.solve(timed(counts.operator_seconds,
                          [&](auto &dst, const auto &src) {
                            block.vmult_free_block(dst, src);
                          }),
                    x,
                    rhs,
                    timed(counts.preconditioner_seconds,
                          [&](auto &dst, const auto &src) {
                            preconditioner->vmult(dst, src);
                            block.restrict_to_free_block(dst);
                          }));
      }
    else
      x = 0.; // S_FF is nonsingular

    if (transpose)
      {
        // (S^T y_F)_O; S^T's rows at the eliminated degrees of freedom are
        // zero.
        adjoint_system->vmult_at_outside(product, x);
        TrilinosWrappers::MPI::Vector in_block = product;
        block.restrict_to_free_block(in_block);
        product -= in_block;
        outside -= product;
      }
    x += outside;
    // recover() sets only the eliminated entries, at the cost of a product
    // over all eliminated rows (on the 3e5 bar of benchmarks/scaling 17 ms a
    // solve, as much as a tenth of a solve late in the outer CG).
    if (with_eliminated)
      system.recover(x, b);
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::forward(const TrilinosWrappers::MPI::Vector &theta,
                       const bool                           with_data,
                       const TrilinosWrappers::MPI::Vector *initial_guess) const
  {
    // The control rows of `r` are zero.
    TrilinosWrappers::MPI::Vector rhs = extend_controls(theta);
    if (with_data)
      rhs += model.rhs;

    TrilinosWrappers::MPI::Vector field =
      initial_guess ? *initial_guess : model.new_vector();
    solve(false, field, rhs);
    return field;
  }



  std::vector<TrilinosWrappers::MPI::Vector>
  ModelSolver::forward(
    const std::vector<TrilinosWrappers::MPI::Vector> &thetas) const
  {
    std::vector<TrilinosWrappers::MPI::Vector> fields;
    if (!direct)
      {
        for (const auto &theta : thetas)
          fields.push_back(forward(theta, false));
        return fields;
      }
    std::vector<TrilinosWrappers::MPI::Vector> rhs;
    for (const auto &theta : thetas)
      rhs.push_back(extend_controls(theta));
    counts.solves += thetas.size();
    const ScopedTime time(counts.seconds);
    direct->solve(fields, rhs, false);
    return fields;
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::adjoint(const TrilinosWrappers::MPI::Vector &z) const
  {
    TrilinosWrappers::MPI::Vector multiplier = model.new_vector();
    // Only the entries at the controls are returned.
    solve(true, multiplier, z, controls_eliminated);
    return restrict_to_controls(multiplier);
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::restrict_to_controls(
    const TrilinosWrappers::MPI::Vector &x) const
  {
    TrilinosWrappers::MPI::Vector restricted = new_control_vector();
    for (std::size_t c = 0; c < control_dofs.size(); ++c)
      restricted(first_control + c) = x(control_dofs[c]);
    restricted.compress(VectorOperation::insert);
    return restricted;
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::extend_controls(const TrilinosWrappers::MPI::Vector &theta) const
  {
    TrilinosWrappers::MPI::Vector extended = model.new_vector();
    for (std::size_t c = 0; c < control_dofs.size(); ++c)
      extended(control_dofs[c]) = theta(first_control + c);
    extended.compress(VectorOperation::insert);
    return extended;
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::solve(const bool                           transpose,
                     const TrilinosWrappers::MPI::Vector &b) const
  {
    TrilinosWrappers::MPI::Vector x = model.new_vector();
    solve(transpose, x, b);
    return x;
  }



  void
  ModelSolver::set_relative_tolerance(const double relative_tolerance) const
  {
    tolerance = relative_tolerance;
  }



  ModelSolverStatistics
  ModelSolver::statistics() const
  {
    return counts;
  }
} // namespace ltn

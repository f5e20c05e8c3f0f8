#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/base/selection.h>
#include <ltn/base/solver_statistics.h>
#include <ltn/model_solvers/model_direct_solver.h>
#include <ltn/model_solvers/model_preconditioner.h>
#include <ltn/model_solvers/schur_complement.h>

#include <array>
#include <memory>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** The solver of a model's equations (`Coupling/Model solvers`). */
  enum class ModelSolverKind
  {
    /** Chosen per level by choose_solvers() (scene/solver_choice.h). */
    automatic,
    /** A sparse direct solver (MUMPS), which needs the assembled matrix. */
    direct,
    /**
     * GMRES on the SchurComplement, preconditioned by ModelPreconditioner.
     */
    preconditioned_gmres,
    /**
     * The same, but CG on the free block of the Schur complement where it
     * is symmetric positive definite (DiscreteModel::symmetric_free_block)
     * and the model has a lattice surrogate, for `M` and `M^T` alike; GMRES
     * elsewhere.
     */
    preconditioned_cg
  };

  /** The names of the model solvers in `Coupling/Model solvers`. */
  inline const SelectionNames<ModelSolverKind> &
  model_solver_names()
  {
    static const SelectionNames<ModelSolverKind> names = {
      {ModelSolverKind::automatic, "auto"},
      {ModelSolverKind::direct, "direct"},
      {ModelSolverKind::preconditioned_gmres, "preconditioned gmres"},
      {ModelSolverKind::preconditioned_cg, "preconditioned cg"}};
    return names;
  }

  /** How a model's equations are solved (subsection `Coupling`). */
  struct ModelSolverSettings
  {
    ModelSolverKind kind = ModelSolverKind::direct;

    /** Does the model solve by a Krylov method (set, and not `direct`)? */
    bool
    iterative() const
    {
      return kind == ModelSolverKind::preconditioned_gmres ||
             kind == ModelSolverKind::preconditioned_cg;
    }
    /**
     * The residual reduction relative to the right-hand side of the free
     * block (doc/discretization.md, 'Iterative model solvers').
     */
    double       relative_tolerance = 1e-12;
    unsigned int max_iterations     = 1000;
    /** The preconditioner's multigrid on a lattice surrogate. */
    SurrogateMultigridSettings multigrid;
    /**
     * Factorize the local (finite element) model however the particle model
     * is solved: its mesh is coarse wherever the coupling is used, and a
     * coupled solve needs one local solve per local coarse column.
     */
    bool direct_local_model = false;

    /** The settings of the local model's solver. */
    ModelSolverSettings
    local() const
    {
      ModelSolverSettings settings = *this;
      if (direct_local_model)
        settings.kind = ModelSolverKind::direct;
      return settings;
    }
  };

  /**
   * One model's own solver, as the reduced-space method sees it: a black box
   * that solves the model's equations for given controls (forward) and the
   * transposed equations (adjoint). The model's field for controls `theta`
   * solves `M x = r + S theta` (see DiscreteModel). The direct solver
   * factorizes `M` and `M^T` once. The iterative one builds their
   * preconditioners once and starts each solve from zero or from a given
   * guess (doc/discretization.md, 'Iterative model solvers', "Starting
   * values").
   *
   * Controls are numbered `0 .. n_controls - 1` over all ranks, each rank
   * owning a contiguous range: those of its own control degrees of freedom,
   * in their order.
   */
  class ModelSolver
  {
  public:
    /**
     * Prepare to solve with the model's matrix, and @p with_adjoint with its
     * transpose, as @p settings say.
     */
    ModelSolver(const DiscreteModel       &model,
                const bool                 with_adjoint,
                const ModelSolverSettings &settings = ModelSolverSettings());

    /** A zero vector of controls. */
    TrilinosWrappers::MPI::Vector
    new_control_vector() const;

    /**
     * The model's field for controls @p theta; with @p with_data, the load
     * and fixed data enter, otherwise they are taken as zero (the linear part
     * of the control-to-state map). The iterative solver starts from
     * @p initial_guess if given (its values at the controls and the fixed
     * data are replaced), else from zero.
     */
    TrilinosWrappers::MPI::Vector
    forward(const TrilinosWrappers::MPI::Vector &theta,
            const bool                           with_data,
            const TrilinosWrappers::MPI::Vector *initial_guess = nullptr) const;

    /**
     * forward() without data for each of @p thetas: a factorized model
     * solves for all of them at once, reading its factors once (on the 2D
     * cracked plate's 352 local coarse columns, 9.8 s one at a time); an
     * iterative one solves them one after the other.
     */
    std::vector<TrilinosWrappers::MPI::Vector>
    forward(const std::vector<TrilinosWrappers::MPI::Vector> &thetas) const;

    /**
     * The adjoint of the control-to-state map of forward() (without data):
     * for a gradient @p z with respect to all degrees of freedom, the
     * gradient with respect to the controls, `S^T M^{-T} z`.
     */
    TrilinosWrappers::MPI::Vector
    adjoint(const TrilinosWrappers::MPI::Vector &z) const;

    /**
     * `S^T x`: the entries of @p x (over the model's degrees of freedom) at
     * the control degrees of freedom, as a vector of controls.
     */
    TrilinosWrappers::MPI::Vector
    restrict_to_controls(const TrilinosWrappers::MPI::Vector &x) const;

    /** `S theta`: the controls @p theta at their degrees of freedom. */
    TrilinosWrappers::MPI::Vector
    extend_controls(const TrilinosWrappers::MPI::Vector &theta) const;

    /**
     * `M^{-1} b` (@p transpose: `M^{-T} b`) for any right-hand side @p b.
     */
    TrilinosWrappers::MPI::Vector
    solve(const bool transpose, const TrilinosWrappers::MPI::Vector &b) const;

    /**
     * Solve the following systems of the iterative solver to a residual
     * reduction of @p relative_tolerance instead of the settings' one: an
     * outer Krylov method relaxes its inner solves as it converges.
     */
    void
    set_relative_tolerance(const double relative_tolerance) const;

    /** The solves so far and their iterations, summed over both kinds. */
    ModelSolverStatistics
    statistics() const;

  private:
    /**
     * Solve `M x = b` (@p transpose: `M^T x = b`); the iterative solver
     * starts from @p x. Without @p with_eliminated it leaves the eliminated
     * entries (DiscreteModel::eliminated) zero.
     */
    void
    solve(const bool                           transpose,
          TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &b,
          const bool                           with_eliminated = true) const;

    /**
     * The iterative solve of `M x = b` (@p transpose: `M^T x = b`) by CG
     * or GMRES on the free block (doc/discretization.md, 'Iterative model
     * solvers'), from
     * the initial guess @p x, to the current tolerance relative to the free
     * block's right-hand side (which sets that of @p control).
     */
    void
    solve_free_block(const bool                           transpose,
                     TrilinosWrappers::MPI::Vector       &x,
                     const TrilinosWrappers::MPI::Vector &b,
                     SolverControl                       &control,
                     const bool with_eliminated) const;

    const DiscreteModel      &model;
    const ModelSolverSettings settings;
    /** Solve by CG on the free block (else GMRES)? */
    const bool use_cg;
    /** The residual reduction of the next iterative solves. */
    mutable double                       tolerance;
    std::vector<types::global_dof_index> control_dofs;
    /** Is a control an eliminated degree of freedom, on any rank? */
    bool controls_eliminated = false;
    /** The number of this rank's first control. */
    types::global_dof_index              first_control;
    IndexSet                             control_partition;
    std::unique_ptr<ModelDirectSolver>   direct;
    std::unique_ptr<ModelPreconditioner> preconditioner;
    std::unique_ptr<SchurComplement>     forward_system, adjoint_system;
    mutable ModelSolverStatistics        counts;
  };
} // namespace ltn

#pragma once

#include <deal.II/base/types.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * How often a model's solver ran, how many iterations it took, and the
   * wall time (this rank's) of its solves, of which the iterative solver
   * spent some in products with the operator and some in its
   * preconditioner (the rest: vector operations, the Schur complement's
   * reduction and recovery).
   */
  struct ModelSolverStatistics
  {
    unsigned int solves                 = 0;
    unsigned int iterations             = 0;
    double       seconds                = 0;
    double       operator_seconds       = 0;
    double       preconditioner_seconds = 0;
    /** Bytes of this rank's factorization or preconditioners (estimated). */
    std::size_t memory = 0;

    /** The solves, iterations and times since @p earlier (memory: now). */
    ModelSolverStatistics
    since(const ModelSolverStatistics &earlier) const
    {
      return {solves - earlier.solves,
              iterations - earlier.iterations,
              seconds - earlier.seconds,
              operator_seconds - earlier.operator_seconds,
              preconditioner_seconds - earlier.preconditioner_seconds,
              memory};
    }
  };

  /**
   * What a solve of a level reports of its solvers: the one record that
   * the coupled solvers fill (CouplingSolution derives from it) and the
   * run summary writes (LevelRecord holds it).
   */
  struct SolverStatistics
  {
    /** One phase of a solve: its wall time, each model's solves in it. */
    struct Phase
    {
      std::string                          name;
      double                               seconds = 0;
      std::array<ModelSolverStatistics, 2> model_solvers;
    };

    unsigned int iterations = 0;
    /** The relative residual the solver reached. */
    double residual = 0;
    /**
     * The reduced-space CG's true relative residual at its final controls
     * (`residual` is its recursion's, which relaxed inner solves let drift
     * from it); negative where not computed.
     */
    double true_residual = -1;
    /**
     * Force-based blending's `|K - K^T|_F / |K|_F`: how far its matrix is
     * from symmetric; negative for the other methods.
     */
    double asymmetry = -1;
    /**
     * The controls whose Hessian block the preconditioner of the
     * reduced-space CG holds explicitly (ControlPreconditioner); 0 without.
     */
    unsigned int explicit_controls = 0;
    /**
     * The coarse modes of its second level (DeflationSpace in the
     * reduced-space CG, ControlCoarseSpace in the full-space GMRES); 0
     * without.
     */
    unsigned int coarse_modes = 0;
    /**
     * Of those, the given fields (`ControlPreconditionerSettings::
     * nonlocal_coarse_fields`) the polynomial columns did not already span.
     */
    unsigned int crack_opening_fields = 0;
    /**
     * The size of the saddle-point system that inverts the model of the
     * nonlocal controls' Hessian block (SurrogateHessianBlock); 0 without.
     */
    types::global_dof_index nonlocal_block_unknowns = 0;
    /** Wall time to build that preconditioner. */
    double preconditioner_setup_seconds = 0;
    /**
     * The reduced-space CG's extreme Ritz values (RitzValues): estimates of
     * the extreme eigenvalues of the reduced Hessian as its preconditioner
     * and coarse space leave it; 0 without.
     */
    double smallest_ritz_value = 0, largest_ritz_value = 0;
    /**
     * Wall time of what solving each model once alone costs with the same
     * solvers and tolerances: building both model solvers, and a forward
     * solve of each from zero with its data and the final controls, after
     * the coupled solve (the reduced-space CG, if asked to time them; else
     * 0).
     */
    double standalone_seconds = 0;
    /** Per model: its own solver's solves, iterations and memory. */
    std::array<ModelSolverStatistics, 2> model_solvers;
    /** The phases of the solve, in order (the reduced-space CG's). */
    std::vector<Phase> phases;
  };
} // namespace ltn

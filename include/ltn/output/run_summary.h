#pragma once

#include <deal.II/base/types.h>

#include <ltn/base/field_errors.h>
#include <ltn/base/json.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** What one refinement level of a run measured. */
  struct LevelRecord
  {
    double h = 0;
    /** Adaptive refinement cycle of the local mesh within the level. */
    unsigned int            cycle           = 0;
    double                  horizon         = 0;
    types::global_dof_index n_nonlocal_dofs = 0;
    types::global_dof_index n_local_dofs    = 0;
    types::global_dof_index n_controls      = 0;
    std::string             solver_method;
    unsigned int            iterations = 0;
    double                  residual   = 0;
    /** CouplingSolution::true_residual (negative: not computed). */
    double true_residual = -1;
    /**
     * The reduced-space preconditioner's explicit controls, coarse modes,
     * setup time.
     */
    unsigned int explicit_controls            = 0;
    unsigned int coarse_modes                 = 0;
    double       preconditioner_setup_seconds = 0;
    /** The Collar layer weight the Control preconditioner used. */
    double collar_layer_weight = 0;
    /** CouplingSolution::crack_opening_fields. */
    unsigned int crack_opening_fields = 0;
    /** CouplingSolution::nonlocal_block_unknowns. */
    types::global_dof_index nonlocal_block_unknowns = 0;
    /** CouplingSolution::standalone_seconds. */
    double standalone_seconds = 0;
    /** CouplingSolution::smallest_ritz_value and largest_ritz_value. */
    double smallest_ritz_value = 0, largest_ritz_value = 0;
    /**
     * Per model (nonlocal, local): its own solver's solves, iterations,
     * and wall time (rank 0's) in all, in operator products and in the
     * preconditioner (ModelSolverStatistics).
     */
    std::array<unsigned int, 2> model_solves                 = {{0, 0}};
    std::array<unsigned int, 2> model_iterations             = {{0, 0}};
    std::array<double, 2>       model_seconds                = {{0, 0}};
    std::array<double, 2>       model_operator_seconds       = {{0, 0}};
    std::array<double, 2>       model_preconditioner_seconds = {{0, 0}};
    /** A phase of the coupled solve and the model solves in it. */
    struct SolvePhase
    {
      std::string                 name;
      double                      seconds       = 0;
      std::array<unsigned int, 2> solves        = {{0, 0}};
      std::array<unsigned int, 2> iterations    = {{0, 0}};
      std::array<double, 2>       solve_seconds = {{0, 0}};
    };
    /** The coupled solve's phases (reduced-space CG), in order. */
    std::vector<SolvePhase> solve_phases;
    /**
     * Per model, bytes over all ranks for its operator, right-hand side and
     * solver (preconditioners; direct factorizations are not counted).
     */
    std::array<double, 2>   model_bytes = {{0, 0}};
    types::global_dof_index n_particles = 0;
    double                  mismatch_J  = 0;
    /** False when the scene has no exact solution. */
    bool       has_errors = false;
    ErrorNorms nonlocal_errors, local_errors, coupled_errors;
    /**
     * What the scene's physics measures besides errors (elasticity: section
     * forces, applied forces, crack openings), written as `mechanics`;
     * null if nothing.
     */
    JsonValue extras;
    /** Wall time per phase, seconds, in the order the phases ran. */
    std::vector<std::pair<std::string, double>> timings;
  };

  /**
   * The run summary, written as `summary.json` (a public interface: see the
   * README for its keys). The top-level fields describe the finest level;
   * a run with several levels adds `convergence`, one entry per level with
   * its mesh size `h` and the observed rates against the previous level.
   */
  struct RunSummary
  {
    std::string              scene;
    unsigned int             dim = 1;
    std::string              model;
    std::vector<LevelRecord> levels;
    double                   total_time = 0;
    double                   memory_mb  = 0;

    JsonValue
    to_json() const;
  };

  /**
   * The observed rate `log(e_coarse / e_fine) / log(h_coarse / h_fine)`.
   */
  double
  observed_rate(const double e_coarse,
                const double e_fine,
                const double h_coarse,
                const double h_fine);
} // namespace ltn

#pragma once

#include <deal.II/base/types.h>

#include <ltn/base/field_errors.h>
#include <ltn/base/json.h>
#include <ltn/base/solver_statistics.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** What one refinement level of a run measured. */
  /**
   * The short-wave model-error estimate of a coupled level
   * (`Postprocess/Model error estimate`, estimate_model_error()).
   */
  struct ModelErrorRecord
  {
    bool computed = false;
    /**
     * `eta = (eta_0^2 + eta_1^2)^(1/2)`: the short waves, `eta_0 =
     * (sum_E V |r_i|^2 / chi / c_G)^(1/2)`, and the long ones, `eta_1 =
     * a_l(z, z)^(1/2)` of the error representer `z` in the local model's
     * finite elements on the whole body.
     */
    double estimate       = 0;
    double estimate_short = 0;
    double estimate_long  = 0;
    /** `eta` over the energy norm of the composite field. */
    double relative = 0;
    /**
     * The same sum within the interaction range of the body's Dirichlet
     * faces, not in `estimate`: the two problems differ there whatever the
     * nonlocal region (a volume constraint against a boundary value).
     */
    double boundary_layer = 0;
    /** The energy norm of the composite field, the scale of `relative`. */
    double norm = 0;
    /** The diagonal of the nonlocal operator at an uncut interior point. */
    double chi = 0;
    /** The largest eigenvalue of the operator over its diagonal. */
    double c_G = 0;
    /** The number of lattice points the residual is evaluated at. */
    types::global_dof_index n_points = 0;
    /**
     * With `Postprocess/True model error`: `||u_* - w||_{A_*}` against the
     * nonlocal model solved on the whole body, relative as `relative` is,
     * and `estimate / true_error`.
     */
    bool   has_true_error = false;
    double true_error     = 0;
    double true_relative  = 0;
    double effectivity    = 0;
    /**
     * With `Postprocess/True model error` and `Geometry/Nonlocal regions =
     * auto`: the region's own modeling error, `||w - w_max||_{A_*}` against
     * the composite field of the coupled solution on the largest admissible
     * region (the same boundary strip and local model along the faces),
     * relative as `relative` is, and `estimate / region_error`.
     */
    bool   has_region_error   = false;
    double region_error       = 0;
    double region_relative    = 0;
    double region_effectivity = 0;
    /** The largest contribution of one point, and where it lies. */
    double              largest = 0;
    std::vector<double> largest_at;
  };

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
    /** The solvers' statistics, as the solve reported them. */
    SolverStatistics solver;
    /** The Collar layer weight the Control preconditioner used. */
    double collar_layer_weight = 0;
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
    JsonValue        extras;
    ModelErrorRecord model_error;
    /** Wall time per phase, seconds, in the order the phases ran. */
    std::vector<std::pair<std::string, double>> timings;
  };

  /**
   * One cycle of `Geometry/Nonlocal regions = auto`: the region it solved
   * on, its estimate, and what it decided.
   */
  struct ModelCycleRecord
  {
    unsigned int cycle = 0;
    /** Its (last) solve's entry in RunSummary::levels. */
    unsigned int level_entry = 0;
    /** The boxes of the region, lower corner then upper corner each. */
    std::vector<std::vector<double>> boxes;
    unsigned int                     blocks    = 0;
    types::global_dof_index          particles = 0;
    /** The estimate relative to the composite field's energy norm. */
    double estimate          = 0;
    double estimate_absolute = 0;
    /** The part of the estimate from blocks already in the region. */
    double estimate_coupling = 0;
    /** Blocks marked, and blocks added with the closure. */
    unsigned int marked = 0, added = 0;
    /** Why the loop stopped after this cycle; empty if it went on. */
    std::string stopped;
  };

  /** The loop of `Geometry/Nonlocal regions = auto`, if the scene runs it. */
  struct ModelAdaptivityRecord
  {
    bool                          enabled    = false;
    double                        tolerance  = 0;
    double                        block_size = 0;
    std::vector<ModelCycleRecord> cycles;
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
    ModelAdaptivityRecord    model_adaptivity;
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

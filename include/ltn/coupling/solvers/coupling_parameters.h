#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ltn/base/selection.h>
#include <ltn/coupling/preconditioners/control_preconditioner.h>
#include <ltn/coupling/system/coupling_system.h>
#include <ltn/model_solvers/model_solver.h>

#include <optional>
#include <string>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** How the optimality system is solved (`Coupling/Method`). */
  enum class CouplingMethod
  {
    /** Chosen per level by choose_solvers() (scene/solver_choice.h). */
    automatic,
    /** States, controls and multipliers in one factorized system. */
    full_space_direct,
    /** The same system unassembled: flexible GMRES, block elimination. */
    full_space_gmres,
    /** CG on the controls, each model solved by its own solver. */
    reduced_space_cg,
    /**
     * A baseline, not LtN's optimization: alternating Schwarz, each model
     * taking the other's trace as its controls, in turn
     * (doc/baseline_couplings.md).
     */
    alternating_schwarz,
    /** The same with Aitken's dynamic relaxation of the local controls. */
    alternating_schwarz_aitken,
    /**
     * A baseline: force-based blending, one field, each node's equation
     * the models' rows weighted by the blending function (1D).
     */
    force_blending,
    /**
     * A baseline: energy-based (Arlequin-type) blending, one field
     * minimizing the sum of the models' energies weighted by the blending
     * function and its complement (1D).
     */
    energy_blending
  };

  /** The names of the methods in `Coupling/Method`. */
  const SelectionNames<CouplingMethod> &
  coupling_method_names();

  /**
   * How the optimality system is solved (subsection `Coupling`), and its
   * optional Tikhonov regularization.
   */
  struct CouplingParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Is the method a blending (force or energy)? */
    bool
    blending() const;

    /**
     * An InputError if the method does not exist for the physics: the
     * blendings couple nonlocal diffusion with the Laplacian only.
     */
    void
    check_physics(const bool diffusion) const;

    /**
     * These parameters at a level of an LPS scene whose overlap is
     * @p overlap_over_horizon horizons wide: an `auto` Collar layer weight
     * resolved there (lps_collar_layer_weight()), where the Control
     * preconditioner weights the nonlocal controls' diagonal, and, where
     * `Crack opening coarse fields` asks for them in @p dim dimensions and
     * there is a coarse level, @p crack_fields (the scene's cracks' opening
     * fields) added to its nonlocal columns.
     */
    CouplingParameters
    at_lps_level(const double                           overlap_over_horizon,
                 const std::vector<AffineProductField> &crack_fields = {},
                 const unsigned int                     dim          = 2) const;

    /**
     * Check that the selected solvers can work with a nonlocal model stored
     * matrix-free (@p matrix_free), coupled to a local one or alone
     * (@p coupled); an InputError names the parameter.
     */
    void
    check_operator(const bool matrix_free, const bool coupled) const;

    CouplingMethod      method = CouplingMethod::full_space_direct;
    ModelSolverSettings model_solvers;
    double              tikhonov_parameter = 0;
    double              relative_tolerance = 1e-12;
    unsigned int        max_iterations     = 1000;
    /** Reduced-space CG: time each model's solve alone afterwards. */
    bool time_standalone_solves = false;
    /** The preconditioner of the reduced Hessian (ControlPreconditioner). */
    ControlPreconditionerSettings controls;
    /**
     * `Collar layer weight = auto`: `controls.collar_layer_weight` is 0
     * until at_lps_level() sets it.
     */
    bool automatic_collar_layer_weight = true;
    /**
     * `Crack opening coarse fields` (empty: `auto`, in 2D only):
     * at_lps_level() adds the fields.
     */
    std::optional<bool> crack_opening_coarse_fields;
  };

  /**
   * The Collar layer weight `auto` gives LPS with an overlap
   * @p overlap_over_horizon horizons wide (doc/discretization.md, section
   * 19): 1.5 log2(w / (8 eps)) above 8, else 0.
   */
  double
  lps_collar_layer_weight(const double overlap_over_horizon);
} // namespace ltn

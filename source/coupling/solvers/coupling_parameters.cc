#include <ltn/base/input_error.h>
#include <ltn/coupling/solvers/coupling_parameters.h>

#include <cmath>
#include <string>

namespace ltn
{
  const SelectionNames<CouplingMethod> &
  coupling_method_names()
  {
    static const SelectionNames<CouplingMethod> names = {
      {CouplingMethod::automatic, "auto"},
      {CouplingMethod::full_space_direct, "full space direct"},
      {CouplingMethod::full_space_gmres, "full space gmres"},
      {CouplingMethod::reduced_space_cg, "reduced space cg"},
      {CouplingMethod::alternating_schwarz, "alternating schwarz"},
      {CouplingMethod::alternating_schwarz_aitken,
       "alternating schwarz aitken"},
      {CouplingMethod::force_blending, "force blending"},
      {CouplingMethod::energy_blending, "energy blending"}};
    return names;
  }



  void
  CouplingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Coupling");
    {
      prm.declare_entry(
        "Method",
        "auto",
        selection_pattern(coupling_method_names()),
        "How to solve the optimality system: `full space "
        "direct` (states, controls and multipliers in one "
        "saddle-point system, sparse direct solver), `full "
        "space gmres` (the same system unassembled, flexible "
        "GMRES preconditioned by block elimination with "
        "each model's solver, two forward and two adjoint "
        "solves per model and iteration; set a loose Model "
        "solver tolerance such as 1e-3) or `reduced space "
        "cg` (CG on the controls; each iteration one forward "
        "and one adjoint solve per model), or `auto`: reduced space cg "
        "where the particle model is solved iteratively "
        "(Model solvers `auto` from 50,000 particle unknowns "
        "or 2.5e7 unknowns times bonds on, or named), where its operator is matrix-free, "
        "or with Time standalone solves; full space direct "
        "otherwise (doc/prm_guide.md, 'Large scenes'). Baselines, "
        "not LtN's optimization: `alternating schwarz` (each model "
        "takes the other's trace as its controls, in turn, until the "
        "mismatch at the local model's controls falls by the Relative "
        "tolerance) and `alternating schwarz aitken` (the same with "
        "Aitken's relaxation), `force blending` (1D: one field, "
        "each node's equation the nonlocal and the local row weighted "
        "by a blending function that falls from 1 to 0 across the "
        "overlap) and `energy blending` (1D: one field minimizing the "
        "nonlocal energy weighted by the blending function plus the "
        "local one weighted by its complement; every body face "
        "Dirichlet); doc/baseline_couplings.md.");
      prm.declare_entry("Tikhonov parameter",
                        "0",
                        Patterns::Double(0),
                        "alpha >= 0 of the regularization alpha/2 |theta|^2 "
                        "of the controls (Euclidean norm of their values).");
      prm.declare_entry("Relative tolerance",
                        "1e-12",
                        Patterns::Double(0),
                        "Reduction of the residual at which the reduced-space "
                        "CG (its recursive residual; its relaxed inner solves "
                        "let the true one, reported as `solver.true "
                        "residual` in summary.json, lie a few times above it) "
                        "or the full-space GMRES stops.");
      prm.declare_entry("Maximum iterations",
                        "1000",
                        Patterns::Integer(1),
                        "Iteration limit of the reduced-space CG, the "
                        "full-space GMRES and each model solve.");
      prm.declare_entry("Control preconditioner",
                        "two level",
                        Patterns::Selection("two level|block diagonal|none"),
                        "Preconditioner of the reduced Hessian, in the "
                        "reduced-space CG and inside the full-space GMRES's "
                        "preconditioner: `block diagonal` (the exact Hessian "
                        "block of the local controls, built with one forward "
                        "local solve per local control, and "
                        "the observation weights of the nonlocal controls; "
                        "keeps the iterations nearly independent of h), `two "
                        "level` (in the reduced-space CG: deflation by the "
                        "nonlocal controls' polynomial fields and by every "
                        "local control, one forward solve of its model per "
                        "column, once; it takes the coupling of the two "
                        "models' controls exactly and removes the slow modes "
                        "they share across the overlap; in the full-space "
                        "GMRES: the block-diagonal level balanced by the "
                        "polynomial fields of both models) or `none` "
                        "(reduced-space CG only).");
      prm.declare_entry("Coarse space degree",
                        "1",
                        Patterns::Integer(0, 4),
                        "Total degree of the polynomials, per model and per "
                        "field component, spanning the coarse level of the "
                        "`two level` control preconditioner (3D elasticity: "
                        "12 nonlocal modes at degree 1, 30 at degree 2, and "
                        "in the full-space GMRES as many local ones).");
      prm.declare_entry(
        "Nonlocal control block",
        "diagonal",
        Patterns::Selection("diagonal|surrogate extension"),
        "The nonlocal controls' block of the Control preconditioner: "
        "`diagonal` (each control particle's observation weight; the "
        "outer iterations then grow with the overlap's width over the "
        "horizon) or `surrogate extension` (also the field the collar "
        "drives into the nonlocal region, modelled with the particle "
        "lattice's nearest-neighbour Laplacian; its sparse saddle-point "
        "form, about three times the particles, is factorized once and "
        "costs one pair of triangular solves per application; needs a "
        "particle model, 2D or 3D; its factorization grows faster than "
        "the particles, so in 3D it suits small lattices only, and "
        "`diagonal` the large ones; measurements in "
        "benchmarks/scaling/HISTORY.md).");
      prm.declare_entry(
        "Collar layer weight",
        "auto",
        Patterns::Anything(),
        "s >= 0, or `auto`: with Nonlocal control block = diagonal, each "
        "nonlocal control's weight in the Control preconditioner is "
        "multiplied by 1 + s c/c_max, c how strongly its particle's bonds "
        "reach into the nonlocal region (the particle lattice's surrogate; "
        "2D and 3D). The outer iterations' largest eigenvalue grows with "
        "the overlap width w over the horizon eps and lives on that layer. "
        "`auto`: for LPS with w/eps > 8, 1.5 log2(w/(8 eps)) at each level "
        "(3 at w/eps = 32), which takes the outer iterations down where "
        "the overlap is wide; else 0, as for nonlocal diffusion, where it "
        "costs iterations (doc/discretization.md, 'A coarse level for the "
        "controls'; measurements in benchmarks/speed_accuracy/HISTORY.md). "
        "The weight used goes to "
        "`solver.control "
        "preconditioner` in summary.json.");
      prm.declare_entry(
        "Crack opening coarse fields",
        "auto",
        Patterns::Selection("auto|true|false"),
        "Elasticity with `two level` in the reduced-space CG: add to the "
        "coarse level, per crack, the nonlocal controls' displacement n "
        "(n.x)(t.x)^2 about the crack's centre, n its normal and t each "
        "direction along it: an opening that varies along the crack, "
        "the slowest mode the polynomial fields leave in 2D "
        "(doc/discretization.md, 'A coarse level for the controls'). One "
        "nonlocal solve per field, once, for fewer outer iterations where "
        "that mode is slow. `auto`: in 2D only (the 3D bars have no such "
        "slow mode, and the extra solves cost more than they save; "
        "measurements in benchmarks/speed_accuracy/HISTORY.md and "
        "benchmarks/scaling/HISTORY.md). A "
        "field the polynomial columns span already (Coarse space degree 3 "
        "and more) is dropped. The number kept goes to `solver.control "
        "preconditioner` in summary.json.");
      prm.declare_entry(
        "Time standalone solves",
        "false",
        Patterns::Bool(),
        "Reduced-space CG only: after the coupled solve, solve each model "
        "once more alone, from zero, with its data and the final controls, "
        "and report the model solvers' setup and these solves as "
        "`standalone model solves seconds` in summary.json: what solving "
        "the two models alone costs with the same solvers and tolerances, "
        "the reference of benchmarks/scaling. The extra solves count in "
        "the solve's wall time.");
      prm.declare_entry(
        "Model solvers",
        "auto",
        selection_pattern(model_solver_names()),
        "How each model's equations are solved, inside the "
        "reduced-space CG or alone: `direct` (sparse LU of "
        "the assembled matrix), `preconditioned gmres` "
        "(GMRES with algebraic multigrid on the finite "
        "element matrix, or on the nonlocal model's "
        "nearest-neighbour surrogate after eliminating the "
        "dilatation; works matrix-free) or `preconditioned "
        "cg` (the same, but CG on the particle model's free "
        "unknowns, whose block is symmetric positive "
        "definite, for forward and adjoint solves alike; "
        "the finite element model keeps GMRES), or `auto`: "
        "preconditioned cg with the finite element model "
        "factorized from 50,000 particle unknowns or 2.5e7 "
        "unknowns times bonds on (2D, 3D) or with a matrix-free operator, unless the "
        "Method is full space direct; direct otherwise.");
      prm.declare_entry("Local model solver",
                        "same",
                        Patterns::Selection("same|direct"),
                        "`same`: the finite element model is solved as "
                        "Model solvers says; `direct`: it is factorized "
                        "(MUMPS) whatever the particle model's solver. A "
                        "coupled solve needs one local solve per local "
                        "control of the coarse level and two per CG "
                        "iteration; on a coarse mesh a factorization makes "
                        "them cheap.");
      prm.declare_entry("Model solver tolerance",
                        "1e-13",
                        Patterns::Double(0),
                        "Residual reduction, relative to the right-hand "
                        "side of its free block, at which a model's "
                        "GMRES or CG stops. Inside "
                        "the reduced-space CG this is the tolerance of its "
                        "first iteration, relaxed as the CG's residual falls "
                        "(at most to 1e-1): keep it about 1e-2 times the "
                        "Relative tolerance; with the two-level Control "
                        "preconditioner it is at most that. Inside the "
                        "full-space GMRES's "
                        "preconditioner it may be loose (1e-1 to 1e-3).");
    }
    prm.leave_subsection();
  }



  void
  CouplingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Coupling");
    {
      method = parse_selection(coupling_method_names(), prm.get("Method"));
      tikhonov_parameter     = prm.get_double("Tikhonov parameter");
      relative_tolerance     = prm.get_double("Relative tolerance");
      max_iterations         = prm.get_integer("Maximum iterations");
      time_standalone_solves = prm.get_bool("Time standalone solves");
      const std::string control_preconditioner =
        prm.get("Control preconditioner");
      controls.enabled = control_preconditioner != "none";
      controls.coarse_degree =
        control_preconditioner == "two level" ?
          std::optional<unsigned int>(prm.get_integer("Coarse space degree")) :
          std::nullopt;
      controls.surrogate_nonlocal_block =
        prm.get("Nonlocal control block") == "surrogate extension";
      const std::string crack_fields = prm.get("Crack opening coarse fields");
      crack_opening_coarse_fields =
        crack_fields == "auto" ? std::nullopt :
                                 std::optional<bool>(crack_fields == "true");
      const std::string weight      = prm.get("Collar layer weight");
      automatic_collar_layer_weight = weight == "auto";
      controls.collar_layer_weight  = 0;
      if (!automatic_collar_layer_weight)
        {
          std::size_t parsed = 0;
          try
            {
              controls.collar_layer_weight = std::stod(weight, &parsed);
            }
          catch (const std::exception &)
            {
              parsed = 0;
            }
          check_input(parsed > 0 &&
                        weight.find_first_not_of(" \t", parsed) ==
                          std::string::npos &&
                        controls.collar_layer_weight >= 0,
                      "Coupling/Collar layer weight",
                      weight,
                      "`auto` or a number s >= 0");
        }
      check_input(controls.collar_layer_weight == 0 ||
                    (control_preconditioner != "none" &&
                     !controls.surrogate_nonlocal_block),
                  "Coupling/Collar layer weight",
                  weight,
                  "0 or `auto` unless Coupling/Control preconditioner is "
                  "`two level` or `block diagonal` with Nonlocal control "
                  "block = diagonal (it weights that diagonal)");
      check_input(control_preconditioner != "none" ||
                    !controls.surrogate_nonlocal_block,
                  "Coupling/Nonlocal control block",
                  prm.get("Nonlocal control block"),
                  "`diagonal` with Coupling/Control preconditioner = none");
      check_input(control_preconditioner != "none" ||
                    method != CouplingMethod::full_space_gmres,
                  "Coupling/Control preconditioner",
                  control_preconditioner,
                  "`two level` or `block diagonal` with Coupling/Method = "
                  "full space gmres (its preconditioner eliminates the "
                  "controls with it)");
      model_solvers.kind =
        parse_selection(model_solver_names(), prm.get("Model solvers"));
      model_solvers.relative_tolerance =
        prm.get_double("Model solver tolerance");
      model_solvers.direct_local_model =
        prm.get("Local model solver") == "direct";
      model_solvers.max_iterations = max_iterations;
      check_input(model_solvers.relative_tolerance > 0 &&
                    model_solvers.relative_tolerance < 1,
                  "Coupling/Model solver tolerance",
                  to_string(model_solvers.relative_tolerance),
                  "a tolerance in (0, 1)");
      check_input(!time_standalone_solves ||
                    method == CouplingMethod::reduced_space_cg ||
                    method == CouplingMethod::automatic,
                  "Coupling/Time standalone solves",
                  "true",
                  "`false` unless Coupling/Method = reduced space cg (the "
                  "only method that solves each model with its own solver)");
      check_input(relative_tolerance > 0 && relative_tolerance < 1,
                  "Coupling/Relative tolerance",
                  to_string(relative_tolerance),
                  "a tolerance in (0, 1)");
    }
    prm.leave_subsection();
  }



  bool
  CouplingParameters::blending() const
  {
    return method == CouplingMethod::force_blending ||
           method == CouplingMethod::energy_blending;
  }



  void
  CouplingParameters::check_physics(const bool diffusion) const
  {
    check_input(diffusion || !blending(),
                "Coupling/Method",
                selection_name(coupling_method_names(), method),
                "a method of elasticity scenes: the blendings couple "
                "nonlocal diffusion with the Laplacian only");
  }



  void
  CouplingParameters::check_operator(const bool matrix_free,
                                     const bool coupled) const
  {
    if (!matrix_free)
      return;
    check_input(model_solvers.kind != ModelSolverKind::direct,
                "Coupling/Model solvers",
                "direct",
                "`preconditioned gmres` or `preconditioned cg` with "
                "Nonlocal model/Operator = matrix-free (a direct solver "
                "needs the assembled matrix)");
    check_input(!coupled || method != CouplingMethod::full_space_direct,
                "Coupling/Method",
                selection_name(coupling_method_names(), method),
                "`reduced space cg` or `full space gmres` with Nonlocal "
                "model/Operator = matrix-free (the full-space direct solver "
                "needs the assembled matrix)");
  }



  double
  lps_collar_layer_weight(const double overlap_over_horizon)
  {
    return overlap_over_horizon > 8 ?
             1.5 * std::log2(overlap_over_horizon / 8) :
             0;
  }



  CouplingParameters
  CouplingParameters::at_lps_level(
    const double                           overlap_over_horizon,
    const std::vector<AffineProductField> &crack_fields,
    const unsigned int                     dim) const
  {
    CouplingParameters level = *this;
    if (automatic_collar_layer_weight && controls.enabled &&
        !controls.surrogate_nonlocal_block)
      level.controls.collar_layer_weight =
        lps_collar_layer_weight(overlap_over_horizon);
    if (controls.coarse_degree &&
        crack_opening_coarse_fields.value_or(dim == 2))
      level.controls.nonlocal_coarse_fields = crack_fields;
    return level;
  }
} // namespace ltn

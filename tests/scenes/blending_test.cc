// The force-based blending baseline in 1D (doc/baseline_couplings.md):
// patch tests pass by construction, its matrix is not symmetric (what the
// literature reports), and on a smooth solution it converges like LtN.

#include <catch2/catch.hpp>

#include "scene_run.h"

namespace
{
  /** The 1D patch scene made quadratic: FE_Q(2) on both sides, u = x^2. */
  const std::vector<std::string> quadratic_1d_patch = {
    "Nonlocal model/Finite element degree=2",
    "Local model/Finite element degree=2",
    "Diffusion data/Exact solution=x^2",
    "Diffusion data/Nonlocal right-hand side=-2",
    "Diffusion data/Local right-hand side=-2",
    "Discretization/Number of levels=2"};
} // namespace



TEST_CASE("force blending in 1D: patch tests to round-off, a matrix that is "
          "not symmetric",
          "[blending][patch]")
{
  for (const auto &[sets, max_u] :
       {std::pair{std::vector<std::string>{"Discretization/Number of levels=2"},
                  1.75},
        std::pair{quadratic_1d_patch, 1.75 * 1.75}})
    {
      auto with_method = sets;
      with_method.push_back("Coupling/Method=force blending");
      const SceneRun run = run_scene("diffusion_1d_patch", with_method);
      for (const auto &level : run.summary.levels)
        {
          INFO("h " << level.h << ": asymmetry " << level.solver.asymmetry);
          REQUIRE(level.has_errors);
          CHECK(level.coupled_errors.linf <= 1e-10 * max_u);
          CHECK(level.solver.residual <= 1e-12);
          // |K - K^T|_F / |K|_F: 0.175 (P1) and 0.125 (P2) at h = 1/16,
          // from the rows across the overlap band, where beta changes.
          CHECK(level.solver.asymmetry > 0.01);
        }
    }
}



TEST_CASE("force blending in 1D converges like LtN on a smooth solution",
          "[blending]")
{
  const SceneRun ltn = run_scene("diffusion_1d_convergence");
  const SceneRun run =
    run_scene("diffusion_1d_convergence", {"Coupling/Method=force blending"});
  check_coupled_rates(run.summary, 1.95, 1.95);
  check_errors_near(run.summary, ltn.summary, 0.05);
}

// The blending baselines in 1D (doc/baseline_couplings.md). Force-based:
// patch tests pass by construction, its matrix is not symmetric (what the
// literature reports), and on a smooth solution it converges like LtN.
// Energy-based: a symmetric matrix whose linear patch test carries the ghost
// forces the derivation predicts, at their order.

#include <catch2/catch.hpp>

#include <cmath>

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



namespace
{
  /**
   * The 1D patch scene (u = x, Omega_n = (0, 1) on the body (0, 1.75), one
   * interior face at x = 1) with energy blending, the constant kernel's
   * horizon eps = 2h, the overlap width @p overlap and @p sets.
   */
  SceneRun
  energy_blending_patch(const double                    overlap,
                        const std::vector<std::string> &sets)
  {
    std::vector<std::string> all = {"Coupling/Method=energy blending",
                                    "Nonlocal model/Horizon=0",
                                    "Nonlocal model/Horizon to mesh size "
                                    "ratio=2",
                                    "Geometry/Overlap width=" +
                                      std::to_string(overlap)};
    all.insert(all.end(), sets.begin(), sets.end());
    return run_scene("diffusion_1d_patch", all);
  }

  /**
   * The ghost-force error of energy blending on u = x that
   * doc/baseline_couplings.md ('Energy-based blending') derives: the
   * dipoles at the kinks of beta leave about g M_4 / (6 delta) inside the
   * band, M_4 = 3/5 eps^2 for the constant kernel, g = 1.
   */
  double
  predicted_ghost_error(const double eps, const double delta)
  {
    return 0.6 * eps * eps / (6 * delta);
  }
} // namespace



TEST_CASE("energy blending in 1D: a symmetric matrix, and the ghost forces "
          "of the linear patch test at the derived level",
          "[blending][patch]")
{
  // Fixed delta = 1/4: second order, as eps = 2h shrinks.
  const SceneRun fixed =
    energy_blending_patch(0.25, {"Discretization/Number of levels=3"});
  const auto &levels = fixed.summary.levels;
  REQUIRE(levels.size() == 3);
  for (const auto &level : levels)
    {
      const double predicted = predicted_ghost_error(2 * level.h, 0.25);
      INFO("h " << level.h << ": max error " << level.coupled_errors.linf
                << ", predicted " << predicted << ", asymmetry "
                << level.solver.asymmetry);
      REQUIRE(level.has_errors);
      CHECK(level.solver.asymmetry < 1e-14);
      CHECK(level.solver.residual < 1e-12);
      // Far above round-off: energy blending fails the patch test.
      CHECK(level.coupled_errors.linf > 1e-4);
      CHECK(level.coupled_errors.linf > 0.5 * predicted);
      CHECK(level.coupled_errors.linf < 2 * predicted);
    }
  for (std::size_t l = 1; l < levels.size(); ++l)
    {
      const double rate = std::log2(levels[l - 1].coupled_errors.linf /
                                    levels[l].coupled_errors.linf);
      INFO("rate " << rate);
      CHECK(std::abs(rate - 2) < 0.2);
    }

  // delta = h: first order, one level per mesh size.
  std::vector<double> errors;
  for (const double h : {1. / 16, 1. / 32, 1. / 64})
    {
      const SceneRun run       = energy_blending_patch(h,
                                                       {"Discretization/Mesh size=" +
                                                        std::to_string(h)});
      const double   linf      = run.summary.levels[0].coupled_errors.linf;
      const double   predicted = predicted_ghost_error(2 * h, h);
      INFO("delta = h = " << h << ": max error " << linf << ", predicted "
                          << predicted);
      CHECK(linf > 0.5 * predicted);
      CHECK(linf < 2 * predicted);
      errors.push_back(linf);
    }
  for (std::size_t l = 1; l < errors.size(); ++l)
    {
      const double rate = std::log2(errors[l - 1] / errors[l]);
      INFO("rate " << rate);
      CHECK(std::abs(rate - 1) < 0.2);
    }
}



TEST_CASE("energy blending in 1D: the field is constant where the data are "
          "constant",
          "[blending][patch]")
{
  // u = 1: every form annihilates constants, so no ghost force; the one
  // known answer that energy blending must reproduce to round-off.
  const SceneRun run =
    energy_blending_patch(0.25,
                          {"Diffusion data/Exact solution=1",
                           "Discretization/Number of levels=2"});
  for (const auto &level : run.summary.levels)
    {
      INFO("h " << level.h);
      CHECK(level.coupled_errors.linf < 1e-12);
    }
}



TEST_CASE("blending on the 2D particle lattice: force blending passes the "
          "patch tests, energy blending carries ghost forces",
          "[blending][patch][particles]")
{
  // One field on the particles of the whole body, the nonlocal rows blended
  // with the 5-point Laplacian (doc/baseline_couplings.md, 'Blending').
  const std::vector<std::string> quadratic = {
    "Diffusion data/Exact solution=x^2 + x*y - 0.5*y^2 + x",
    "Diffusion data/Nonlocal right-hand side=-1",
    "Diffusion data/Local right-hand side=-1"};
  for (const auto &[sets, max_u] :
       {std::pair{std::vector<std::string>{}, 4.}, std::pair{quadratic, 7.5}})
    {
      auto force = sets;
      force.push_back("Coupling/Method=force blending");
      const SceneRun run   = run_scene("diffusion_2d_patch", force);
      const auto    &level = run.summary.levels.back();
      INFO("force blending: max error " << level.coupled_errors.linf);
      REQUIRE(level.has_errors);
      // Each row a convex combination of two consistent operators.
      CHECK(level.coupled_errors.linf <= 1e-10 * max_u);
    }

  auto energy = std::vector<std::string>{"Coupling/Method=energy blending"};
  const SceneRun run   = run_scene("diffusion_2d_patch", energy);
  const auto    &level = run.summary.levels.back();
  INFO("energy blending: max error " << level.coupled_errors.linf);
  REQUIRE(level.has_errors);
  // The ghost forces where beta bends, far above round-off: 6.3e-3 (u = x +
  // 2y, eps = 3h = 0.1875, delta = 0.25), concentrated in the band.
  CHECK(level.coupled_errors.linf > 1e-3);
  CHECK(level.coupled_errors.linf < 3e-2);
}

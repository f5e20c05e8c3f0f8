// Convergence of the 1D coupling for u = sin(k x): second order at fixed
// horizon against the exact solution of both models, and, with eps = m h,
// convergence of the coupled solution to the local solution.

#include <catch2/catch.hpp>

#include <cmath>

#include "scene_run.h"

namespace
{
  void
  check_rates(const ltn::RunSummary &summary,
              const double           min_rate,
              const double           max_coarse_l2)
  {
    const auto &levels = summary.levels;
    REQUIRE(levels.size() >= 5);
    CHECK(levels.front().coupled_errors.l2() < max_coarse_l2);
    check_coupled_rates(summary, min_rate, min_rate);
    // The nonlocal part alone is pre-asymptotic on coarse levels for the
    // fractional kernels (rates 1.78, 1.89, 1.95, 1.97, 1.99 for s = 0.5):
    // require the rate where it has settled, on the finest refinement.
    const auto &c = levels[levels.size() - 2], &f = levels.back();
    CHECK(ltn::observed_rate(c.nonlocal_errors.l2(),
                             f.nonlocal_errors.l2(),
                             c.h,
                             f.h) >= min_rate);
  }
} // namespace



TEST_CASE("second order at fixed horizon for every kernel", "[convergence]")
{
  for (const std::string kernel :
       {"constant", "inverse distance", "fractional"})
    for (const std::string method : {"full space direct", "reduced space cg"})
      {
        INFO(kernel << ", " << method);
        const SceneRun run = run_scene("diffusion_1d_convergence",
                                       {"Nonlocal model/Kernel=" + kernel,
                                        "Coupling/Method=" + method});
        check_rates(run.summary, 1.9, 5e-3);
      }
}



TEST_CASE("fractional kernels of several orders converge", "[convergence]")
{
  for (const double s : {0.1, 0.5, 0.9})
    {
      INFO("s = " << s);
      const SceneRun run =
        run_scene("diffusion_1d_convergence",
                  {"Nonlocal model/Kernel=fractional",
                   "Nonlocal model/Fractional order=" + std::to_string(s)});
      check_rates(run.summary, 1.9, 5e-3);
    }
}



TEST_CASE("asymptotic compatibility with eps = m h converges to the local "
          "solution",
          "[convergence]")
{
  // f_n = f_l = -u'': the nonlocal model alone differs from u by O(eps^2),
  // so with eps = m h the coupled error against u is O(h^2).
  for (const std::string kernel : {"constant", "inverse distance"})
    for (const std::string m : {"1", "2", "3.5"})
      {
        INFO(kernel << ", m = " << m);
        const SceneRun run =
          run_scene("diffusion_1d_asymptotic_compatibility",
                    {"Nonlocal model/Kernel=" + kernel,
                     "Nonlocal model/Horizon to mesh size ratio=" + m});
        // The coarse error is mostly the model error O(eps^2) = O(m^2 h^2).
        check_rates(run.summary, 1.9, 6e-3 * std::pow(std::stod(m), 2));
      }
}

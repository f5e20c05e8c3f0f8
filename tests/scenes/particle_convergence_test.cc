// Convergence of the particle-FEM coupling in 2D and 3D for smooth
// non-polynomial solutions (sums of plane waves, with -L u computed exactly
// from the kernel's symbol).

#include <catch2/catch.hpp>

#include "scene_run.h"

TEST_CASE("2D second order at fixed horizon against the nonlocal solution",
          "[particles][convergence]")
{
  const SceneRun run = run_scene("diffusion_2d_convergence");
  REQUIRE(run.summary.levels.size() == 3);
  CHECK(run.summary.levels.front().coupled_errors.l2() < 5e-3);
  check_coupled_rates(run.summary, 1.9, 1.9);
}



TEST_CASE("2D second order on a nonlocal region made of boxes",
          "[particles][convergence]")
{
  // An L-shape: its concave corner and the face where its boxes touch.
  const SceneRun run =
    run_scene("diffusion_2d_convergence",
              {"Geometry/Nonlocal regions=0,0,0.5,1; 0.5,0,1,0.5"});
  check_coupled_rates(run.summary, 1.9, 1.9);
}



TEST_CASE("2D asymptotic compatibility with eps = m h",
          "[particles][convergence]")
{
  for (const std::string m : {"2.5", "3"})
    {
      INFO("m = " << m);
      const SceneRun run =
        run_scene("diffusion_2d_asymptotic_compatibility",
                  {"Nonlocal model/Horizon to mesh size ratio=" + m});
      REQUIRE(run.summary.levels.size() == 3);
      check_coupled_rates(run.summary, 1.9, 1.9);
    }
}



TEST_CASE("3D asymptotic compatibility with eps = 2 h",
          "[particles][convergence]")
{
  const SceneRun run = run_scene("diffusion_3d_convergence",
                                 {"Nonlocal model/Horizon to mesh size ratio=2",
                                  "Diffusion data/Nonlocal right-hand side="
                                  "3*pi^2*sin(pi*x)*cos(pi*y)*cos(pi*z)",
                                  "Discretization/Mesh size=0.25",
                                  "Discretization/Number of levels=3"});
  // Observed: L2 rates 2.36 and 2.13, max rates 1.63 and 1.89; the max
  // error on h = 1/4 is not yet asymptotic.
  check_coupled_rates(run.summary, 1.9, 1.6);
}

// The same body solved by one model alone, through the same executable and
// .prm: the references a coupled result is compared with.

#include <ltn/base/input_error.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "scene_run.h"

TEST_CASE("all-local and all-nonlocal solves of the coupled scenes", "[pure]")
{
  for (const std::string scene :
       {"diffusion_1d_convergence", "diffusion_2d_convergence"})
    {
      const std::vector<std::string> two_levels = {
        "Discretization/Number of levels=2"};
      auto local_only = two_levels, nonlocal_only = two_levels;
      local_only.push_back("Geometry/Models=local only");
      nonlocal_only.push_back("Geometry/Models=nonlocal only");
      const SceneRun coupled  = run_scene(scene, two_levels);
      const SceneRun local    = run_scene(scene, local_only);
      const SceneRun nonlocal = run_scene(scene, nonlocal_only);
      for (std::size_t l = 0; l < 2; ++l)
        {
          INFO(scene << " level " << l);
          const auto &c = coupled.summary.levels[l];
          const auto &a = local.summary.levels[l];
          const auto &n = nonlocal.summary.levels[l];
          // One model each, no controls, no missing model's errors.
          CHECK(a.n_nonlocal_dofs == 0);
          CHECK(a.n_controls == 0);
          CHECK(std::isnan(a.nonlocal_errors.l2()));
          CHECK(n.n_local_dofs == 0);
          CHECK(n.n_controls == 0);
          CHECK(std::isnan(n.local_errors.l2()));
          // Each solves its model exactly up to discretization: errors of
          // the size of the coupled one's or smaller (the particle
          // discretization is far more accurate than P1).
          CHECK(a.coupled_errors.l2() < 2 * c.coupled_errors.l2());
          CHECK(n.coupled_errors.l2() < 2 * c.coupled_errors.l2());
          CHECK(a.coupled_errors.l2() > 0);
          CHECK(n.coupled_errors.l2() > 0);
        }
      // The all-local solve converges at second order like the coupled one.
      const auto &a0 = local.summary.levels[0], &a1 = local.summary.levels[1];
      CHECK(ltn::observed_rate(a0.coupled_errors.l2(),
                               a1.coupled_errors.l2(),
                               a0.h,
                               a1.h) >= 1.9);
    }
}



TEST_CASE("an all-nonlocal scene needs volume constraints on every face",
          "[pure]")
{
  CHECK_THROWS_AS(run_scene("diffusion_2d_patch",
                            {"Geometry/Models=nonlocal only",
                             "Local model/Dirichlet boundaries=x-, y-, y+"}),
                  ltn::InputError);
}

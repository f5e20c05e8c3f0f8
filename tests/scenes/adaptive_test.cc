// Kelly-adaptive refinement of the local mesh: hanging nodes keep the patch
// test exact with both solver methods, and each cycle reduces the error.

#include <catch2/catch.hpp>

#include "scene_run.h"

TEST_CASE("patch tests on adaptively refined local meshes", "[adaptive]")
{
  // u = x + 2y + xy is harmonic and in Q1: reproduced on meshes with
  // hanging nodes in 2D; in 1D refinement adds no hanging nodes.
  const std::vector<std::pair<std::string, std::vector<std::string>>> scenes = {
    {"diffusion_2d_patch",
     {"Local model/Adaptive refinement cycles=3",
      "Diffusion data/Exact solution=x + 2*y + x*y"}},
    {"diffusion_1d_patch", {"Local model/Adaptive refinement cycles=3"}}};
  for (const auto &[scene, sets] : scenes)
    {
      std::vector<ltn::CouplingSolution> solutions;
      for (const std::string method : {"full space direct", "reduced space cg"})
        {
          auto with_method = sets;
          with_method.push_back("Coupling/Method=" + method);
          const SceneRun run = run_scene(scene, with_method);
          REQUIRE(run.summary.levels.size() == 4);
          CHECK(run.summary.levels.back().n_local_dofs >
                run.summary.levels.front().n_local_dofs);
          for (const auto &cycle : run.summary.levels)
            {
              INFO(scene << ", " << method << ", cycle " << cycle.cycle
                         << ", local dofs " << cycle.n_local_dofs);
              CHECK(cycle.coupled_errors.linf / 4 <= 1e-10);
            }
          solutions.push_back(run.solutions.front());
        }
      // On an exact solution the Kelly indicators are round-off, so the two
      // methods refine different cells: compare them on the first mesh.
      CHECK(relative_difference(solutions[0], solutions[1]) <= 1e-8);
    }
}



TEST_CASE("adaptive cycles reduce the local error", "[adaptive]")
{
  const SceneRun run    = run_scene("diffusion_2d_convergence",
                                    {"Discretization/Number of levels=1",
                                     "Local model/Adaptive refinement cycles=3"});
  const auto    &levels = run.summary.levels;
  REQUIRE(levels.size() == 4);
  for (std::size_t c = 1; c < levels.size(); ++c)
    {
      INFO("cycle " << c << ": local dofs " << levels[c].n_local_dofs
                    << ", local L2 error " << levels[c].local_errors.l2());
      CHECK(levels[c].local_errors.l2() <
            0.95 * levels[c - 1].local_errors.l2());
      CHECK(levels[c].coupled_errors.l2() <
            0.95 * levels[c - 1].coupled_errors.l2());
    }
}

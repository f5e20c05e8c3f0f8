// The preconditioned reduced-space CG (doc/discretization.md, section 17):
// its iterations grow only slowly as h halves at fixed eps/h, while the
// unpreconditioned CG's grow about 2.5x per halving; both reach the same
// solution.

#include "scene_run.h"

TEST_CASE("reduced-space CG iterations at fixed eps/h over three halvings",
          "[solvers][scenes]")
{
  const std::vector<std::string> sets = {"Coupling/Method=reduced space cg",
                                         "Discretization/Number of levels=4",
                                         "Output/Write VTU=false"};
  std::vector<std::string>       unpreconditioned_sets = sets;
  unpreconditioned_sets.push_back("Coupling/Control preconditioner=none");
  const SceneRun preconditioned =
    run_scene("diffusion_2d_asymptotic_compatibility", sets);
  const SceneRun unpreconditioned =
    run_scene("diffusion_2d_asymptotic_compatibility", unpreconditioned_sets);

  const auto &levels = preconditioned.summary.levels;
  REQUIRE(levels.size() == 4);
  for (std::size_t l = 0; l < levels.size(); ++l)
    {
      const unsigned int with = levels[l].iterations;
      const unsigned int without =
        unpreconditioned.summary.levels[l].iterations;
      std::cout << "h = " << levels[l].h << ": " << with << " preconditioned, "
                << without << " unpreconditioned CG iterations" << std::endl;
      INFO("level " << l << ": " << with << " against " << without);
      CHECK(relative_difference(preconditioned.solutions[l],
                                unpreconditioned.solutions[l]) < 1e-8);
      if (l > 0)
        CHECK(with < 1.3 * levels[l - 1].iterations);
    }
  CHECK(10 * levels.back().iterations <
        unpreconditioned.summary.levels.back().iterations);
}

// The coupled system stays solvable, and the patch test holds, for a thin
// overlap and across horizon-to-mesh-size ratios.

#include <catch2/catch.hpp>

#include "scene_run.h"

namespace
{
  void
  check_linear_patch(const std::vector<std::string> &sets)
  {
    std::vector<ltn::CouplingSolution> solutions;
    for (const std::string method : {"full space direct", "reduced space cg"})
      {
        auto with_method = sets;
        with_method.push_back("Coupling/Method=" + std::string(method));
        const SceneRun run = run_scene("diffusion_1d_patch", with_method);
        for (const auto &level : run.summary.levels)
          {
            INFO(method << ": h " << level.h << " eps " << level.horizon
                        << " residual " << level.solver.residual);
            CHECK(level.coupled_errors.linf / 1.75 <= 1e-10);
          }
        solutions.push_back(run.solutions.back());
      }
    CHECK(relative_difference(solutions[0], solutions[1]) <= 1e-8);
  }
} // namespace



TEST_CASE("overlap only 2h wide", "[stability]")
{
  for (const std::string kernel : {"constant", "fractional"})
    {
      INFO(kernel);
      check_linear_patch({"Nonlocal model/Kernel=" + kernel,
                          "Geometry/Overlap width=0.125",
                          "Discretization/Mesh size=0.0625"});
      check_linear_patch({"Nonlocal model/Kernel=" + kernel,
                          "Geometry/Overlap width=0.0625",
                          "Discretization/Mesh size=0.03125"});
    }
}



TEST_CASE("horizon to mesh size ratio from 1 to 8", "[stability]")
{
  for (const std::string kernel : {"constant", "inverse distance"})
    for (const std::string m : {"1", "1.5", "2", "3", "4", "5", "6", "7", "8"})
      {
        INFO(kernel << ", eps/h = " << m);
        check_linear_patch({"Nonlocal model/Kernel=" + kernel,
                            "Nonlocal model/Horizon to mesh size ratio=" + m,
                            "Discretization/Number of levels=2"});
      }
}



TEST_CASE("Tikhonov regularization keeps the system solvable", "[stability]")
{
  // With alpha > 0 the controls are biased towards zero, so the patch test
  // no longer holds exactly; the mismatch grows with alpha but stays small
  // for a small alpha.
  double previous_J = 0;
  for (const std::string alpha : {"1e-10", "1e-6", "1e-2"})
    {
      const SceneRun run = run_scene("diffusion_1d_patch",
                                     {"Coupling/Tikhonov parameter=" + alpha});
      const double   J   = run.summary.levels.back().mismatch_J;
      INFO("alpha " << alpha << " J " << J);
      CHECK(J >= previous_J);
      previous_J = J;
    }
  CHECK(previous_J > 0);
}

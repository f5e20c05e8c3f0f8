// Patch tests of the 1D coupling: solutions in both discrete spaces are
// reproduced to round-off by either solver method, and the two methods agree.

#include <catch2/catch.hpp>

#include "scene_run.h"

namespace
{
  const std::vector<std::string> methods = {"full space direct",
                                            "reduced space cg"};
  const std::vector<std::string> kernels = {"constant",
                                            "inverse distance",
                                            "fractional"};

  /** Check u is reproduced; return the solutions of both methods. */
  std::vector<ltn::CouplingSolution>
  check_patch(const std::vector<std::string> &sets, const double max_u)
  {
    std::vector<ltn::CouplingSolution> solutions;
    for (const std::string &method : methods)
      {
        auto with_method = sets;
        with_method.push_back("Coupling/Method=" + method);
        const SceneRun run = run_scene("diffusion_1d_patch", with_method);
        for (const auto &level : run.summary.levels)
          {
            INFO(method << " h " << level.h << " eps " << level.horizon);
            REQUIRE(level.has_errors);
            CHECK(level.coupled_errors.linf / max_u <= 1e-10);
            CHECK(level.nonlocal_errors.linf / max_u <= 1e-10);
            CHECK(level.local_errors.linf / max_u <= 1e-10);
          }
        solutions.push_back(run.solutions.back());
      }
    CHECK(relative_difference(solutions[0], solutions[1]) <= 1e-8);
    return solutions;
  }
} // namespace



TEST_CASE("linear patch test for every kernel and both methods", "[patch]")
{
  for (const std::string &kernel : kernels)
    {
      INFO("kernel " << kernel);
      check_patch({"Nonlocal model/Kernel=" + kernel,
                   "Discretization/Number of levels=3"},
                  1.75);
    }
}



TEST_CASE("quadratic patch test with P2 on both sides", "[patch]")
{
  for (const std::string &kernel : kernels)
    {
      INFO("kernel " << kernel);
      check_patch({"Nonlocal model/Kernel=" + kernel,
                   "Nonlocal model/Finite element degree=2",
                   "Local model/Finite element degree=2",
                   "Diffusion data/Exact solution=x^2",
                   "Diffusion data/Nonlocal right-hand side=-2",
                   "Diffusion data/Local right-hand side=-2",
                   "Discretization/Number of levels=2"},
                  1.75 * 1.75);
    }
}



TEST_CASE("patch tests with a Neumann condition on the local side", "[patch]")
{
  check_patch({"Local model/Dirichlet boundaries=x-",
               "Diffusion data/Boundary gradient=1"},
              1.75);
  check_patch({"Local model/Dirichlet boundaries=x-",
               "Nonlocal model/Finite element degree=2",
               "Local model/Finite element degree=2",
               "Diffusion data/Exact solution=x^2",
               "Diffusion data/Nonlocal right-hand side=-2",
               "Diffusion data/Local right-hand side=-2",
               "Diffusion data/Boundary gradient=2*x"},
              1.75 * 1.75);
}



TEST_CASE("P1 does not contain x^2 so its error is that of P1", "[patch]")
{
  // A control on the test above: with P1 on both sides x^2 is not
  // reproduced, so the patch test is not passing for a trivial reason.
  const SceneRun run = run_scene("diffusion_1d_patch",
                                 {"Diffusion data/Exact solution=x^2",
                                  "Diffusion data/Nonlocal right-hand side=-2",
                                  "Diffusion data/Local right-hand side=-2"});
  CHECK(run.summary.levels.back().coupled_errors.linf > 1e-6);
}

#pragma once

// Run a scene of parameter_files/ in-process, with --set style overrides,
// and hand back its summary and solutions.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <ltn/app/parameter_reading.h>
#include <ltn/app/scene_selection.h>

#include <catch2/catch.hpp>

#include <iostream>
#include <string>
#include <vector>

/**
 * diffusion_2d_patch made quadratic: FE_Q(2), which needs a particle per
 * nodal spacing h/2, and a quadratic solution.
 */
inline const std::vector<std::string> quadratic_2d_patch = {
  "Local model/Finite element degree=2",
  "Nonlocal model/Particle spacing to mesh size ratio=0.5",
  "Diffusion data/Exact solution=x^2 + x*y - 0.5*y^2 + x",
  "Diffusion data/Nonlocal right-hand side=-1",
  "Diffusion data/Local right-hand side=-1"};

struct SceneRun
{
  ltn::RunSummary                    summary;
  std::vector<ltn::CouplingSolution> solutions;
};

inline SceneRun
run_scene(const std::string &scene, const std::vector<std::string> &sets = {})
{
  dealii::ParameterHandler prm;
  ltn::declare_all_parameters(prm);
  ltn::read_parameters(prm,
                       std::string(LTN_SOURCE_DIR) + "/parameter_files/" +
                         scene + ".prm",
                       sets);
  dealii::ConditionalOStream quiet(std::cout, false);
  SceneRun                   run;
  ltn::with_selected_scene(prm, scene, [&](auto &runner) {
    run.summary   = runner.run("", quiet);
    run.solutions = runner.get_solutions();
  });
  return run;
}

/**
 * Check the observed rates of the coupled L2 and max errors on every
 * refinement of a run (a Catch2 CHECK each).
 */
inline void
check_coupled_rates(const ltn::RunSummary &summary,
                    const double           min_l2_rate,
                    const double           min_max_rate)
{
  const auto &levels = summary.levels;
  for (std::size_t l = 1; l < levels.size(); ++l)
    {
      const auto  &c = levels[l - 1], &f = levels[l];
      const double l2_rate  = ltn::observed_rate(c.coupled_errors.l2(),
                                                f.coupled_errors.l2(),
                                                c.h,
                                                f.h);
      const double max_rate = ltn::observed_rate(c.coupled_errors.linf,
                                                 f.coupled_errors.linf,
                                                 c.h,
                                                 f.h);
      INFO("level " << l << " h " << f.h << " eps " << f.horizon << ": L2 rate "
                    << l2_rate << ", max rate " << max_rate);
      CHECK(l2_rate >= min_l2_rate);
      CHECK(max_rate >= min_max_rate);
    }
}

/**
 * Check that the coupled L2 error of every level of @p summary lies within
 * @p fraction of @p reference's (a Catch2 CHECK each).
 */
inline void
check_errors_near(const ltn::RunSummary &summary,
                  const ltn::RunSummary &reference,
                  const double           fraction)
{
  REQUIRE(summary.levels.size() == reference.levels.size());
  for (std::size_t l = 0; l < summary.levels.size(); ++l)
    {
      const double ours   = summary.levels[l].coupled_errors.l2();
      const double theirs = reference.levels[l].coupled_errors.l2();
      INFO("level " << l << ": L2 error " << ours << ", the reference's "
                    << theirs);
      CHECK(std::abs(ours - theirs) <= fraction * theirs);
    }
}

/** max_i |a_i - b_i| / max_i |b_i| over both fields of two solutions. */
inline double
relative_difference(const ltn::CouplingSolution &a,
                    const ltn::CouplingSolution &b)
{
  double difference = 0, scale = 0;
  for (const unsigned int k : {0u, 1u})
    if (b.fields[k].size() > 0)
      {
        dealii::TrilinosWrappers::MPI::Vector d = a.fields[k];
        d -= b.fields[k];
        difference = std::max(difference, d.linfty_norm());
        scale      = std::max(scale, b.fields[k].linfty_norm());
      }
  return difference / scale;
}

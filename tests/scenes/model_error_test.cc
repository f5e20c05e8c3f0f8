// The short-wave model-error estimate (Postprocess/Model error estimate,
// doc/model_adaptivity.md): zero to round-off where both models agree
// (polynomial patch tests, one box and unions), as is the true error
// against the nonlocal model on the whole body; on the cracked plate
// largest next to the nonlocal region ahead of a crack tip, smaller for
// larger regions, and below the true error (a lower bound).

#include <catch2/catch.hpp>

#include "scene_run.h"

namespace
{
  ltn::ModelErrorRecord
  estimate_of(const std::string &scene, std::vector<std::string> sets)
  {
    sets.push_back("Postprocess/True model error=true");
    const SceneRun run    = run_scene(scene, sets);
    const auto    &record = run.summary.levels.back().model_error;
    REQUIRE(record.computed);
    return record;
  }
} // namespace



TEST_CASE("the model-error estimate vanishes where the models agree",
          "[particles][patch][model error]")
{
  const auto &quadratic_2d = quadratic_2d_patch;
  auto        union_2d     = quadratic_2d;
  union_2d.push_back(
    "Geometry/Nonlocal regions=0,0,0.5,1; 0.5,0,1,0.5; 1.375,0.25,1.75,0.75");
  union_2d.push_back("Geometry/Overlap width=0.125");
  for (const auto &[scene, sets] :
       std::vector<std::pair<std::string, std::vector<std::string>>>{
         {"diffusion_2d_patch", quadratic_2d},
         {"diffusion_2d_patch", union_2d},
         {"diffusion_3d_patch", {}},
         {"lps_plate_2d_quadratic_patch", {}},
         {"lps_plate_2d_quadratic_patch",
          {"Geometry/Nonlocal regions=0.5,0.5,1.5,0.875; 0.75,0.25,1.25,0.5; "
           "1.75,0.25,2,0.75"}}})
    {
      const auto record = estimate_of(scene, sets);
      INFO(scene << ": estimate " << record.estimate << ", relative "
                 << record.relative << " over " << record.n_points
                 << " points, chi " << record.chi << ", c_G " << record.c_G);
      CHECK(record.n_points > 0);
      CHECK(record.relative <= 1e-10);
      REQUIRE(record.has_true_error);
      CHECK(record.true_relative <= 1e-10);
      CHECK(record.boundary_layer <= 1e-10 * record.estimate / record.relative);
    }
}



TEST_CASE("the model-error estimate on the cracked plate",
          "[particles][model error]")
{
  // The crack runs from x = 0.75 to 1.25 at y = 1; the scene's region is
  // (0.5, 1.5) x (0.75, 1.25), the collar 2 eps = 0.05 deep.
  const double range  = 0.05;
  const auto   record = estimate_of("lps_plate_2d_crack", {});
  INFO("estimate " << record.estimate << ", relative " << record.relative
                   << ", largest at " << record.largest_at[0] << ", "
                   << record.largest_at[1]);
  CHECK(record.relative > 1e-6);
  // eta_0^2 / c_G bounds the error in energy from below.
  REQUIRE(record.has_true_error);
  CHECK(record.estimate <= record.true_error);
  // Largest just outside the region, ahead of a tip along x.
  const double x = record.largest_at[0], y = record.largest_at[1];
  const double outside_x = std::max({0., 0.5 - x, x - 1.5});
  const double outside_y = std::max({0., 0.75 - y, y - 1.25});
  CHECK(outside_x + outside_y > 0);
  CHECK(std::hypot(outside_x, outside_y) <= range);
  CHECK(std::abs(x - 1) <= 0.25 + range);

  // A larger region leaves less to estimate.
  const double smaller =
    estimate_of("lps_plate_2d_crack",
                {"Geometry/Nonlocal regions=0.6,0.85,1.4,1.15"})
      .estimate;
  const double larger =
    estimate_of("lps_plate_2d_crack",
                {"Geometry/Nonlocal regions=0.25,0.5,1.75,1.5"})
      .estimate;
  INFO("smaller region " << smaller << ", larger " << larger);
  CHECK(smaller > record.estimate);
  CHECK(record.estimate > larger);
}

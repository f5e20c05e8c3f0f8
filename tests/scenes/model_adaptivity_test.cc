// `Geometry/Nonlocal regions = auto` (doc/model_adaptivity.md, section 3):
// on the cracked plate the loop starts from the crack's box, grows the
// region where the estimate is largest, and stops below the tolerance with
// a region that holds the crack and its collar, its true error (against
// the coupled solution on the largest admissible region) below the
// tolerance; the same cycles, blocks and particles on 1 and 2 ranks (the
// test runs in both).

#include <catch2/catch.hpp>

#include "scene_run.h"

namespace
{
  /** Is (@p x, @p y) in one of @p boxes (lower corner, upper corner)? */
  bool
  in_boxes(const std::vector<std::vector<double>> &boxes,
           const double                            x,
           const double                            y)
  {
    for (const auto &box : boxes)
      if (box[0] <= x && x <= box[2] && box[1] <= y && y <= box[3])
        return true;
    return false;
  }
} // namespace

TEST_CASE("auto regions on the cracked plate", "[particles][model adaptivity]")
{
  const SceneRun                    run  = run_scene("lps_plate_2d_crack",
                                                     {"Geometry/Nonlocal regions=auto",
                                                      "Geometry/Model error tolerance=3e-5",
                                                      "Postprocess/True model error=true"});
  const ltn::ModelAdaptivityRecord &loop = run.summary.model_adaptivity;
  REQUIRE(loop.enabled);
  // Blocks of the overlap width 0.1 (the collar, 0.05, is thinner).
  CHECK(loop.block_size == Approx(0.1));
  // The region grows by a layer of blocks per cycle from the start.
  REQUIRE(loop.cycles.size() == 4);
  const std::vector<unsigned int> blocks = {40, 68, 100, 136};
  for (unsigned int c = 0; c < 4; ++c)
    CHECK(loop.cycles[c].blocks == blocks[c]);
  const auto &first = loop.cycles.front(), &last = loop.cycles.back();
  // The start: the crack (0.75..1.25 at y = 1) grown by the overlap and
  // three horizons (0.175), snapped to the blocks: (0.5, 0.8)-(1.5, 1.2).
  REQUIRE(first.boxes.size() == 1);
  const std::vector<double> start = {0.5, 0.8, 1.5, 1.2};
  for (unsigned int i = 0; i < 4; ++i)
    CHECK(first.boxes[0][i] == Approx(start[i]));
  CHECK(first.blocks == 40);
  CHECK(first.estimate > loop.tolerance);
  CHECK(first.stopped.empty());
  CHECK(first.added == 28);
  CHECK(last.particles == 10384);
  CHECK(last.stopped == "tolerance");
  CHECK(last.estimate <= loop.tolerance);

  // The final region holds the crack grown by the overlap and the collar.
  for (double x = 0.6; x <= 1.4 + 1e-12; x += 0.05)
    for (double y = 0.85; y <= 1.15 + 1e-12; y += 0.05)
      CHECK(in_boxes(last.boxes, x, y));

  // Each cycle's estimate against the region's true error (the coupled
  // solution on the largest admissible region): effectivity between 0.5
  // and 2, and below the tolerance on the final region.
  const auto &first_error = run.summary.levels[first.level_entry].model_error;
  const auto &last_error  = run.summary.levels[last.level_entry].model_error;
  REQUIRE(first_error.has_region_error);
  REQUIRE(last_error.has_region_error);
  INFO("true errors " << first_error.region_relative << ", "
                      << last_error.region_relative << "; effectivities "
                      << first_error.region_effectivity << ", "
                      << last_error.region_effectivity);
  CHECK(first_error.region_effectivity >= 0.5);
  CHECK(first_error.region_effectivity <= 2);
  CHECK(last_error.region_effectivity >= 0.5);
  CHECK(last_error.region_effectivity <= 2);
  CHECK(last_error.region_relative <= loop.tolerance);
  CHECK(first_error.region_relative > loop.tolerance);
}



TEST_CASE("auto regions on a plate with two cracks far apart",
          "[particles][model adaptivity]")
{
  // The cracked plate with two cracks of length 0.2, at (0.4..0.6, 0.5)
  // and (1.4..1.6, 1.5): a region grows around each.
  const SceneRun run =
    run_scene("lps_plate_2d_crack",
              {"Geometry/Nonlocal regions=auto",
               "Geometry/Model error tolerance=3e-5",
               "Cracks/Corners=0.4, 0.5, 0.6, 0.5; 1.4, 1.5, 1.6, 1.5",
               "Postprocess/Reference crack opening=",
               "Postprocess/True model error=true"});
  const ltn::ModelAdaptivityRecord &loop = run.summary.model_adaptivity;
  REQUIRE(loop.cycles.size() == 2);
  const auto &first = loop.cycles.front(), &last = loop.cycles.back();
  // Each crack grown by 0.175 on the blocks: (0.2, 0.3)-(0.8, 0.7) and
  // (1.2, 1.3)-(1.8, 1.7).
  CHECK(first.boxes.size() == 2);
  CHECK(first.blocks == 48);
  CHECK(last.blocks == 88);
  CHECK(last.particles == 7504);
  CHECK(last.stopped == "tolerance");
  CHECK(last.estimate <= loop.tolerance);
  // Each crack with the overlap and the collar (0.15) in the region, and
  // the plate between them left to the local model.
  for (const double x : {0.25, 0.5, 0.75})
    for (const double y : {0.35, 0.5, 0.65})
      {
        CHECK(in_boxes(last.boxes, x, y));
        CHECK(in_boxes(last.boxes, x + 1, y + 1));
      }
  CHECK(!in_boxes(last.boxes, 1, 1));
  CHECK(!in_boxes(last.boxes, 0.5, 1.5));
  const auto &error = run.summary.levels[last.level_entry].model_error;
  REQUIRE(error.has_region_error);
  INFO("true error " << error.region_relative << ", effectivity "
                     << error.region_effectivity);
  CHECK(error.region_relative <= loop.tolerance);
  CHECK(error.region_effectivity >= 0.5);
  CHECK(error.region_effectivity <= 2);
}



TEST_CASE("auto regions without cracks start from the local model alone",
          "[particles][model adaptivity]")
{
  // 2D diffusion on [0, 2] x [0, 1] with a source concentrated at
  // (1.3, 0.5), the same for both models: they differ where the solution
  // curves most. Blocks of 0.125 (the overlap width).
  const std::string source = "100*exp(-100*((x-1.3)^2+(y-0.5)^2))";
  const SceneRun    run =
    run_scene("diffusion_2d_convergence",
              {"Geometry/Nonlocal regions=auto",
               "Geometry/Overlap width=0.125",
               "Geometry/Model error tolerance=1e-2",
               "Discretization/Number of levels=1",
               "Diffusion data/Exact solution=",
               "Diffusion data/Plane wave number=0",
               "Diffusion data/Nonlocal right-hand side=" + source,
               "Diffusion data/Local right-hand side=" + source,
               "Diffusion data/Boundary data=0",
               "Diffusion data/Volume constraint data=0",
               "Postprocess/True model error=true"});
  const ltn::ModelAdaptivityRecord &loop = run.summary.model_adaptivity;
  REQUIRE(loop.cycles.size() == 3);
  // Cycle 0: the local model alone.
  CHECK(loop.cycles[0].blocks == 0);
  CHECK(loop.cycles[0].particles == 0);
  CHECK(loop.cycles[0].estimate > loop.tolerance);
  // The first blocks: three by three around the source.
  const auto &seed = loop.cycles[1];
  CHECK(seed.blocks == 9);
  REQUIRE(seed.boxes.size() == 1);
  CHECK(in_boxes(seed.boxes, 1.3, 0.5));
  const auto &last = loop.cycles.back();
  CHECK(last.blocks == 21);
  CHECK(last.stopped == "tolerance");
  CHECK(last.estimate <= loop.tolerance);
  for (const auto &cycle : loop.cycles)
    {
      const auto &error = run.summary.levels[cycle.level_entry].model_error;
      REQUIRE(error.has_region_error);
      INFO("cycle " << cycle.cycle << ": estimate " << cycle.estimate
                    << ", true " << error.region_relative);
      CHECK(error.region_effectivity >= 0.5);
      CHECK(error.region_effectivity <= 2);
    }
  CHECK(run.summary.levels[last.level_entry].model_error.region_relative <=
        loop.tolerance);

  // A linear patch needs no nonlocal model: the local model alone meets
  // any tolerance, to round-off.
  const SceneRun patch =
    run_scene("lps_plate_2d_linear_patch", {"Geometry/Nonlocal regions=auto"});
  const auto &only = patch.summary.model_adaptivity.cycles;
  REQUIRE(only.size() == 1);
  CHECK(only[0].blocks == 0);
  CHECK(only[0].stopped == "tolerance");
  CHECK(only[0].estimate <= 1e-10);
}



TEST_CASE("auto regions with adaptive refinement of the local mesh",
          "[particles][model adaptivity][adaptive]")
{
  // The cracked plate at 5e-5: without refinement the loop needs three
  // cycles (7,836 particles); one Kelly cycle of the local mesh halves the
  // start's estimate, which then meets the tolerance: half of it was the
  // FE solution's own error.
  const SceneRun                    run  = run_scene("lps_plate_2d_crack",
                                                     {"Geometry/Nonlocal regions=auto",
                                                      "Geometry/Model error tolerance=5e-5",
                                                      "Local model/Adaptive refinement cycles=1"});
  const ltn::ModelAdaptivityRecord &loop = run.summary.model_adaptivity;
  REQUIRE(loop.cycles.size() == 1);
  REQUIRE(run.summary.levels.size() == 2);
  const auto &cycle = loop.cycles.front();
  // The cycle is judged on its last (refined) solve.
  CHECK(cycle.level_entry == 1);
  CHECK(cycle.blocks == 40);
  CHECK(cycle.stopped == "tolerance");
  const auto &coarse = run.summary.levels[0], &refined = run.summary.levels[1];
  CHECK(refined.n_local_dofs > coarse.n_local_dofs);
  INFO("estimates " << coarse.model_error.relative << ", "
                    << refined.model_error.relative);
  CHECK(coarse.model_error.relative > loop.tolerance);
  CHECK(refined.model_error.relative <= loop.tolerance);
}

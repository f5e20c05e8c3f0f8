// Cracks against a nonlocal region made of boxes: a crack must lie in the
// part of the region the overlap bands leave to the nonlocal model alone.

#include <ltn/base/input_error.h>
#include <ltn/problem/crack.h>

#include <catch2/catch.hpp>

#include "box_layout.h"

using namespace ltn;

TEST_CASE("a slanted crack in an L-shaped region", "[geometry]")
{
  const Geometry<2> g        = l_shape_layout();
  const auto        accepted = [&](const Point<2> &a, const Point<2> &b) {
    CrackSet<2> set;
    Crack<2>    crack;
    crack.corners = {{a, b}};
    set.cracks    = {crack};
    try
      {
        set.validate(g, {1. / 64});
      }
    catch (const InputError &)
      {
        return false;
      }
    return true;
  };
  // Across the concave corner inside S: its bounding box is not in S.
  CHECK(accepted(Point<2>(0.64, 1.01), Point<2>(1.01, 0.64)));
  // Through the band at the corner, (0.95, 0.95).
  CHECK_FALSE(accepted(Point<2>(0.7, 1.2), Point<2>(1.2, 0.7)));
  // Axis-parallel: in S, and reaching into the band.
  CHECK(accepted(Point<2>(0.7, 0.7), Point<2>(1.3, 0.7)));
  CHECK_FALSE(accepted(Point<2>(0.7, 0.9), Point<2>(1.3, 0.9)));
}

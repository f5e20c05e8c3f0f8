// Derived regions of the seed's 1D layout and of a 2D layout.

#include <ltn/problem/geometry.h>

#include <catch2/catch.hpp>

#include "seed_geometry.h"

using namespace ltn;

TEST_CASE("regions of the seed's 1D layout", "[geometry]")
{
  const Geometry<1> g   = seed_geometry();
  const double      eps = 0.1;

  CHECK(g.nonlocal_face_on_body_boundary(0));
  CHECK_FALSE(g.nonlocal_face_on_body_boundary(1));
  const auto shrunk = g.nonlocal_region().shrunk_extent(0);
  REQUIRE(shrunk.size() == 1);
  CHECK(shrunk[0].second == Approx(0.75));

  const auto region = [&](const double x) {
    return g.nonlocal_region_of(Point<1>(x), eps);
  };
  CHECK(region(-0.05) == Region::physical_collar);
  CHECK(region(0.) == Region::physical_collar);
  CHECK(region(0.5) == Region::nonlocal);
  CHECK(region(0.8) == Region::overlap);
  CHECK(region(1.) == Region::control_collar);
  CHECK(region(1.05) == Region::control_collar);

  CHECK_FALSE(g.in_local_region(Point<1>(0.)));
  CHECK_FALSE(g.in_local_region(Point<1>(0.5)));
  CHECK(g.in_local_region(Point<1>(0.75)));
  CHECK(g.in_local_region(Point<1>(1.75)));
  CHECK(g.local_region_of(Point<1>(1.2), eps) == Region::local);
  CHECK(g.local_region_of(Point<1>(1.1), eps) == Region::overlap);
}



TEST_CASE("2D layout: overlap band on the interior face only", "[geometry]")
{
  Geometry<2> g;
  g.body.upper    = Point<2>(2, 1);
  g.overlap_width = 0.25;
  g.set_nonlocal_boxes({{Point<2>(0, 0), Point<2>(1, 1)}});
  const auto x = g.nonlocal_region().shrunk_extent(0);
  const auto y = g.nonlocal_region().shrunk_extent(1);
  REQUIRE(x.size() == 1);
  REQUIRE(y.size() == 1);
  CHECK(x[0].first == Approx(0));
  CHECK(x[0].second == Approx(0.75));
  CHECK(y[0].second == Approx(1));
  CHECK(g.in_local_region(Point<2>(0.8, 0.5)));
  CHECK_FALSE(g.in_local_region(Point<2>(0.5, 0.5)));
  // The control collar has rounded corners: Euclidean distance to Omega_n.
  CHECK(g.in_overlap(Point<2>(1.07, 0.5), 0.1));
  CHECK_FALSE(g.in_overlap(Point<2>(1.2, 0.5), 0.1));
}

#pragma once

// The seed's 1D layout, shared by the unit tests: body [0, 1.75], nonlocal
// region (0, 1), overlap width 0.25 (so the local region is [0.75, 1.75]).

#include <ltn/problem/geometry.h>

inline ltn::Geometry<1>
seed_geometry()
{
  ltn::Geometry<1> geometry;
  geometry.body.lower[0] = 0;
  geometry.body.upper[0] = 1.75;
  geometry.overlap_width = 0.25;
  geometry.set_nonlocal_boxes({{ltn::Point<1>(0), ltn::Point<1>(1)}});
  return geometry;
}

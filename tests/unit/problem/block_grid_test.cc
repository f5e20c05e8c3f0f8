// The blocks of `Geometry/Nonlocal regions = auto` (doc/model_adaptivity.md,
// section 3): numbering, the block of a point, covering and inner sets,
// neighbours, pieces, and the boxes read off a set (disjoint, covering
// exactly the set).

#include <ltn/problem/block_grid.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace ltn;

namespace
{
  /** The blocks covered by @p boxes, each block tested at its centre. */
  template <int dim>
  std::vector<bool>
  blocks_of(const BlockGrid<dim> &grid, const std::vector<Box<dim>> &boxes)
  {
    std::vector<bool> set(grid.n_blocks(), false);
    for (unsigned int k = 0; k < grid.n_blocks(); ++k)
      {
        const Box<dim> b = grid.block(k);
        Point<dim>     centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = 0.5 * (b.lower[d] + b.upper[d]);
        unsigned int holding = 0;
        for (const auto &box : boxes)
          holding += box.contains(centre);
        CHECK(holding <= 1);
        set[k] = holding == 1;
      }
    return set;
  }
} // namespace



TEST_CASE("a grid of blocks over a body", "[unit][model adaptivity]")
{
  // [0, 2] x [0, 1.05] in blocks of 0.1: 20 x 11, the last row 0.05 high.
  Box<2> body;
  body.upper = Point<2>(2, 1.05);
  const BlockGrid<2> grid(body, 0.1);
  REQUIRE(grid.n_blocks() == 220);
  CHECK(grid.block(21).lower.distance(Point<2>(0.1, 0.1)) < 1e-12);
  CHECK(std::abs(grid.block(219).upper[1] - 1.05) < 1e-12);
  CHECK(grid.block_of(Point<2>(0.15, 0.15)) == 21);
  // Half-open, closed at the upper faces.
  CHECK(grid.block_of(Point<2>(0.2, 0.1)) == 22);
  CHECK(grid.block_of(Point<2>(2, 1.05)) == 219);

  // A box (0.25, 0.3)-(0.5, 0.6) meets the blocks 2..4 x 3..5.
  Box<2> box;
  box.lower          = Point<2>(0.25, 0.3);
  box.upper          = Point<2>(0.5, 0.6);
  const auto covered = grid.covering(box);
  CHECK(BlockGrid<2>::count(covered) == 9);
  CHECK(covered[3 * 20 + 2]);
  CHECK(!covered[6 * 20 + 2]);
  CHECK(!covered[3 * 20 + 5]);

  // At least 0.15 from every face: x blocks 2..17, y blocks 2..8 (the
  // block [0.8, 0.9] ends 0.15 below the top; the next does not).
  CHECK(BlockGrid<2>::count(grid.inside(0.15)) == 16 * 7);

  CHECK(grid.face_neighbours(0).size() == 2);
  CHECK(grid.face_neighbours(21).size() == 4);
}



TEST_CASE("sets of blocks as pieces and boxes", "[unit][model adaptivity]")
{
  Box<2> body;
  body.upper = Point<2>(1, 1);
  const BlockGrid<2> grid(body, 0.125);
  // An L (blocks x 1..4 at y 1, x 1 at y 2..4), a lone block touching it
  // only at a corner (x 2, y 2), and a 2 x 2 square apart.
  std::vector<bool> set(grid.n_blocks(), false);
  const auto at = [&](unsigned int x, unsigned int y) { return y * 8 + x; };
  for (unsigned int x = 1; x <= 4; ++x)
    set[at(x, 1)] = true;
  for (unsigned int y = 2; y <= 4; ++y)
    set[at(1, y)] = true;
  set[at(2, 2)] = true;
  for (unsigned int x = 5; x <= 6; ++x)
    for (unsigned int y = 5; y <= 6; ++y)
      set[at(x, y)] = true;

  const auto pieces = grid.pieces(set);
  // (2, 2) shares a face with (2, 1) and (1, 2): one piece with the L.
  REQUIRE(pieces.size() == 2);
  CHECK(pieces[0].size() == 8);
  CHECK(pieces[1].size() == 4);

  const auto boxes = grid.boxes(set);
  CHECK(blocks_of(grid, boxes) == set);
  // The first box is the L's row, grown along x and no further along y.
  CHECK(boxes.front().lower.distance(Point<2>(0.125, 0.125)) < 1e-12);
  CHECK(boxes.front().upper.distance(Point<2>(0.625, 0.25)) < 1e-12);
  // The square is one box.
  CHECK(boxes.back().lower.distance(Point<2>(0.625, 0.625)) < 1e-12);
  CHECK(boxes.back().upper.distance(Point<2>(0.875, 0.875)) < 1e-12);

  // 3D: a random set is read off as boxes that cover exactly it.
  Box<3> cube;
  cube.upper = Point<3>(1, 1, 1);
  const BlockGrid<3> grid_3d(cube, 0.25);
  std::vector<bool>  set_3d(grid_3d.n_blocks(), false);
  for (unsigned int k = 0; k < grid_3d.n_blocks(); ++k)
    set_3d[k] = (k * 7919) % 5 < 2;
  CHECK(blocks_of(grid_3d, grid_3d.boxes(set_3d)) == set_3d);
}

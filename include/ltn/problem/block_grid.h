#pragma once

#include <deal.II/base/point.h>

#include <ltn/problem/box.h>

#include <array>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The body cut into blocks of one size, aligned with its lower corner
   * (the last block along an axis ends at the body's face): the units
   * `Geometry/Nonlocal regions = auto` adds to the nonlocal region
   * (doc/model_adaptivity.md, '`Geometry/Nonlocal regions = auto`'). A set
   * of blocks is a bitmap, one flag per block, numbered lexicographically
   * with axis 0 fastest.
   */
  template <int dim>
  class BlockGrid
  {
  public:
    using Set = std::vector<bool>;

    BlockGrid() = default;

    /** Blocks of size @p block_size over @p body. */
    BlockGrid(const Box<dim> &body, const double block_size);

    unsigned int
    n_blocks() const;

    /** The box of block @p k (clipped to the body). */
    Box<dim>
    block(const unsigned int k) const;

    /**
     * The block that holds @p p: blocks are half-open, closed at the
     * body's upper faces.
     */
    unsigned int
    block_of(const Point<dim> &p) const;

    /** The blocks whose interior meets the interior of @p box. */
    Set
    covering(const Box<dim> &box) const;

    /**
     * The blocks at least @p room from every face of the body (the
     * largest region whose collar of depth @p room stays in the body).
     */
    Set
    inside(const double room) const;

    /** The blocks sharing a face with block @p k. */
    std::vector<unsigned int>
    face_neighbours(const unsigned int k) const;

    /**
     * The `(2 radius + 1)^dim` blocks around block @p k, moved as little as
     * needed to lie within the smallest box of blocks that holds
     * @p within, and cut to @p within.
     */
    Set
    window(const unsigned int k,
           const unsigned int radius,
           const Set         &within) const;

    /**
     * The connected pieces of @p set (blocks joined through faces), each
     * as its blocks in ascending order.
     */
    std::vector<std::vector<unsigned int>>
    pieces(const Set &set) const;

    /**
     * @p set as disjoint boxes: scanning the blocks in order, each not yet
     * taken starts a box grown along axis 0, then 1, then 2 while the whole
     * slab added is in the set and not taken.
     */
    std::vector<Box<dim>>
    boxes(const Set &set) const;

    /** The number of blocks in @p set. */
    static unsigned int
    count(const Set &set);

  private:
    std::array<unsigned int, dim>
    coordinates(unsigned int k) const;

    unsigned int
    number(const std::array<unsigned int, dim> &c) const;

    Box<dim>                      body;
    double                        size = 0;
    std::array<unsigned int, dim> counts{};
  };
} // namespace ltn

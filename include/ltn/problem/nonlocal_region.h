#pragma once

#include <ltn/problem/box.h>

#include <array>
#include <utility>
#include <vector>

namespace ltn
{
  /**
   * The nonlocal region `U = Omega_n` of a scene: a union of closed
   * axis-parallel boxes in the body `D` whose interiors are disjoint (they
   * may touch, forming L- and T-shapes), and the sets derived from it
   * (doc/model_adaptivity.md, 'Regions made of blocks'):
   *
   * - the depth `s(x) = dist_inf(x, closure(D \ U))`: how far `x` lies
   *   inside `U` from the part of the body that is not nonlocal (faces of `U`
   *   on the body's boundary and faces where boxes touch do not count);
   * - the shrunk region `S = {x in U : s(x) >= delta}` of the nonlocal model
   *   alone, `delta` the overlap width; the local region is the rest of the
   *   body, `{x in D : s(x) <= delta}`.
   *
   * The max-norm makes `S` a union of boxes again (a square band at a
   * concave corner, not a quarter circle). Both `D \ U` and `S` are unions
   * of the cells of rectilinear grids whose planes are the faces of the body
   * and of the boxes (and, for `S`, those planes moved by `delta`): the only
   * data structures.
   */
  template <int dim>
  class NonlocalRegion
  {
  public:
    NonlocalRegion() = default;

    /**
     * @p boxes in @p body, with the overlap width @p overlap_width and the
     * tolerance @p tolerance of geometric comparisons. Validation is the
     * caller's (Geometry::validate()): the sets are defined for any boxes.
     */
    NonlocalRegion(const Box<dim>              &body,
                   const std::vector<Box<dim>> &boxes,
                   const double                 overlap_width,
                   const double                 tolerance);

    const std::vector<Box<dim>> &
    boxes() const;

    /** The smallest box holding every box of the region. */
    Box<dim>
    bounding_box() const;

    /** Is @p p in the closed region, up to @p tolerance? */
    bool
    contains(const Point<dim> &p, const double tolerance) const;

    /**
     * Is @p p in the interior of the region, at least @p tolerance from
     * its boundary? A point of a face where two boxes touch is.
     */
    bool
    contains_strictly(const Point<dim> &p, const double tolerance) const;

    /** The Euclidean distance from @p p to the region (zero inside). */
    double
    distance(const Point<dim> &p) const;

    /**
     * The depth `s(p)` of a point @p p of the body, capped at @p cap (zero
     * outside the region).
     */
    double
    depth(const Point<dim> &p, const double cap) const;

    /** Is @p p in the closed local region `{x in D : s(x) <= delta}`? */
    bool
    in_local_part(const Point<dim> &p) const;

    /** Does the region touch face @p face of the body (with some area)? */
    bool
    touches_body_face(const unsigned int face) const;

    /** Does the region cover the whole body? */
    bool
    covers_body() const;

    /**
     * Does part of the body outside the region lie beyond face @p face of
     * @p box (one of the region's boxes), right next to it?
     */
    bool
    face_is_exposed(const Box<dim> &box, const unsigned int face) const;

    /**
     * Does every connected piece of the region hold part of `S`? A piece
     * that is all overlap band has no nonlocal model of its own.
     */
    bool
    every_piece_has_shrunk_part() const;

    /** Is the closed box @p box inside the closure of `S`? */
    bool
    shrunk_region_contains(const Box<dim> &box) const;

    /**
     * The coordinates along axis @p d of the faces of `S` that lie inside
     * the body: the planes a mesh must resolve for its cells to be either
     * in `S` or in the local region.
     */
    std::vector<double>
    shrunk_face_coordinates(const unsigned int d) const;

    /** Does the plane `x_d = plane` cut a cell of `S` in two? */
    bool
    shrunk_region_crosses(const unsigned int d, const double plane) const;

    /**
     * The projection of `S` onto axis @p d: disjoint open intervals in
     * increasing order, touching ones merged.
     */
    std::vector<std::pair<double, double>>
    shrunk_extent(const unsigned int d) const;

  private:
    /**
     * A rectilinear grid over the body: the planes of each axis and one
     * flag per cell, lexicographic, the first axis fastest.
     */
    struct CellGrid
    {
      std::array<std::vector<double>, dim> planes;
      std::vector<bool>                    flag;

      std::size_t
      n_cells() const;
      /** The index of the cell with per-axis indices @p i. */
      std::size_t
      cell(const std::array<unsigned int, dim> &i) const;
      Box<dim>
      box(const std::array<unsigned int, dim> &i) const;
      /** Call `f(i)` for the per-axis indices of every cell in turn. */
      template <typename F>
      void
      for_each_cell(const F &f) const;
    };

    /** The grid on planes @p planes, a cell flagged where @p flag says. */
    template <typename Flag>
    static CellGrid
    make_grid(std::array<std::vector<double>, dim> planes,
              const double                         tolerance,
              const Flag                          &flag);

    Box<dim>              body;
    std::vector<Box<dim>> region_boxes;
    double                overlap_width = 0;
    double                tolerance     = 0;
    /** Cells of the body's grid: flagged where in the region. */
    CellGrid region_cells;
    /** Cells of the finer grid (planes also moved by delta): flagged in S. */
    CellGrid shrunk_cells;
  };
} // namespace ltn

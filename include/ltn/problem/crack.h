#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ltn/problem/geometry.h>

#include <array>
#include <string>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * A crack: in 2D the straight segment between `corners[0]` and
   * `corners[1]`; in 3D the planar parallelogram (a rectangle when its edges
   * are perpendicular) `corners[0] + s (corners[1] - corners[0]) + t
   * (corners[2] - corners[0])`, `s, t` in `[0, 1]`. The nonlocal model
   * removes every bond that crosses it.
   */
  template <int dim>
  struct Crack
  {
    std::array<Point<dim>, dim> corners;

    /**
     * Does the open segment from @p x to @p y cross the crack (its end
     * points on opposite sides of the crack's line or plane, strictly, and
     * the crossing point on the crack up to @p tolerance)? Symmetric in
     * @p x and @p y to the last bit.
     */
    bool
    cuts(const Point<dim> &x,
         const Point<dim> &y,
         const double      tolerance) const;

    /** The signed distance of @p p from the crack's line or plane. */
    double
    signed_distance(const Point<dim> &p) const;

    /** The unit normal of the crack's line or plane. */
    Tensor<1, dim>
    normal() const;

    /**
     * The coordinates `(s, t)` (only `s` in 2D) of the projection of @p p on
     * the crack's line or plane in the basis of its edges: `p` projects into
     * the crack when all are in `[0, 1]`.
     */
    std::array<double, dim - 1>
    edge_coordinates(const Point<dim> &p) const;

    /** The smallest box that holds the crack. */
    Box<dim>
    bounding_box() const;

    /** The length (2D) or area (3D) of the crack. */
    double
    measure() const;
  };

  /**
   * The cracks of a scene (subsection `Cracks`), parsed and checked against
   * the layout: every crack lies in the nonlocal region.
   */
  template <int dim>
  struct CrackSet
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Check the cracks against @p geometry and the particle spacings of a
     * study (none of its particles may lie on a crack, which would leave it
     * on neither side): an InputError names `Cracks/Corners` otherwise.
     */
    void
    validate(const Geometry<dim>       &geometry,
             const std::vector<double> &spacings) const;

    std::vector<Crack<dim>> cracks;
  };
} // namespace ltn

#pragma once

#include <deal.II/base/point.h>

namespace ltn
{
  using namespace dealii;

  /**
   * Is @p length a whole multiple of @p size, up to round-off? The test of
   * every alignment of a layout with a mesh or a particle lattice.
   */
  bool
  is_whole_multiple(const double length, const double size);

  /** An axis-aligned box `[lower, upper]`. */
  template <int dim>
  struct Box
  {
    Point<dim> lower;
    Point<dim> upper;

    /** Is @p p in the closed box, up to a tolerance? */
    bool
    contains(const Point<dim> &p, const double tolerance = 0) const;

    /** Is @p p in the open box, at least @p tolerance from its faces? */
    bool
    contains_strictly(const Point<dim> &p, const double tolerance = 0) const;

    /** Euclidean distance from @p p to the box (zero inside). */
    double
    distance(const Point<dim> &p) const;

    /** The max-norm distance from @p p to the box (zero inside). */
    double
    max_norm_distance(const Point<dim> &p) const;
  };
} // namespace ltn

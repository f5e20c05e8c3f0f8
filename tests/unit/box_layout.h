#pragma once

// Layouts of the unit tests from boxes: a box (x0, x1) x (y0, y1)^(dim-1),
// and a Geometry of a body, the boxes of Omega_n and the overlap width, set
// in the order Geometry::set_nonlocal_boxes() needs (body and width first).

#include <ltn/problem/geometry.h>

#include <vector>

/** The box (x0, x1) x (y0, y1)^(dim-1). */
template <int dim>
ltn::Box<dim>
slab(const double x0, const double x1, const double y0, const double y1)
{
  ltn::Box<dim> box;
  for (unsigned int d = 0; d < dim; ++d)
    {
      box.lower[d] = (d == 0) ? x0 : y0;
      box.upper[d] = (d == 0) ? x1 : y1;
    }
  return box;
}

/** A coupled layout: @p body, Omega_n the union of @p boxes. */
template <int dim>
ltn::Geometry<dim>
box_layout(const ltn::Box<dim>              &body,
           const std::vector<ltn::Box<dim>> &boxes,
           const double                      overlap_width)
{
  ltn::Geometry<dim> geometry;
  geometry.body          = body;
  geometry.overlap_width = overlap_width;
  geometry.set_nonlocal_boxes(boxes);
  return geometry;
}

/**
 * The L of the region tests in the body (0, 2)^2, overlap width 0.125:
 * (0.5, 1.5) x (0.5, 1) and (0.5, 1) x (1, 1.5), touching along y = 1. Its
 * shrunk region S is (0.625, 1.375) x (0.625, 0.875) and (0.625, 0.875) x
 * (0.875, 1.375).
 */
inline ltn::Geometry<2>
l_shape_layout()
{
  return box_layout<2>(slab<2>(0, 2, 0, 2),
                       {slab<2>(0.5, 1.5, 0.5, 1), slab<2>(0.5, 1, 1, 1.5)},
                       0.125);
}

#include <ltn/problem/blending_function.h>

#include <algorithm>

namespace ltn
{
  template <int dim>
  BlendingFunction<dim>::BlendingFunction(const Geometry<dim> &geometry)
    : geometry(geometry)
  {}



  template <int dim>
  double
  BlendingFunction<dim>::value(const Point<dim> &p, const unsigned int) const
  {
    // Beyond the body (the collars that carry the boundary data), the
    // weight of the nearest point of the body: a face crossed adds no kink.
    Point<dim> nearest = p;
    for (unsigned int d = 0; d < dim; ++d)
      nearest[d] =
        std::clamp(p[d], geometry.body.lower[d], geometry.body.upper[d]);
    const double delta = geometry.overlap_width;
    return geometry.nonlocal_region().depth(nearest, delta) / delta;
  }



  template <int dim>
  std::vector<double>
  BlendingFunction<dim>::kinks(const unsigned int d) const
  {
    const double        delta = geometry.overlap_width;
    std::vector<double> planes;
    for (const Box<dim> &box : geometry.nonlocal_region().boxes())
      for (const double x : {box.lower[d],
                             box.lower[d] + delta,
                             box.upper[d] - delta,
                             box.upper[d]})
        planes.push_back(x);
    std::sort(planes.begin(), planes.end());
    planes.erase(std::unique(planes.begin(), planes.end()), planes.end());
    return planes;
  }



  template class BlendingFunction<1>;
  template class BlendingFunction<2>;
  template class BlendingFunction<3>;
} // namespace ltn

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
    const double delta = geometry.overlap_width;
    return geometry.body.contains(p, geometry.tolerance()) ?
             geometry.nonlocal_region().depth(p, delta) / delta :
             1.;
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

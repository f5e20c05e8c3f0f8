#include <ltn/problem/box.h>

#include <algorithm>
#include <cmath>

namespace ltn
{
  bool
  is_whole_multiple(const double length, const double size)
  {
    const double n = length / size;
    return std::abs(n - std::round(n)) < 1e-8 * std::max(1., n);
  }



  template <int dim>
  bool
  Box<dim>::contains(const Point<dim> &p, const double tolerance) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (p[d] < lower[d] - tolerance || p[d] > upper[d] + tolerance)
        return false;
    return true;
  }



  template <int dim>
  bool
  Box<dim>::contains_strictly(const Point<dim> &p, const double tolerance) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (p[d] <= lower[d] + tolerance || p[d] >= upper[d] - tolerance)
        return false;
    return true;
  }



  template <int dim>
  double
  Box<dim>::distance(const Point<dim> &p) const
  {
    double squared = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double outside = std::max({lower[d] - p[d], p[d] - upper[d], 0.});
        squared += outside * outside;
      }
    return std::sqrt(squared);
  }



  template <int dim>
  double
  Box<dim>::max_norm_distance(const Point<dim> &p) const
  {
    double largest = 0;
    for (unsigned int d = 0; d < dim; ++d)
      largest = std::max({largest, lower[d] - p[d], p[d] - upper[d]});
    return largest;
  }

  template struct Box<1>;
  template struct Box<2>;
  template struct Box<3>;
} // namespace ltn

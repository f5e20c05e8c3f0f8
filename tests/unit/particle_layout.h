#pragma once

// The particle layout shared by the unit tests of the particle operators: the
// body (0,2)x(0,1)^(dim-1) and Omega_n = (0,1.25)x(0.25,0.75)^(dim-1), so the
// collar at x < 0 lies outside the body (volume constraint) and the rest
// inside it (controls); cracks placed by crack_at(); random vectors.

#include <ltn/base/discrete_model.h>
#include <ltn/scene/crack.h>
#include <ltn/scene/geometry.h>

#include <random>

template <int dim>
ltn::Geometry<dim>
particle_layout()
{
  ltn::Geometry<dim> geometry;
  for (unsigned int d = 0; d < dim; ++d)
    {
      geometry.body.upper[d]            = (d == 0) ? 2 : 1;
      geometry.nonlocal_region.lower[d] = (d == 0) ? 0 : 0.25;
      geometry.nonlocal_region.upper[d] = (d == 0) ? 1.25 : 0.75;
    }
  geometry.overlap_width = 0.125;
  return geometry;
}

/** A crack in the plane x = @p x, the square |y - 0.5| <= @p half_width. */
template <int dim>
ltn::Crack<dim>
crack_at(const double x, const double half_width)
{
  ltn::Crack<dim> crack;
  for (unsigned int k = 0; k < dim; ++k)
    {
      crack.corners[k][0] = x;
      for (unsigned int d = 1; d < dim; ++d)
        crack.corners[k][d] = (k == d) ? 0.5 + half_width : 0.5 - half_width;
    }
  return crack;
}

/** Values uniform in [-1, 1] at every owned degree of freedom. */
inline dealii::TrilinosWrappers::MPI::Vector
random_vector(const ltn::DiscreteModel &model, std::mt19937 &random)
{
  std::uniform_real_distribution<double> value(-1, 1);
  dealii::TrilinosWrappers::MPI::Vector  x = model.new_vector();
  for (const auto i : model.owned)
    x(i) = value(random);
  x.compress(dealii::VectorOperation::insert);
  return x;
}

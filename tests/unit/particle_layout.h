#pragma once

// The particle layout shared by the unit tests of the particle operators: the
// body (0,2)x(0,1)^(dim-1) and Omega_n = (0,1.25)x(0.25,0.75)^(dim-1), so the
// collar at x < 0 lies outside the body (volume constraint) and the rest
// inside it (controls); cracks placed by crack_at(); the particle models on
// it; random vectors.

#include <ltn/base/discrete_model.h>
#include <ltn/nonlocal/particle_diffusion.h>
#include <ltn/nonlocal/particle_elasticity.h>
#include <ltn/problem/crack.h>
#include <ltn/problem/geometry.h>

#include <memory>
#include <random>

#include "box_layout.h"

template <int dim>
ltn::Geometry<dim>
particle_layout()
{
  return box_layout<dim>(slab<dim>(0, 2, 0, 1),
                         {slab<dim>(0, 1.25, 0.25, 0.75)},
                         0.125);
}

/**
 * The body of particle_layout() with Omega_n made of four boxes, in the
 * (x, y) plane (z, in 3D, from 0.25 to 0.75 for all): a U of a bar
 * (0,1.125)x(0.25,0.5) with two arms (0,0.25)x(0.5,0.75) and
 * (0.875,1.125)x(0.5,0.75), and apart from it (1.625,1.875)x(0.25,0.75).
 * Lattice lines through both arms have two runs, and the bar's lines pass
 * under the gap: a segment of the products ends where its neighbours' line
 * enters its next run.
 */
template <int dim>
ltn::Geometry<dim>
union_layout()
{
  ltn::Geometry<dim>                         geometry = particle_layout<dim>();
  const std::array<std::array<double, 4>, 4> xy       = {
    {{{0, 0.25, 1.125, 0.5}},
           {{0, 0.5, 0.25, 0.75}},
           {{0.875, 0.5, 1.125, 0.75}},
           {{1.625, 0.25, 1.875, 0.75}}}};
  std::vector<ltn::Box<dim>> boxes(xy.size());
  for (unsigned int b = 0; b < xy.size(); ++b)
    for (unsigned int d = 0; d < dim; ++d)
      {
        boxes[b].lower[d] = d < 2 ? xy[b][d] : 0.25;
        boxes[b].upper[d] = d < 2 ? xy[b][2 + d] : 0.75;
      }
  geometry.set_nonlocal_boxes(boxes);
  return geometry;
}

/**
 * particle_layout() and union_layout() for the lifetime of the tests: a
 * particle model keeps a reference to its geometry.
 */
template <int dim>
const ltn::Geometry<dim> &
lasting_particle_layout()
{
  static const ltn::Geometry<dim> geometry = particle_layout<dim>();
  return geometry;
}

template <int dim>
const ltn::Geometry<dim> &
lasting_union_layout()
{
  static const ltn::Geometry<dim> geometry = union_layout<dim>();
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

/**
 * LPS on the layout (constant kernel, eps = @p m h, lambda 1.3, mu 0.7) with
 * an inner crack and one across the whole lattice, loaded by 1 in every
 * component, assembled or @p matrix_free.
 */
template <int dim>
std::unique_ptr<ltn::ParticleElasticity<dim>>
cracked_lps(const double              h,
            const double              m,
            const bool                matrix_free,
            const ltn::Geometry<dim> &geometry = lasting_particle_layout<dim>())
{
  const std::vector<ltn::Crack<dim>> cracks = {crack_at<dim>(0.5 + h / 2, 0.1),
                                               crack_at<dim>(1 - h / 2, 10)};
  auto particles = std::make_unique<ltn::ParticleElasticity<dim>>(
    geometry,
    ltn::Kernel(ltn::KernelKind::constant, 0.5, dim, m * h),
    h,
    1.3,
    0.7,
    cracks,
    MPI_COMM_WORLD);
  const dealii::Functions::ConstantFunction<dim> load(1., dim);
  particles->assemble(load, load, matrix_free);
  return particles;
}

/**
 * Nonlocal diffusion on the layout (constant kernel, eps = @p m h), data 1,
 * assembled or @p matrix_free.
 */
template <int dim>
std::unique_ptr<ltn::ParticleDiffusion<dim>>
layout_diffusion(
  const double              h,
  const double              m,
  const bool                matrix_free,
  const ltn::Geometry<dim> &geometry = lasting_particle_layout<dim>())
{
  auto particles = std::make_unique<ltn::ParticleDiffusion<dim>>(
    geometry,
    ltn::Kernel(ltn::KernelKind::constant, 0.5, dim, m * h),
    h,
    MPI_COMM_WORLD);
  const dealii::Functions::ConstantFunction<dim> data(1.);
  particles->assemble(data, data, matrix_free);
  return particles;
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

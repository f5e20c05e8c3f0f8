#pragma once

// Nonlocal diffusion on the shared particle layout (particle_layout.h)
// coupled to Poisson: the pieces the unit tests of the coupling build their
// CouplingSystem from.

#include <deal.II/base/function.h>

#include <ltn/coupling/system/overlap_quadrature.h>
#include <ltn/local/poisson_problem.h>

#include "particle_layout.h"

/**
 * Poisson (FE_Q(1), mesh size @p h, Dirichlet on x- and y-, data 1 and flux
 * 0.5) and assembled nonlocal diffusion (spacing @p spacing, horizon
 * @p m spacings) on the layout, and their overlap quadrature.
 */
template <int dim>
struct DiffusionPoissonLayout
{
  DiffusionPoissonLayout(const double h, const double spacing, const double m)
    : geometry(particle_layout<dim>())
    , parameters(poisson_parameters())
    , local(geometry, parameters, h, MPI_COMM_WORLD)
    , particles(layout_diffusion<dim>(spacing, m, false))
  {
    const dealii::Functions::ConstantFunction<dim> one(1.), flux(0.5, dim);
    local.assemble(one, one, flux);
    overlap = ltn::create_overlap_quadrature(geometry,
                                             m * spacing,
                                             *particles,
                                             local.get_dof_handler());
  }

  const ltn::Geometry<dim> geometry;
  /** Kept: the problem refers to them. */
  const ltn::LocalParameters<dim>                    parameters;
  ltn::PoissonProblem<dim>                           local;
  const std::unique_ptr<ltn::ParticleDiffusion<dim>> particles;
  ltn::OverlapQuadrature<dim>                        overlap;

private:
  static ltn::LocalParameters<dim>
  poisson_parameters()
  {
    ltn::LocalParameters<dim> parameters;
    parameters.dirichlet_faces = {0, 2};
    return parameters;
  }
};

#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <ltn/base/discrete_model.h>
#include <ltn/coupling/system/overlap_quadrature.h>
#include <ltn/nonlocal/nonlocal_weak_form_1d.h>

namespace ltn
{
  using namespace dealii;

  /**
   * Fill @p overlap's control traces for the alternating Schwarz method
   * (doc/baseline_couplings.md, 'The transfer operators') of a 1D coupling:
   * each nonlocal control (a node of the nonlocal mesh in its collar) as
   * the local finite element field at its position, and each local control
   * (the node of `Gamma_c`) as the nonlocal finite element field there.
   * Both meshes are whole on every rank.
   */
  void
  add_control_traces(OverlapQuadrature<1>     &overlap,
                     const NonlocalWeakForm1D &nonlocal,
                     const DiscreteModel      &local_model,
                     const DoFHandler<1>      &local_dofs);

  /**
   * The same for particles: each control particle (the collar, all in
   * `Omega_l`) as the local field at its position, found by the rank that
   * owns its cell of the local mesh; each owned local control (a node of
   * `Gamma_c`, inside `Omega_n`) as the tensor-product Lagrange interpolant
   * of the particle field, of the local finite element's degree, on the
   * particles nearest to it along each axis: exact for the polynomials the
   * patch tests use.
   */
  template <int dim, template <int> class ParticleModel>
  void
  add_control_traces(OverlapQuadrature<dim>   &overlap,
                     const ParticleModel<dim> &nonlocal,
                     const DiscreteModel      &local_model,
                     const DoFHandler<dim>    &local_dofs);
} // namespace ltn

#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <ltn/coupling/system/overlap_quadrature.h>
#include <ltn/nonlocal/nonlocal_weak_form_1d.h>
#include <ltn/problem/geometry.h>

namespace ltn
{
  using namespace dealii;

  /**
   * Fill @p overlap's blending nodes for force-based blending in 1D
   * (doc/baseline_couplings.md, 'Force-based blending'): the nodes of the
   * two models' meshes identified by position (both meshes have the same
   * mesh size and degree, so where they overlap their nodes coincide), and
   * per node the blending weight of BlendingFunction. Serial, as 1D scenes
   * are.
   */
  void
  add_blending_nodes(OverlapQuadrature<1>     &overlap,
                     const Geometry<1>        &geometry,
                     const NonlocalWeakForm1D &nonlocal,
                     const DoFHandler<1>      &local_dofs);
} // namespace ltn

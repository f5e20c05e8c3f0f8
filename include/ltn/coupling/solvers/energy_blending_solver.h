#pragma once

#include <ltn/coupling/system/coupling_system.h>

namespace ltn
{
  /**
   * A baseline coupling, not LtN's optimization: energy-based
   * (Arlequin-type) blending in 1D (doc/baseline_couplings.md, 'Energy-based
   * blending'). One field on the nodes of a shared mesh (@p system's
   * overlap's blending nodes) minimizes the nonlocal energy with the bond
   * weight `(beta(x) + beta(y)) / 2` plus the local one with the
   * coefficient `1 - beta`, less the blended load: the two weighted forms
   * the scene put into the blending nodes, summed node by node. The nodes
   * where either closed model fixes its field (Dirichlet faces, the
   * physical collar) keep that value, eliminated from the other rows so
   * that the matrix stays symmetric. Solved as solve_blended_system() says.
   */
  template <int dim>
  CouplingSolution
  solve_energy_blending(const CouplingSystem<dim> &system);
} // namespace ltn

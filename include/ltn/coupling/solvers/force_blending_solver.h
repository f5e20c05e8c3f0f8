#pragma once

#include <ltn/coupling/system/coupling_system.h>

namespace ltn
{
  /**
   * A baseline coupling, not LtN's optimization: force-based blending in 1D
   * (doc/baseline_couplings.md, 'Force-based blending'; Seleson,
   * Beneddine, Prudhomme 2013). One field on the nodes of a shared mesh
   * (@p system's overlap's blending nodes): at each node the equation
   * `beta (nonlocal row) + (1 - beta) (local row)`, each model's closed row
   * as it assembled it and its load likewise, solved by a sparse LU
   * (UMFPACK); each model's field is the shared field at its nodes. The
   * matrix is not symmetric across the band where `beta` changes; its
   * relative asymmetry `|K - K^T|_F / |K|_F` and the LU's relative residual
   * go to the solution's statistics.
   */
  template <int dim>
  CouplingSolution
  solve_force_blending(const CouplingSystem<dim> &system);
} // namespace ltn

#pragma once

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ltn/coupling/system/coupling_system.h>

namespace ltn
{
  /**
   * Solve a blended system on the blending nodes of @p system's overlap
   * (force- and energy-based blending, doc/baseline_couplings.md):
   * `matrix x = load` by a sparse LU (UMFPACK); each model's field is the
   * shared field at its nodes. The LU's relative residual and the matrix's
   * relative asymmetry `|K - K^T|_F / |K|_F` go to the solution's
   * statistics.
   */
  template <int dim>
  CouplingSolution
  solve_blended_system(const CouplingSystem<dim>  &system,
                       const SparseMatrix<double> &matrix,
                       const Vector<double>       &load);
} // namespace ltn

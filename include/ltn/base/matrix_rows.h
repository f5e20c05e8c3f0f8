#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>

namespace ltn
{
  using namespace dealii;

  /**
   * `f(column, value)` for each stored entry of the locally owned row
   * @p row of @p matrix, read in place from Epetra. (deal.II's iterators
   * look for the next nonempty row at an empty one, which made a loop over
   * the mostly empty rows of the surrogate's collar coupling quadratic:
   * 7.9 s at 131,840 unknowns; and they copy the row at each `end(row)`:
   * half of the full-space assembly's time on the 3D convergence scene.)
   */
  template <typename Function>
  void
  for_each_in_row(const TrilinosWrappers::SparseMatrix &matrix,
                  const types::global_dof_index         row,
                  const Function                       &f)
  {
    const Epetra_CrsMatrix &epetra  = matrix.trilinos_matrix();
    int                     n       = 0;
    double                 *values  = nullptr;
    int                    *columns = nullptr;
    epetra.ExtractMyRowView(
      epetra.RowMap().LID(static_cast<TrilinosWrappers::types::int_type>(row)),
      n,
      values,
      columns);
    for (int k = 0; k < n; ++k)
      f(static_cast<types::global_dof_index>(epetra.ColMap().GID(columns[k])),
        values[k]);
  }
} // namespace ltn

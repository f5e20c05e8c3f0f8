#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <functional>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** Per component, the entries `(column, value)` of a particle's row. */
  using ParticleRows =
    std::vector<std::vector<std::pair<types::global_dof_index, double>>>;

  /**
   * Assemble into @p matrix (rows and columns over @p owned_dofs) the rows
   * of @p particles, this rank's, @p n_components degrees of freedom each
   * (numbered `n_components p + c`), each row given by @p rows_of, of the
   * components in the mask @p stored_rows_of (bit `c` for component `c`);
   * the other rows stay empty. @p relevant becomes @p owned_dofs and the
   * columns the rows read.
   */
  void
  assemble_rows(
    const IndexSet    &particles,
    const unsigned int n_components,
    const std::function<void(types::global_dof_index, ParticleRows &)> &rows_of,
    const std::function<unsigned int(types::global_dof_index)> &stored_rows_of,
    const IndexSet                                             &owned_dofs,
    const MPI_Comm                                              communicator,
    TrilinosWrappers::SparseMatrix                             &matrix,
    IndexSet                                                   &relevant);
} // namespace ltn

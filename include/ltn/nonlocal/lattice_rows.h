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
   * Assemble the rows of @p particles, this rank's, @p n_components degrees
   * of freedom each (numbered `n_components p + c`), each row given by
   * @p rows_of, of the components in the mask @p stored_rows_of (bit `c`
   * for component `c`): a row of component `c` goes into `*matrices[g]` for
   * the group `g` whose mask @p row_groups[g] holds `c` (columns over
   * @p owned_dofs; rows over @p owned_dofs, the other rows empty, or with
   * @p only_stored_rows over the rows the matrix stores, so that a product
   * touches no other row and gives a vector of those rows only). Each
   * particle's rows are built twice whatever the number of groups: once for
   * the patterns, once for the values. @p relevant becomes @p owned_dofs
   * and the columns the rows read.
   */
  void
  assemble_rows(
    const IndexSet    &particles,
    const unsigned int n_components,
    const std::function<void(types::global_dof_index, ParticleRows &)> &rows_of,
    const std::function<unsigned int(types::global_dof_index)> &stored_rows_of,
    const std::vector<unsigned int>                            &row_groups,
    const bool                                           only_stored_rows,
    const IndexSet                                      &owned_dofs,
    const MPI_Comm                                       communicator,
    const std::vector<TrilinosWrappers::SparseMatrix *> &matrices,
    IndexSet                                            &relevant);
} // namespace ltn

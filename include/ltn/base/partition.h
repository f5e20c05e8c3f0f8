#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>

namespace ltn
{
  using namespace dealii;

  /**
   * The contiguous share of this rank of `n_local` items per rank, numbered
   * rank by rank: `[sum of n_local of lower ranks, ... + n_local)` within
   * `[0, sum of all n_local)`.
   */
  IndexSet
  contiguous_partition(const types::global_dof_index n_local,
                       const MPI_Comm                communicator);

  /** An even split of `[0, n)` into contiguous ranges, one per rank. */
  IndexSet
  even_partition(const types::global_dof_index n, const MPI_Comm communicator);
} // namespace ltn

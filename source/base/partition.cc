#include <ltn/base/partition.h>

namespace ltn
{
  IndexSet
  contiguous_partition(const types::global_dof_index n_local,
                       const MPI_Comm                communicator)
  {
    const auto counts = Utilities::MPI::all_gather(communicator, n_local);
    const auto rank   = Utilities::MPI::this_mpi_process(communicator);
    types::global_dof_index first = 0, total = 0;
    for (unsigned int r = 0; r < counts.size(); ++r)
      {
        if (r < rank)
          first += counts[r];
        total += counts[r];
      }
    IndexSet result(total);
    result.add_range(first, first + n_local);
    return result;
  }



  IndexSet
  even_partition(const types::global_dof_index n, const MPI_Comm communicator)
  {
    const types::global_dof_index ranks = Utilities::MPI::n_mpi_processes(
                                    communicator),
                                  rank = Utilities::MPI::this_mpi_process(
                                    communicator);
    IndexSet result(n);
    result.add_range(n * rank / ranks, n * (rank + 1) / ranks);
    return result;
  }
} // namespace ltn

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <ltn/base/memory.h>

#include <unistd.h>

namespace ltn
{
  double
  peak_memory_mb(const MPI_Comm comm)
  {
    dealii::Utilities::System::MemoryStats stats;
    dealii::Utilities::System::get_memory_stats(stats);
    // VmHWM is in kB.
    return dealii::Utilities::MPI::sum(stats.VmHWM / 1024., comm);
  }



  double
  physical_memory_bytes(const MPI_Comm comm)
  {
    // The ranks that share a machine's memory; the first of each counts it.
    MPI_Comm machine;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &machine);
    const bool first_on_machine =
      dealii::Utilities::MPI::this_mpi_process(machine) == 0;
    MPI_Comm_free(&machine);
    const long   pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    const double bytes = pages > 0 && page > 0 ? double(pages) * page : 0.;
    // Zero if any machine does not say.
    const double smallest = dealii::Utilities::MPI::min(bytes, comm);
    const double sum =
      dealii::Utilities::MPI::sum(first_on_machine ? bytes : 0., comm);
    return smallest > 0 ? sum : 0.;
  }
} // namespace ltn

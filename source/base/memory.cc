#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <ltn/base/memory.h>

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
} // namespace ltn

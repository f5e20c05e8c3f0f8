#pragma once

#include <mpi.h>

namespace ltn
{
  /** Peak resident memory (VmHWM) of this process, summed over @p comm, MB. */
  double
  peak_memory_mb(const MPI_Comm comm);
} // namespace ltn

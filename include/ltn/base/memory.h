#pragma once

#include <mpi.h>

namespace ltn
{
  /** Peak resident memory (VmHWM) of this process, summed over @p comm, MB. */
  double
  peak_memory_mb(const MPI_Comm comm);

  /**
   * The physical memory of the machines the ranks of @p comm run on, in
   * bytes, each machine counted once; zero where a machine does not say.
   */
  double
  physical_memory_bytes(const MPI_Comm comm);
} // namespace ltn

#pragma once

namespace ltn
{
  /**
   * Keep the BLAS library to one thread: LtN runs one MPI rank per core.
   * OpenBLAS (Debian's default BLAS) otherwise starts a thread per core, and
   * after each call those threads spin in `sched_yield`, taking the core of
   * the other rank. Without OpenBLAS this does nothing.
   */
  void
  use_one_blas_thread();
} // namespace ltn

#pragma once

#include <ltn/output/run_summary.h>

#include <ostream>

namespace ltn
{
  /**
   * Print the per-level table of a run: sizes, iterations, mismatch, and,
   * with an exact solution, the coupled errors with their observed rates.
   */
  void
  print_convergence_table(const RunSummary &summary, std::ostream &out);
} // namespace ltn

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

  /**
   * Print where the run's wall time went: each phase over all levels (the
   * `timings` of summary.json) with its share of the total, and for the
   * last level the coupled solve's own phases (reduced-space CG) with each
   * model's solves and iterations in them.
   */
  void
  print_time_per_phase(const RunSummary &summary, std::ostream &out);
} // namespace ltn

#include <ltn/output/console_table.h>

#include <boost/io/ios_state.hpp>

#include <iomanip>
#include <sstream>

namespace ltn
{
  void
  print_convergence_table(const RunSummary &summary, std::ostream &out)
  {
    const auto &levels = summary.levels;
    out << std::left << std::setw(11) << "h" << std::setw(11) << "eps"
        << std::setw(9) << "dofs_n" << std::setw(9) << "dofs_l" << std::setw(6)
        << "iter" << std::setw(11) << "J";
    if (levels.front().has_errors)
      out << std::setw(11) << "L2 error" << std::setw(7) << "rate"
          << std::setw(11) << "max error" << std::setw(7) << "rate";
    out << '\n';
    for (std::size_t l = 0; l < levels.size(); ++l)
      {
        const LevelRecord &r = levels[l];
        out << std::setprecision(4) << std::defaultfloat << std::setw(11) << r.h
            << std::setw(11) << r.horizon << std::setw(9) << r.n_nonlocal_dofs
            << std::setw(9) << r.n_local_dofs << std::setw(6)
            << r.solver.iterations << std::scientific << std::setprecision(2)
            << std::setw(11) << r.mismatch_J;
        if (r.has_errors)
          {
            const auto rate = [&](const double coarse, const double fine) {
              std::ostringstream s;
              if (l > 0)
                s << std::fixed << std::setprecision(2)
                  << observed_rate(coarse, fine, levels[l - 1].h, r.h);
              return s.str();
            };
            const ErrorNorms &c =
              (l > 0) ? levels[l - 1].coupled_errors : r.coupled_errors;
            out << std::setw(11) << r.coupled_errors.l2() << std::setw(7)
                << rate(c.l2(), r.coupled_errors.l2()) << std::setw(11)
                << r.coupled_errors.linf << std::setw(7)
                << rate(c.linf, r.coupled_errors.linf);
          }
        out << std::defaultfloat << '\n';
      }
  }



  void
  print_time_per_phase(const RunSummary &summary, std::ostream &out)
  {
    const auto &levels = summary.levels;
    if (levels.empty())
      return;
    // The caller's format comes back whichever way this returns.
    const boost::io::ios_all_saver restore(out);
    const auto                     seconds = [](const double t) {
      std::ostringstream s;
      s << std::fixed << std::setprecision(t < 10 ? 2 : 1) << t;
      return s.str();
    };
    out << "Wall time per phase, seconds (all levels; share of "
        << seconds(summary.total_time) << " s)\n";
    for (std::size_t p = 0; p < levels.front().timings.size(); ++p)
      {
        double sum = 0;
        for (const LevelRecord &level : levels)
          sum += level.timings[p].second;
        out << "  " << std::left << std::setw(22)
            << levels.front().timings[p].first << std::right << std::setw(9)
            << seconds(sum) << std::setw(7) << std::fixed
            << std::setprecision(1)
            << (summary.total_time > 0 ? 100 * sum / summary.total_time : 0.)
            << " %\n";
      }
    const LevelRecord &last = levels.back();
    if (last.solver.phases.empty())
      return;
    // Each model's solves in a phase, with its iterations where it
    // iterates (a factorized model solves without).
    const auto solves = [](const SolverStatistics::Phase &phase,
                           const unsigned int             k) {
      const ModelSolverStatistics &solver = phase.model_solvers[k];
      std::ostringstream           s;
      s << solver.solves;
      if (solver.iterations > 0)
        s << " (" << solver.iterations << ")";
      return s.str();
    };
    out << "\nThe coupled solve"
        << (levels.size() > 1 ? " of the last level" : "") << ", "
        << last.solver.iterations << " outer iterations:\n"
        << "  " << std::left << std::setw(22) << "phase" << std::right
        << std::setw(9) << "seconds" << std::setw(26)
        << "nonlocal solves (iter.)" << std::setw(24) << "local solves (iter.)"
        << '\n';
    for (const SolverStatistics::Phase &phase : last.solver.phases)
      out << "  " << std::left << std::setw(22) << phase.name << std::right
          << std::setw(9) << seconds(phase.seconds) << std::setw(26)
          << solves(phase, 0) << std::setw(24) << solves(phase, 1) << '\n';
  }
} // namespace ltn

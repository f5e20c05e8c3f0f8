#include <ltn/output/console_table.h>

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
            << std::setw(9) << r.n_local_dofs << std::setw(6) << r.iterations
            << std::scientific << std::setprecision(2) << std::setw(11)
            << r.mismatch_J;
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
} // namespace ltn

#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <iomanip>
#include <sstream>
#include <string>

namespace ltn
{
  using namespace dealii;

  /**
   * Progress lines of a run on the console (rank 0's stream): a line is
   * printed once the run has gone on for `quiet_seconds` and then at most
   * every `interval_seconds`, so that a run of a few seconds keeps its
   * short report and a long one shows, phase by phase and iteration by
   * iteration, that it advances. Each line starts with the run's wall
   * time.
   */
  class Progress
  {
  public:
    /** Silent: for callers that report nothing (tests, inner solves). */
    Progress()
      : out(nullptr)
    {}

    explicit Progress(ConditionalOStream &out,
                      const double        quiet_seconds    = 5,
                      const double        interval_seconds = 5)
      : out(&out)
      , quiet_seconds(quiet_seconds)
      , interval_seconds(interval_seconds)
    {}

    /**
     * Print the line @p make_line makes (called only then), if a line is
     * due.
     */
    template <typename MakeLine>
    void
    report(const MakeLine &make_line)
    {
      if (out == nullptr || !out->is_active())
        return;
      const double now = timer.wall_time();
      if (now < quiet_seconds || now < last_line + interval_seconds)
        return;
      last_line = now;
      // Formatted apart: the console's own format stays as its user set it.
      std::ostringstream time;
      time << std::fixed << std::setprecision(1) << now;
      *out << "  [" << time.str() << " s] " << make_line() << std::endl;
    }

  private:
    ConditionalOStream *out;
    Timer               timer;
    double              quiet_seconds    = 0;
    double              interval_seconds = 0;
    double              last_line        = -1e300;
  };
} // namespace ltn

// The run's closing tables on the console (source/output/console_table.cc):
// the wall time per phase over all levels with its share of the total, and
// the last level's coupled solve per phase with each model's solves.

#include <ltn/output/console_table.h>

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

using namespace ltn;

namespace
{
  /** The words of the line of @p text that starts with @p start. */
  std::vector<std::string>
  words_of_line(const std::string &text, const std::string &start)
  {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind(start, 0) == 0)
        {
          std::istringstream       in(line);
          std::vector<std::string> words;
          for (std::string word; in >> word;)
            words.push_back(word);
          return words;
        }
    return {};
  }

  using Words = std::vector<std::string>;

  LevelRecord
  level(const double solve_seconds, const unsigned int outer_iterations)
  {
    LevelRecord record;
    record.solver.iterations = outer_iterations;
    record.timings = {{"assemble nonlocal", 0.5}, {"solve", solve_seconds}};
    // Each model's solves and iterations in a phase.
    const auto phase = [](const std::string                &name,
                          const double                      seconds,
                          const std::array<unsigned int, 2> solves,
                          const std::array<unsigned int, 2> iterations) {
      SolverStatistics::Phase p{name, seconds, {}};
      for (const unsigned int k : {0u, 1u})
        {
          p.model_solvers[k].solves     = solves[k];
          p.model_solvers[k].iterations = iterations[k];
        }
      return p;
    };
    record.solver.phases = {
      phase("coarse space", 12.35, {{12, 78}}, {{125, 0}}),
      phase("iterations", 29.1, {{25, 13}}, {{340, 26}})};
    return record;
  }
} // namespace



TEST_CASE("the console's time per phase sums the levels and lists the last "
          "level's solve phases with each model's solves and iterations",
          "[output][unit]")
{
  RunSummary summary;
  summary.levels     = {level(3., 10), level(47.5, 12)};
  summary.total_time = 52.;

  std::ostringstream out;
  out.precision(3);
  print_time_per_phase(summary, out);
  const std::string text = out.str();
  INFO(text);

  // 0.5 + 0.5 s of assembly, 3 + 47.5 s of solve, of 52 s.
  CHECK(text.find("share of 52.0 s") != std::string::npos);
  CHECK(words_of_line(text, "  assemble nonlocal") ==
        Words{"assemble", "nonlocal", "1.00", "1.9", "%"});
  CHECK(words_of_line(text, "  solve") == Words{"solve", "50.5", "97.1", "%"});
  CHECK(text.find("of the last level, 12 outer iterations") !=
        std::string::npos);
  // A model without iterations (factorized) shows its solves alone.
  CHECK(words_of_line(text, "  coarse space") ==
        Words{"coarse", "space", "12.3", "12", "(125)", "78"});
  CHECK(words_of_line(text, "  iterations") ==
        Words{"iterations", "29.1", "25", "(340)", "13", "(26)"});
  // The caller's stream format is left as it was.
  CHECK(out.precision() == 3);
  CHECK((out.flags() & std::ios::floatfield) == std::ios::fmtflags{});

  // One level without solve phases (a direct method): the first table only.
  RunSummary direct;
  direct.levels = {level(1., 1)};
  direct.levels.front().solver.phases.clear();
  direct.total_time = 2.;
  std::ostringstream direct_out;
  print_time_per_phase(direct, direct_out);
  CHECK(direct_out.str().find("coupled solve") == std::string::npos);
  CHECK(words_of_line(direct_out.str(), "  solve") ==
        Words{"solve", "1.00", "50.0", "%"});
}

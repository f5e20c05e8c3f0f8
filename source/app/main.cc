// ltn: the command-line front end of LtN. It parses the command line, reads
// the scene, and hands everything else to the library.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <ltn/app/parameter_reading.h>
#include <ltn/app/scene_selection.h>
#include <ltn/base/blas_threads.h>
#include <ltn/base/input_error.h>
#include <ltn/base/memory.h>
#include <ltn/output/console_table.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace
{
  const char *usage =
    "usage: ltn SCENE.prm [--set \"Subsection/.../name=value\"]... "
    "[--output-dir DIR]\n"
    "       ltn --print-parameters [--json]\n";

  /**
   * A failed check (deal.II's AssertThrow, in deal.II or in LtN) for a
   * user: its message on one line, then where it was raised, for a bug
   * report; not deal.II's block of the violated condition and the stack.
   */
  std::string
  failure_message(const dealii::ExceptionBase &error)
  {
    std::ostringstream info;
    error.print_info(info);
    std::istringstream words(info.str());
    std::string        message, word;
    while (words >> word)
      message += (message.empty() ? "" : " ") + word;
    if (message.empty() || message == "(none)")
      message = error.get_exc_name();
    // what() begins "An error occurred in line <L> of file <F> in function".
    const std::string what  = error.what();
    const auto        field = [&](const std::string &before) {
      const auto begin = what.find(before);
      if (begin == std::string::npos)
        return std::string();
      const auto start = begin + before.size();
      return what.substr(start, what.find('>', start) - start);
    };
    const std::string line = field("in line <"), file = field("of file <");
    if (!file.empty())
      message += "\n  (raised at " + file + ":" + line + ")";
    return message;
  }

  struct CommandLine
  {
    std::string              scene_file;
    std::vector<std::string> sets;
    std::string              output_directory;
    bool                     print_parameters = false;
    /**
     * With --print-parameters: deal.II's JSON form, which also gives each
     * parameter's pattern (doc/prm_guide.md's table is made from it).
     */
    bool json = false;
  };

  CommandLine
  parse_command_line(const int argc, char **argv)
  {
    CommandLine command_line;
    for (int i = 1; i < argc; ++i)
      {
        const std::string argument = argv[i];
        const auto        next     = [&]() {
          ltn::check_input(i + 1 < argc,
                           argument,
                           "",
                           "a value after " + argument);
          return std::string(argv[++i]);
        };
        if (argument == "--print-parameters")
          command_line.print_parameters = true;
        else if (argument == "--json")
          command_line.json = true;
        else if (argument == "--set")
          command_line.sets.push_back(next());
        else if (argument == "--output-dir")
          command_line.output_directory = next();
        else if (argument == "--help" || argument == "-h")
          {
            std::cout << usage;
            std::exit(0);
          }
        else if (argument.rfind("--", 0) == 0 ||
                 !command_line.scene_file.empty())
          throw ltn::InputError("command line",
                                argument,
                                std::string("the arguments of\n") + usage);
        else
          command_line.scene_file = argument;
      }
    ltn::check_input(command_line.print_parameters ||
                       !command_line.scene_file.empty(),
                     "command line",
                     "",
                     std::string("a scene file\n") + usage);
    ltn::check_input(!command_line.json || command_line.print_parameters,
                     "--json",
                     "",
                     "--json only with --print-parameters");
    return command_line;
  }
  /**
   * Validate the scene (done by its constructor), and only then create its
   * output directory, run it and write the summary.
   */
  template <class Scene>
  void
  run_scene(Scene                      &scene,
            dealii::ParameterHandler   &prm,
            const CommandLine          &command_line,
            dealii::ConditionalOStream &pcout)
  {
    constexpr int dim = Scene::dimension;
    using namespace dealii;
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const std::string &scene_name = scene.get_name();

    std::string output_directory = command_line.output_directory;
    if (output_directory.empty())
      output_directory = scene.get_output_directory();
    if (output_directory.empty())
      output_directory = "output/" + scene_name;
    bool writable = true;
    if (root)
      {
        std::error_code error;
        std::filesystem::create_directories(output_directory, error);
        std::ofstream used(output_directory + "/used_parameters.prm");
        writable = !error && used.good();
        if (writable)
          prm.print_parameters(used, ParameterHandler::PRM);
      }
    // Every rank learns whether the directory is usable, and fails alike.
    ltn::check_input(Utilities::MPI::min(writable ? 1 : 0, MPI_COMM_WORLD) == 1,
                     "--output-dir (or Output/Directory)",
                     output_directory,
                     "a directory that can be created and written to");

    pcout << "LtN scene '" << scene_name << "' (" << dim << "D)" << std::endl;
    ltn::RunSummary summary = scene.run(output_directory, pcout);
    summary.memory_mb       = ltn::peak_memory_mb(MPI_COMM_WORLD);

    if (root)
      {
        std::ofstream json(output_directory + "/summary.json");
        summary.to_json().write(json);
        json << '\n';
        std::cout << '\n';
        ltn::print_convergence_table(summary, std::cout);
        std::cout << '\n';
        ltn::print_time_per_phase(summary, std::cout);
        std::cout << "\nTotal wall time " << std::setprecision(3)
                  << summary.total_time << " s, peak memory " << std::fixed
                  << std::setprecision(0) << summary.memory_mb << " MB\n"
                  << std::defaultfloat << "Output written to "
                  << output_directory << "/" << std::endl;
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ltn::use_one_blas_thread();
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  ConditionalOStream pcout(std::cout, root);

  try
    {
      const CommandLine command_line = parse_command_line(argc, argv);
      ParameterHandler  prm;
      ltn::declare_all_parameters(prm);
      if (command_line.print_parameters)
        {
          if (root)
            prm.print_parameters(std::cout,
                                 command_line.json ? ParameterHandler::JSON :
                                                     ParameterHandler::PRM);
          return 0;
        }

      ltn::read_parameters(prm, command_line.scene_file, command_line.sets);
      ltn::with_selected_scene(
        prm,
        std::filesystem::path(command_line.scene_file).stem().string(),
        [&](auto &scene) { run_scene(scene, prm, command_line, pcout); });
    }
  catch (const ltn::InputError &error)
    {
      if (root)
        std::cerr << "ltn: error: " << error.what() << std::endl;
      return 2;
    }
  catch (const dealii::ExceptionBase &error)
    {
      if (root)
        std::cerr << "ltn: failed: " << failure_message(error) << std::endl;
      return 1;
    }
  catch (const std::exception &error)
    {
      if (root)
        std::cerr << "ltn: failed: " << error.what() << std::endl;
      return 1;
    }
  return 0;
}

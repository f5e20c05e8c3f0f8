#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <ltn/app/parameter_reading.h>
#include <ltn/base/input_error.h>
#include <ltn/scene/diffusion_scene.h>
#include <ltn/scene/elasticity_scene.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace ltn
{
  void
  declare_all_parameters(ParameterHandler &prm)
  {
    // Declarations do not depend on the dimension.
    prm.declare_entry("Model",
                      "diffusion",
                      Patterns::Selection("diffusion|elasticity"),
                      "The physics of the scene: `diffusion` (nonlocal "
                      "diffusion coupled to Poisson) or `elasticity` (LPS "
                      "peridynamics coupled to Navier-Cauchy, 2D and 3D).");
    DiffusionScene<1>::declare_parameters(prm);
    ElasticityScene<2>::declare_parameters(prm);
  }



  namespace
  {
    /** The "additional information" of a deal.II exception, on one line. */
    std::string
    short_message(const std::exception &error)
    {
      std::ostringstream message;
      if (const auto *deal_error = dynamic_cast<const ExceptionBase *>(&error))
        deal_error->print_info(message);
      else
        message << error.what();
      std::string text = message.str();
      for (char &c : text)
        if (c == '\n')
          c = ' ';
      return Utilities::trim(text);
    }

    /**
     * An InputError naming @p where if @p found: the scene's data moved
     * from `Problem data` to one subsection per physics.
     */
    void
    check_no_problem_data(const bool found, const std::string &where)
    {
      check_input(!found,
                  "Problem data",
                  where,
                  "renamed, one subsection per physics: `Diffusion data` "
                  "(Model = diffusion) or `Elasticity data` (Model = "
                  "elasticity)");
    }
  } // namespace



  void
  read_parameters(ParameterHandler               &prm,
                  const std::string              &filename,
                  const std::vector<std::string> &sets)
  {
    check_input(std::ifstream(filename).good(),
                "scene file",
                filename,
                "a readable .prm file");
    {
      const std::regex old_subsection(
        R"(\s*subsection\s+Problem\s+data\s*(#.*)?)");
      std::ifstream file(filename);
      std::string   line;
      while (std::getline(file, line))
        check_no_problem_data(std::regex_match(line, old_subsection),
                              "a subsection in " + filename);
    }
    try
      {
        prm.parse_input(filename);
      }
    catch (const std::exception &error)
      {
        throw InputError("in " + filename,
                         short_message(error),
                         "every line must set a declared parameter to a "
                         "value its pattern accepts; `ltn "
                         "--print-parameters` lists them all");
      }

    for (const std::string &assignment : sets)
      {
        const auto equals = assignment.find('=');
        check_input(equals != std::string::npos,
                    "--set",
                    assignment,
                    "\"Subsection/.../name=value\"");
        std::vector<std::string> path = Utilities::split_string_list(
          Utilities::trim(assignment.substr(0, equals)), '/');
        const std::string value =
          Utilities::trim(assignment.substr(equals + 1));
        check_input(!path.empty() && !path.back().empty(),
                    "--set",
                    assignment,
                    "\"Subsection/.../name=value\" with a parameter name");
        const std::string name = path.back();
        path.pop_back();
        check_no_problem_data(!path.empty() && path[0] == "Problem data",
                              assignment);
        check_input(path.empty() || prm.subsection_path_exists(path),
                    "--set",
                    assignment,
                    "the subsection path must exist; `ltn "
                    "--print-parameters` lists them all");
        for (const std::string &subsection : path)
          prm.enter_subsection(subsection);
        try
          {
            prm.set(name, value);
          }
        catch (const std::exception &error)
          {
            for (std::size_t i = 0; i < path.size(); ++i)
              prm.leave_subsection();
            throw InputError(assignment.substr(0, equals),
                             value,
                             short_message(error) +
                               " (`ltn --print-parameters` lists every "
                               "parameter and its allowed values)");
          }
        for (std::size_t i = 0; i < path.size(); ++i)
          prm.leave_subsection();
      }
  }
} // namespace ltn

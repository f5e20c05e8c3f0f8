#include <ltn/scene/scene.h>

namespace ltn
{
  template <int dim>
  void
  Scene<dim>::declare_output_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory",
                        "",
                        Patterns::Anything(),
                        "Where the run writes its files. Empty: "
                        "output/<scene name>. The command line's "
                        "--output-dir takes precedence.");
      prm.declare_entry("Write VTU",
                        "true",
                        Patterns::Bool(),
                        "Write the fields of every level as VTU files.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  Scene<dim>::Scene(const std::string &scene_name)
    : scene_name(scene_name)
  {}



  template <int dim>
  void
  Scene<dim>::parse_parameters(ParameterHandler            &prm,
                               const std::function<void()> &parse_physics)
  {
    geometry.parse_parameters(prm);
    nonlocal_parameters.parse_parameters(prm);
    local_parameters.parse_parameters(prm);
    parse_physics();
    discretization.parse_parameters(prm);
    coupling_parameters.parse_parameters(prm);
    prm.enter_subsection("Output");
    output_directory = prm.get("Directory");
    write_vtu        = prm.get_bool("Write VTU");
    prm.leave_subsection();
  }



  template <int dim>
  const std::vector<CouplingSolution> &
  Scene<dim>::get_solutions() const
  {
    return solutions;
  }



  template <int dim>
  const std::string &
  Scene<dim>::get_output_directory() const
  {
    return output_directory;
  }

  template class Scene<1>;
  template class Scene<2>;
  template class Scene<3>;
} // namespace ltn

#include <ltn/base/input_error.h>
#include <ltn/scene/scene.h>

#include <cmath>

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
    prm.enter_subsection("Postprocess");
    {
      prm.declare_entry(
        "Model error estimate",
        "false",
        Patterns::Bool(),
        "Estimate the modeling error of a coupled 2D or 3D level: the "
        "residual of the nonlocal model on the whole body at the composite "
        "field (u_n on the nonlocal region, u_l elsewhere), near the body "
        "outside the nonlocal region, measured in energy: its short waves "
        "scaled by the operator's diagonal, its long waves through an error "
        "representer in the local model's finite elements on the whole body "
        "(doc/model_adaptivity.md). Needs the particle spacing to divide the "
        "offset of the nonlocal region from the body's lower corner.");
      prm.declare_entry(
        "True model error",
        "false",
        Patterns::Bool(),
        "Also solve the nonlocal model on the whole body at each level and "
        "report the true modeling error in energy, ||u_* - w||, and the "
        "estimate's effectivity (estimate / true error). Costs the "
        "whole-body nonlocal solve; as the estimate, a coupled 2D or 3D "
        "scene.");
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
    prm.enter_subsection("Postprocess");
    model_error_estimate = prm.get_bool("Model error estimate");
    true_model_error     = prm.get_bool("True model error");
    prm.leave_subsection();
    // The loop of `auto` marks blocks by the estimate.
    model_error_estimate = model_error_estimate || geometry.automatic_region;
    if (model_error_estimate || true_model_error)
      {
        const std::string parameter =
          geometry.automatic_region ? "Geometry/Nonlocal regions" :
          true_model_error          ? "Postprocess/True model error" :
                                      "Postprocess/Model error estimate";
        check_input(dim > 1 &&
                      geometry.models == Geometry<dim>::Models::coupled,
                    parameter,
                    "true",
                    "a coupled scene in 2D or 3D (the estimate compares the "
                    "coupled solution with the nonlocal model on the whole "
                    "body)");
        // The whole body's lattice must hold the coupled one's particles:
        // `auto`'s regions are made of blocks of whole mesh sizes.
        Tensor<1, dim> offset;
        if (geometry.automatic_region)
          for (unsigned int d = 0; d < dim; ++d)
            offset[d] = discretization.mesh_size(0);
        else
          offset = geometry.nonlocal_region().bounding_box().lower -
                   geometry.body.lower;
        for (unsigned int level = 0; level < discretization.n_levels; ++level)
          {
            const double spacing = nonlocal_parameters.particle_spacing(
              discretization.mesh_size(level));
            for (unsigned int d = 0; d < dim; ++d)
              check_input(is_whole_multiple(offset[d], spacing),
                          "Nonlocal model/Particle spacing to mesh size ratio",
                          to_string(nonlocal_parameters.spacing_ratio),
                          "with " + parameter +
                            ", a spacing that divides the offset of the "
                            "nonlocal region from the body's lower corner (" +
                            to_string(offset[d]) + ")");
          }
      }
  }



  template <int dim>
  void
  Scene<dim>::start_model_adaptivity(const std::vector<Box<dim>> &starts,
                                     const double interaction_range,
                                     const double margin)
  {
    if constexpr (dim > 1)
      {
        model_adaptivity.emplace(geometry,
                                 discretization.mesh_size(0),
                                 interaction_range,
                                 starts,
                                 margin);
        // Without a start the first cycle is the local model alone; the
        // checks run on the largest region a cycle may reach.
        geometry.set_nonlocal_boxes(starts.empty() ?
                                      model_adaptivity->largest_boxes() :
                                      model_adaptivity->region_boxes());
      }
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

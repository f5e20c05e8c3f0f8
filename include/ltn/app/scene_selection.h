#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ltn/base/input_error.h>
#include <ltn/scene/diffusion_scene.h>
#include <ltn/scene/elasticity_scene.h>

#include <string>

namespace ltn
{
  /**
   * Make the scene that the parameters @p prm select, by `Model` and
   * `Dimension`, under the name @p scene_name, and call @p action on it
   * (a callable taking any of the scene types). The one place that maps
   * the two parameters to a type: `main` and the tests both go through it.
   * A selection that names no scene type is an InputError.
   */
  template <class Action>
  void
  with_selected_scene(ParameterHandler  &prm,
                      const std::string &scene_name,
                      Action           &&action)
  {
    const int dim = prm.get_integer("Dimension");
    if (prm.get("Model") == "elasticity")
      {
        check_input(dim > 1,
                    "Dimension",
                    std::to_string(dim),
                    "2 or 3 for Model = elasticity");
        if (dim == 2)
          {
            ElasticityScene<2> scene(prm, scene_name);
            action(scene);
          }
        else
          {
            ElasticityScene<3> scene(prm, scene_name);
            action(scene);
          }
      }
    else if (dim == 1)
      {
        DiffusionScene<1> scene(prm, scene_name);
        action(scene);
      }
    else if (dim == 2)
      {
        DiffusionScene<2> scene(prm, scene_name);
        action(scene);
      }
    else
      {
        DiffusionScene<3> scene(prm, scene_name);
        action(scene);
      }
  }
} // namespace ltn

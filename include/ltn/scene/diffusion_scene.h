#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <ltn/problem/diffusion_data.h>
#include <ltn/scene/scene.h>

#include <optional>
#include <string>

namespace ltn
{
  using namespace dealii;

  /**
   * A local-to-nonlocal diffusion scene: nonlocal diffusion on `Omega_n`
   * (in 1D in weak form by finite elements, NonlocalWeakForm1D; in 2D and 3D
   * in strong form on particles, ParticleDiffusion), Poisson on `Omega_l`
   * (PoissonProblem), coupled by the optimality system (CouplingSystem) and
   * solved, level by level, by the method the `Coupling` subsection selects.
   */
  template <int dim>
  class DiffusionScene : public Scene<dim>
  {
  public:
    /** Declare the parameters of the scene and of everything it uses. */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the scene from @p prm and validate all of it, for every level,
     * before anything runs: an InputError names the first bad parameter.
     */
    DiffusionScene(ParameterHandler &prm, const std::string &scene_name);

    RunSummary
    run(const std::string &output_directory, ConditionalOStream &out) override;

  private:
    using Scene<dim>::geometry;
    using Scene<dim>::nonlocal_parameters;
    using Scene<dim>::local_parameters;
    using Scene<dim>::discretization;
    using Scene<dim>::coupling_parameters;

    DiffusionData problem_data;
    /**
     * With a blending on the particle lattice (2D, 3D): the layout as the
     * scene gives it (nonlocal region, overlap), for the blending function;
     * the scene's geometry is then the whole body, nonlocal only.
     */
    std::optional<Geometry<dim>> blended_layout;
  };
} // namespace ltn

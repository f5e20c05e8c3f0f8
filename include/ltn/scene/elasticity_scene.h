#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <ltn/problem/crack.h>
#include <ltn/problem/elasticity_data.h>
#include <ltn/problem/material.h>
#include <ltn/scene/scene.h>

#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * A local-to-nonlocal elasticity scene (2D or 3D): linearized state-based
   * peridynamics on particles of `Omega_n` (ParticleElasticity), with the
   * scene's cracks, Navier–Cauchy by finite elements on `Omega_l`
   * (ElasticityProblem), coupled by the optimality system on the overlap
   * and solved level by level. Besides errors against an exact solution it
   * measures what a user of fracture mechanics checks: the force through
   * cross-sections of the local region, the resultant of the applied loads,
   * and the opening of every crack.
   */
  template <int dim>
  class ElasticityScene : public Scene<dim>
  {
  public:
    /** Declare the parameters only elasticity scenes have. */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the scene from @p prm and validate all of it, for every level,
     * before anything runs: an InputError names the first bad parameter.
     */
    ElasticityScene(ParameterHandler &prm, const std::string &scene_name);

    RunSummary
    run(const std::string &output_directory, ConditionalOStream &out) override;

  private:
    using Scene<dim>::geometry;
    using Scene<dim>::nonlocal_parameters;
    using Scene<dim>::local_parameters;
    using Scene<dim>::discretization;
    using Scene<dim>::coupling_parameters;

    Material       material;
    CrackSet<dim>  crack_set;
    ElasticityData data;
    /** Planes `x_d = c` through which the force is measured. */
    std::vector<std::pair<unsigned int, double>> section_planes;
    std::string                                  reference_crack_opening;
  };
} // namespace ltn

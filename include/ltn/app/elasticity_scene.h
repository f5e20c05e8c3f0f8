#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <ltn/coupling/coupling_parameters.h>
#include <ltn/coupling/coupling_system.h>
#include <ltn/local/local_parameters.h>
#include <ltn/nonlocal/nonlocal_parameters.h>
#include <ltn/output/run_summary.h>
#include <ltn/scene/crack.h>
#include <ltn/scene/discretization.h>
#include <ltn/scene/elasticity_data.h>
#include <ltn/scene/geometry.h>
#include <ltn/scene/material.h>

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
  class ElasticityScene
  {
  public:
    static constexpr int dimension = dim;

    /** Declare the parameters only elasticity scenes have. */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the scene from @p prm and validate all of it, for every level,
     * before anything runs: an InputError names the first bad parameter.
     */
    ElasticityScene(ParameterHandler &prm, const std::string &scene_name);

    /**
     * Solve every level; write VTU files into @p output_directory when it is
     * not empty and `Output/Write VTU` is set. Progress goes to @p out.
     */
    RunSummary
    run(const std::string &output_directory, ConditionalOStream &out);

    /** The solution of each level of the last run (for tests). */
    const std::vector<CouplingSolution> &
    get_solutions() const;

    /** `Output/Directory`: empty unless the scene names one. */
    const std::string &
    get_output_directory() const;

  private:
    std::string          scene_name;
    Geometry<dim>        geometry;
    NonlocalParameters   nonlocal_parameters;
    LocalParameters<dim> local_parameters;
    Material             material;
    CrackSet<dim>        crack_set;
    ElasticityData       data;
    Discretization       discretization;
    CouplingParameters   coupling_parameters;
    bool                 write_vtu = true;
    std::string          output_directory;
    /** Planes `x_d = c` through which the force is measured. */
    std::vector<std::pair<unsigned int, double>> section_planes;
    std::string                                  reference_crack_opening;
    std::vector<CouplingSolution>                solutions;
  };
} // namespace ltn

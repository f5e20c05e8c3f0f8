#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <ltn/coupling/coupling_parameters.h>
#include <ltn/coupling/coupling_system.h>
#include <ltn/local/local_parameters.h>
#include <ltn/local/poisson_problem.h>
#include <ltn/nonlocal/nonlocal_parameters.h>
#include <ltn/output/run_summary.h>
#include <ltn/scene/discretization.h>
#include <ltn/scene/geometry.h>
#include <ltn/scene/problem_data.h>

#include <string>
#include <vector>

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
  class DiffusionScene
  {
  public:
    static constexpr int dimension = dim;

    /** Declare the parameters of the scene and of everything it uses. */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the scene from @p prm and validate all of it, for every level,
     * before anything runs: an InputError names the first bad parameter.
     */
    DiffusionScene(ParameterHandler &prm, const std::string &scene_name);

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
    std::string                   scene_name;
    Geometry<dim>                 geometry;
    NonlocalParameters            nonlocal_parameters;
    LocalParameters<dim>          local_parameters;
    ProblemData                   problem_data;
    Discretization                discretization;
    CouplingParameters            coupling_parameters;
    bool                          write_vtu = true;
    std::string                   output_directory;
    std::vector<CouplingSolution> solutions;
  };
} // namespace ltn

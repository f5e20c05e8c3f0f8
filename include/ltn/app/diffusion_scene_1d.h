#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <ltn/coupling/coupling_parameters.h>
#include <ltn/coupling/coupling_system.h>
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
   * The 1D local-to-nonlocal diffusion scene of the seed: nonlocal diffusion
   * in weak form (NonlocalWeakForm1D) on `Omega_n`, Poisson (PoissonProblem)
   * on `Omega_l`, coupled by the optimality system (CouplingSystem) and
   * solved, level by level, by the method the `Coupling` subsection selects.
   */
  class DiffusionScene1D
  {
  public:
    /** Declare the parameters of the scene and of everything it uses. */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the scene from @p prm and validate all of it, for every level,
     * before anything runs: an InputError names the first bad parameter.
     */
    DiffusionScene1D(ParameterHandler &prm, const std::string &scene_name);

    /**
     * Solve every level; write VTU files into @p output_directory when it is
     * not empty and `Output/Write VTU` is set. Progress and the convergence
     * table go to @p out.
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
    Geometry<1>                   geometry;
    NonlocalParameters            nonlocal_parameters;
    PoissonProblem<1>::Parameters local_parameters;
    ProblemData                   problem_data;
    Discretization                discretization;
    CouplingParameters            coupling_parameters;
    bool                          write_vtu = true;
    std::string                   output_directory;
    std::vector<CouplingSolution> solutions;
  };
} // namespace ltn

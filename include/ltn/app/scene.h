#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <ltn/app/level_solve.h>
#include <ltn/coupling/coupling_parameters.h>
#include <ltn/coupling/coupling_system.h>
#include <ltn/coupling/overlap_quadrature.h>
#include <ltn/local/local_parameters.h>
#include <ltn/nonlocal/nonlocal_parameters.h>
#include <ltn/output/field_output.h>
#include <ltn/output/nonlocal_output.h>
#include <ltn/output/run_summary.h>
#include <ltn/scene/discretization.h>
#include <ltn/scene/geometry.h>

#include <iomanip>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * What the scenes of every physics (DiffusionScene, ElasticityScene)
   * share: the parameters of the geometry, of both models, of the
   * discretization, of the coupling and of the output; and the run of a
   * level, whose models are built, refined, assembled, coupled, solved,
   * measured and written in the same order whatever the physics
   * (run_level()).
   */
  template <int dim>
  class Scene
  {
  public:
    static constexpr int dimension = dim;

    /** Declare `Output/Directory` and `Output/Write VTU`. */
    static void
    declare_output_parameters(ParameterHandler &prm);

    virtual ~Scene() = default;

    /**
     * Solve every level; write VTU files into @p output_directory when it is
     * not empty and `Output/Write VTU` is set. Progress goes to @p out.
     */
    virtual RunSummary
    run(const std::string &output_directory, ConditionalOStream &out) = 0;

    /** The solution of each level of the last run (for tests). */
    const std::vector<CouplingSolution> &
    get_solutions() const;

    /** `Output/Directory`: empty unless the scene names one. */
    const std::string &
    get_output_directory() const;

  protected:
    /**
     * Parse the subsections every scene has; the physics checks them
     * (each names what it allows).
     */
    Scene(ParameterHandler &prm, const std::string &scene_name);

    /**
     * run() for a physics whose models of a level of mesh size `h` are
     * those of `physics_of_level(h)` (run_level()); @p model names the
     * physics in the summary.
     */
    template <typename PhysicsOfLevel>
    RunSummary
    run_levels(const std::string    &model,
               const std::string    &output_directory,
               ConditionalOStream   &out,
               const PhysicsOfLevel &physics_of_level);

    std::string          scene_name;
    Geometry<dim>        geometry;
    NonlocalParameters   nonlocal_parameters;
    LocalParameters<dim> local_parameters;
    Discretization       discretization;
    CouplingParameters   coupling_parameters;
    bool                 write_vtu = true;
    std::string          output_directory;

  private:
    std::vector<CouplingSolution> solutions;

    /**
     * The VTU records written so far, per model: (step, file), for the
     * `.pvd` collections.
     */
    struct WrittenFiles
    {
      std::vector<std::pair<double, std::string>> nonlocal, local;
    };

    /**
     * Solve one level with the models @p physics builds, through every
     * adaptive cycle of the local mesh: one LevelRecord per cycle in
     * @p summary, one solution per cycle in `solutions`, VTU files into
     * @p output_directory (if not empty and `Output/Write VTU`), the progress
     * line to @p out. The physics supplies, as `Physics`:
     *
     * - the types `Nonlocal` and `Local` of its models;
     * - `h`, `eps` (the horizon), `collar_depth` (how far out of `Omega_n`
     *   its particles read: one horizon for diffusion, two for LPS);
     * - `make_nonlocal()`, `make_local()`, and `assemble()` of each model;
     * - `coupling()`: the coupling parameters of the level;
     * - `exact_solution()`: the exact solution, or null;
     * - `n_particles(nonlocal)`;
     * - `postprocess(nonlocal, local, solution, local_field, record)`: its
     *   own measurements into @p record, returning the lines of the progress
     *   report (models null where the scene has none);
     * - `nonlocal_file`, `local_file`: the VTU files' names, and
     *   `write_local(local, field, region, directory, name)`;
     * - `grouped_collection`: whether to write `scene.pvd` with both models;
     * - `dofs_label`: what the progress line calls the nonlocal unknowns.
     */
    template <typename Physics>
    void
    run_level(const Physics      &physics,
              const unsigned int  level,
              const std::string  &output_directory,
              RunSummary         &summary,
              WrittenFiles       &files,
              ConditionalOStream &out);
  };



  template <int dim>
  template <typename PhysicsOfLevel>
  RunSummary
  Scene<dim>::run_levels(const std::string    &model,
                         const std::string    &output_directory,
                         ConditionalOStream   &out,
                         const PhysicsOfLevel &physics_of_level)
  {
    Timer total_timer;
    solutions.clear();
    RunSummary summary;
    summary.scene = scene_name;
    summary.dim   = dim;
    summary.model = model;
    WrittenFiles files;
    for (unsigned int level = 0; level < discretization.n_levels; ++level)
      run_level(physics_of_level(discretization.mesh_size(level)),
                level,
                output_directory,
                summary,
                files,
                out);
    summary.total_time = total_timer.wall_time();
    return summary;
  }



  template <int dim>
  template <typename Physics>
  void
  Scene<dim>::run_level(const Physics      &physics,
                        const unsigned int  level,
                        const std::string  &output_directory,
                        RunSummary         &summary,
                        WrittenFiles       &files,
                        ConditionalOStream &out)
  {
    const double h = physics.h, eps = physics.eps;
    // The models of the scene: both, or one on the whole body. The local
    // mesh may be refined adaptively within a level.
    std::unique_ptr<typename Physics::Nonlocal> nonlocal;
    std::unique_ptr<typename Physics::Local>    local;
    CouplingSolution                            solution;
    const unsigned int                          cycles =
      geometry.has_local_model() ? local_parameters.adaptive_cycles : 0;
    for (unsigned int cycle = 0; cycle <= cycles; ++cycle)
      {
        ConditionalOStream silent(out.get_stream(), false);
        TimerOutput timer(silent, TimerOutput::never, TimerOutput::wall_times);
        LevelRecord record;
        record.h       = h;
        record.horizon = eps;
        record.cycle   = cycle;

        timer.enter_subsection("setup meshes");
        if (cycle == 0)
          {
            if (geometry.has_nonlocal_model())
              nonlocal = physics.make_nonlocal();
            if (geometry.has_local_model())
              local = physics.make_local();
          }
        else
          {
            // In 2D/3D the particles of the overlap, out to the collar's
            // depth, observe the local field: its cells there keep at least
            // p particle spacings (see NonlocalParameters::
            // validate_particles()).
            const double spacing = nonlocal_parameters.particle_spacing(h);
            local->refine(solution.fields[local_model],
                          [&](const Point<dim> &center, const double size) {
                            return dim == 1 || !nonlocal ||
                                   !geometry.in_overlap(center,
                                                        physics.collar_depth +
                                                          size) ||
                                   size / 2 >= local_parameters.degree *
                                                 spacing * (1 - 1e-12);
                          });
          }
        timer.leave_subsection();

        if (nonlocal && cycle == 0)
          {
            timer.enter_subsection("assemble nonlocal");
            physics.assemble(*nonlocal);
            timer.leave_subsection();
          }
        if (local)
          {
            timer.enter_subsection("assemble local");
            physics.assemble(*local);
            timer.leave_subsection();
          }

        OverlapQuadrature<dim> overlap;
        if (nonlocal && local)
          {
            timer.enter_subsection("assemble coupling");
            overlap = create_overlap_quadrature(geometry,
                                                eps,
                                                *nonlocal,
                                                local->get_dof_handler());
            timer.leave_subsection();
          }
        timer.enter_subsection("solve");
        solution = solve_level(nonlocal ? &nonlocal->get_model() : nullptr,
                               local ? &local->get_model() : nullptr,
                               overlap,
                               physics.coupling(),
                               record);
        timer.leave_subsection();
        solutions.push_back(solution);

        timer.enter_subsection("postprocess");
        record.n_nonlocal_dofs =
          nonlocal ? nonlocal->get_model().owned.size() : 0;
        record.n_local_dofs = local ? local->get_dof_handler().n_dofs() : 0;
        record.n_particles  = nonlocal ? physics.n_particles(*nonlocal) : 0;
        const TrilinosWrappers::MPI::Vector local_field =
          local ? local->get_model().ghosted(solution.fields[local_model]) :
                  TrilinosWrappers::MPI::Vector();
        const Function<dim> *exact = physics.exact_solution();
        if (exact)
          {
            const ErrorNorms nonlocal_errors =
              nonlocal ?
                nonlocal->errors(solution.fields[nonlocal_model], *exact) :
                ErrorNorms();
            record_errors<dim>(nonlocal ? &nonlocal_errors : nullptr,
                               local ? &local->get_dof_handler() : nullptr,
                               local_field,
                               *exact,
                               geometry.nonlocal_region,
                               geometry.tolerance(),
                               record);
          }
        const std::string report = physics.postprocess(
          nonlocal.get(), local.get(), solution, local_field, record);
        timer.leave_subsection();

        if (!output_directory.empty() && write_vtu)
          {
            timer.enter_subsection("output");
            // One file per solve: level, or level and adaptive cycle.
            const unsigned int step = summary.levels.size();
            const std::string  suffix =
              "_level-" + Utilities::int_to_string(step, 2);
            const std::string directory = output_directory + "/";
            if (nonlocal)
              {
                files.nonlocal.emplace_back(
                  step,
                  write_nonlocal_vtu(*nonlocal,
                                     solution.fields[nonlocal_model],
                                     exact,
                                     output_directory,
                                     physics.nonlocal_file + suffix));
                write_level_collection(directory + physics.nonlocal_file +
                                         ".pvd",
                                       files.nonlocal);
              }
            if (local)
              {
                files.local.emplace_back(step,
                                         physics.write_local(
                                           *local,
                                           local_field,
                                           [&](const Point<dim> &p) {
                                             return geometry.local_region_of(
                                               p, physics.collar_depth);
                                           },
                                           output_directory,
                                           physics.local_file + suffix));
                write_level_collection(directory + physics.local_file + ".pvd",
                                       files.local);
              }
            if (physics.grouped_collection)
              write_grouped_collection(directory + "scene.pvd",
                                       {files.nonlocal, files.local});
            timer.leave_subsection();
          }
        record_timings(timer, record);

        out << "level " << level
            << (cycle > 0 ? ", cycle " + std::to_string(cycle) : std::string())
            << ": h = " << h << ", eps = " << eps << ", " << physics.dofs_label
            << " = " << record.n_nonlocal_dofs
            << ", local dofs = " << record.n_local_dofs
            << ", controls = " << record.n_controls
            << ", iterations = " << record.iterations
            << ", J = " << std::scientific << std::setprecision(3)
            << record.mismatch_J << std::defaultfloat << std::endl
            << report;
        summary.levels.push_back(record);
      }
  }
} // namespace ltn

#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <ltn/base/progress.h>
#include <ltn/coupling/solvers/coupling_parameters.h>
#include <ltn/coupling/system/coupling_system.h>
#include <ltn/local/local_parameters.h>
#include <ltn/nonlocal/nonlocal_parameters.h>
#include <ltn/output/run_summary.h>
#include <ltn/problem/discretization.h>
#include <ltn/problem/geometry.h>
#include <ltn/scene/model_adaptivity.h>
#include <ltn/scene/model_error.h>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * What the level of every physics (Scene::run_level()) reads of its
   * scene: the geometry, both models' parameters and the coupling's, and
   * the level's mesh size.
   */
  template <int dim>
  struct SceneLevel
  {
    const Geometry<dim>        &geometry;
    const NonlocalParameters   &nonlocal_parameters;
    const LocalParameters<dim> &local_parameters;
    const CouplingParameters   &coupling_parameters;
    const double                h;
  };



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

    /** The scene's name: its file's, without the extension. */
    const std::string &
    get_name() const
    {
      return scene_name;
    }

    /** `Output/Directory`: empty unless the scene names one. */
    const std::string &
    get_output_directory() const;

  protected:
    explicit Scene(const std::string &scene_name);

    /**
     * Parse the subsections every scene has, and the physics' own with
     * @p parse_physics, called between the local model's and the
     * discretization's (the order in which a bad value is reported first);
     * the physics then checks them (each names what it allows).
     */
    void
    parse_parameters(ParameterHandler            &prm,
                     const std::function<void()> &parse_physics);

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

    /**
     * For `Geometry/Nonlocal regions = auto`: the loop's blocks and its
     * start from @p starts (a box per crack) grown by @p margin beyond the
     * overlap, for a nonlocal model whose collar is @p interaction_range
     * deep on the coarsest level; `Omega_n` becomes the start (without
     * starts, the largest region a cycle may reach, which the checks then
     * see; the first cycle is the local model alone). Call after
     * parse_parameters(), before the geometry is validated.
     */
    void
    start_model_adaptivity(const std::vector<Box<dim>> &starts,
                           const double                 interaction_range,
                           const double                 margin);

    /** What the level of mesh size @p h reads of this scene. */
    SceneLevel<dim>
    level(const double h) const
    {
      return {geometry,
              nonlocal_parameters,
              local_parameters,
              coupling_parameters,
              h};
    }

    std::string          scene_name;
    Geometry<dim>        geometry;
    NonlocalParameters   nonlocal_parameters;
    LocalParameters<dim> local_parameters;
    Discretization       discretization;
    CouplingParameters   coupling_parameters;
    bool                 write_vtu = true;
    /** `Postprocess/Model error estimate`. */
    bool model_error_estimate = false;
    /** `Postprocess/True model error`. */
    bool        true_model_error = false;
    std::string output_directory;
    /** With `Geometry/Nonlocal regions = auto`. */
    std::optional<ModelAdaptivity<dim>> model_adaptivity;

  private:
    std::vector<CouplingSolution> solutions;

    /**
     * What the model-error estimate of a level builds whatever the region
     * (built by the level's first estimate, kept by the model-adaptivity
     * loop for all its cycles): the nonlocal model on the whole body, with
     * its solution for the true error, the local model on the whole body
     * (the long waves' representer), and ModelErrorOperators.
     */
    template <typename Physics>
    struct LevelReference
    {
      /** The layouts of the two models, and the representer's parameters
       * (which the models keep references to). */
      Geometry<dim>                               whole_body, local_body;
      LocalParameters<dim>                        representer_parameters;
      std::unique_ptr<typename Physics::Nonlocal> nonlocal;
      std::unique_ptr<typename Physics::Local>    representer;
      CouplingSolution                            solution;
      ModelErrorOperators                         operators;
    };

    /**
     * The VTU records written so far, per model: (step, file), for the
     * `.pvd` collections.
     */
    struct WrittenFiles
    {
      std::vector<std::pair<double, std::string>> nonlocal, local, model_error;
    };

    /**
     * Solve one level with the models @p physics builds, through every
     * adaptive cycle of the local mesh: one LevelRecord per cycle in
     * @p summary, one solution per cycle in `solutions`, VTU files into
     * @p output_directory (if not empty and `Output/Write VTU`), the progress
     * line to @p out. Its phases, once the run is long, go to @p progress. The physics supplies, as `Physics`:
     *
     * - the types `Nonlocal` and `Local` of its models;
     * - `h`, `eps` (the horizon), `collar_depth` (how far out of `Omega_n`
     *   its particles read: one horizon for diffusion, two for LPS);
     * - `make_nonlocal()`, `make_local(layout, parameters)`, and
     *   `assemble()` of each model
     *   (of the nonlocal one with the operator matrix-free or not);
     * - `coupling()`: the coupling parameters of the level, whose `auto`
     *   choices run_level() resolves (choose_solvers());
     * - `exact_solution()`: the exact solution, or null;
     * - `n_particles(nonlocal)`;
     * - `postprocess(nonlocal, local, solution, local_field, record)`: its
     *   own measurements into @p record, returning the lines of the progress
     *   report (models null where the scene has none);
     * - `nonlocal_file`, `local_file`: the VTU files' names, and
     *   `write_local(local, field, region, directory, name)`;
     * - `grouped_collection`: whether to write `scene.pvd` with both models;
     * - `dofs_label`: what the progress line calls the nonlocal unknowns.
     *
     * @p label names the solve in the progress ("level 0", "level 0, model
     * cycle 2"); @p region_reference is passed to the model-error estimate,
     * which builds its reference into @p reference if given (to be kept
     * for the next region), else its own. Returns the estimate's terms of
     * the last adaptive cycle (empty without an estimate).
     */
    template <typename Physics>
    ModelErrorField<dim>
    run_level(const Physics                       &physics,
              const std::string                   &label,
              const std::string                   &output_directory,
              RunSummary                          &summary,
              WrittenFiles                        &files,
              ConditionalOStream                  &out,
              Progress                            &progress,
              const TrilinosWrappers::MPI::Vector *region_reference = nullptr,
              LevelReference<Physics>             *reference        = nullptr);

    /**
     * The first level under `Geometry/Nonlocal regions = auto`: a
     * run_level() per model cycle, each on the region the previous one's
     * estimate grew, until the estimate meets the tolerance (or the loop
     * stops otherwise); the cycles into `summary.model_adaptivity`. With
     * `Postprocess/True model error`, first the coupled solve on the
     * largest admissible region, the reference of each cycle's true error.
     */
    template <typename Physics>
    void
    run_model_cycles(const Physics      &physics,
                     const std::string  &output_directory,
                     RunSummary         &summary,
                     WrittenFiles       &files,
                     ConditionalOStream &out,
                     Progress           &progress);

    /**
     * The model-error estimate of a coupled level (2D, 3D; @p nonlocal null
     * where the local model covers the body) whose models @p nonlocal and
     * @p local have the solution @p solution (@p local_field
     * its local part, ghosted): against the level's nonlocal model on the
     * whole body, built into @p reference unless there, and solved with
     * `Postprocess/True model error`, and against @p region_reference if not
     * null. The terms point
     * by point go to @p field.
     */
    template <typename Physics>
    ModelErrorRecord
    estimate_level_model_error(
      const Physics                       &physics,
      const typename Physics::Nonlocal    *nonlocal,
      const typename Physics::Local       &local,
      const CouplingSolution              &solution,
      const TrilinosWrappers::MPI::Vector &local_field,
      const TrilinosWrappers::MPI::Vector *region_reference,
      LevelReference<Physics>             &reference,
      Progress                            &progress,
      ModelErrorField<dim>                &field) const;
  };
} // namespace ltn

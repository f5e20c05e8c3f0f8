#pragma once

// The definitions of Scene's member templates, for the scenes' own source
// files: the level loop needs the output and overlap functions, which
// the scenes' users (main, the tests) do not.

#include <deal.II/base/timer.h>

#include <ltn/base/field_errors.h>
#include <ltn/coupling/system/blending_nodes.h>
#include <ltn/coupling/system/control_traces.h>
#include <ltn/coupling/system/overlap_quadrature.h>
#include <ltn/output/field_output.h>
#include <ltn/output/nonlocal_output.h>
#include <ltn/output/parallel_vtu.h>
#include <ltn/output/point_cloud_output.h>
#include <ltn/scene/level_solve.h>
#include <ltn/scene/scene.h>
#include <ltn/scene/solver_choice.h>

#include <iomanip>
#include <memory>
#include <type_traits>

namespace ltn
{
  namespace internal
  {
    /**
     * The bonds per particle of the nonlocal model @p nonlocal, for
     * choose_solvers(): its stencil's on a particle lattice; none for the
     * 1D weak form, which is always factorized.
     */
    template <typename Nonlocal>
    std::size_t
    bonds_per_particle(const Nonlocal &nonlocal)
    {
      if constexpr (std::is_same_v<Nonlocal, NonlocalWeakForm1D>)
        return 0;
      else
        return nonlocal.bonds_per_particle();
    }
  } // namespace internal

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
    Progress     progress(out);
    for (unsigned int level = 0; level < discretization.n_levels; ++level)
      if (level == 0 && model_adaptivity)
        run_model_cycles(physics_of_level(discretization.mesh_size(level)),
                         output_directory,
                         summary,
                         files,
                         out,
                         progress);
      else
        run_level(physics_of_level(discretization.mesh_size(level)),
                  "level " + std::to_string(level),
                  output_directory,
                  summary,
                  files,
                  out,
                  progress);
    summary.total_time = total_timer.wall_time();
    return summary;
  }



  template <int dim>
  template <typename Physics>
  void
  Scene<dim>::run_model_cycles(const Physics      &physics,
                               const std::string  &output_directory,
                               RunSummary         &summary,
                               WrittenFiles       &files,
                               ConditionalOStream &out,
                               Progress           &progress)
  {
    ModelAdaptivity<dim>  &loop   = *model_adaptivity;
    ModelAdaptivityRecord &record = summary.model_adaptivity;
    record.enabled                = true;
    record.tolerance              = geometry.model_error_tolerance;
    record.block_size             = loop.block_size();
    // One estimate's reference for every region of the level.
    LevelReference<Physics> reference;
    ModelErrorField<dim>    largest;
    if (true_model_error)
      {
        // The reference: its own summary, files and solutions, none kept
        // but its composite field.
        geometry.models = Geometry<dim>::Models::coupled;
        geometry.set_nonlocal_boxes(loop.largest_boxes());
        RunSummary        scratch;
        WrittenFiles      none;
        const std::size_t n_solutions = solutions.size();
        largest                       = run_level(physics,
                            "level 0, largest region (reference)",
                            "",
                            scratch,
                            none,
                            out,
                            progress,
                            nullptr,
                            &reference);
        solutions.resize(n_solutions);
      }
    for (unsigned int cycle = 0;; ++cycle)
      {
        // An empty region (no crack to start from): the local model alone.
        const std::vector<Box<dim>> boxes = loop.region_boxes();
        geometry.models = boxes.empty() ? Geometry<dim>::Models::local_only :
                                          Geometry<dim>::Models::coupled;
        if (!boxes.empty())
          geometry.set_nonlocal_boxes(boxes);
        const ModelErrorField<dim> field =
          run_level(physics,
                    "level 0, model cycle " + std::to_string(cycle),
                    output_directory,
                    summary,
                    files,
                    out,
                    progress,
                    true_model_error ? &largest.composite : nullptr,
                    &reference);
        ModelCycleRecord entry;
        entry.level_entry        = summary.levels.size() - 1;
        const LevelRecord &level = summary.levels.back();
        entry.particles          = level.n_particles;
        for (const Box<dim> &box : boxes)
          {
            std::vector<double> corners;
            for (const Point<dim> &corner : {box.lower, box.upper})
              for (unsigned int d = 0; d < dim; ++d)
                corners.push_back(corner[d]);
            entry.boxes.push_back(corners);
          }
        const bool go_on =
          loop.adapt(level.model_error, field.block_indicators, cycle, entry);
        out << "model cycle " << cycle << ": " << entry.blocks << " blocks in "
            << boxes.size() << (boxes.size() == 1 ? " box, " : " boxes, ")
            << entry.particles << " particles, estimate " << std::scientific
            << std::setprecision(2) << entry.estimate << " (tolerance "
            << geometry.model_error_tolerance << ")";
        if (level.model_error.has_region_error)
          out << ", true " << level.model_error.region_relative
              << ", effectivity " << std::defaultfloat << std::setprecision(3)
              << level.model_error.region_effectivity;
        out << std::defaultfloat;
        if (go_on)
          out << ", marked " << entry.marked << ", added " << entry.added
              << std::endl;
        else
          out << "; stopped: " << entry.stopped << std::endl;
        record.cycles.push_back(entry);
        if (!go_on)
          break;
      }
  }



  template <int dim>
  template <typename Physics>
  ModelErrorField<dim>
  Scene<dim>::run_level(const Physics                       &physics,
                        const std::string                   &label,
                        const std::string                   &output_directory,
                        RunSummary                          &summary,
                        WrittenFiles                        &files,
                        ConditionalOStream                  &out,
                        Progress                            &progress,
                        const TrilinosWrappers::MPI::Vector *region_reference,
                        LevelReference<Physics>             *reference)
  {
    const double h = physics.h, eps = physics.eps;
    // The models of the scene: both, or one on the whole body. The local
    // mesh may be refined adaptively within a level.
    // A mesh is graded towards a nonlocal region only (the local model
    // alone: a cycle of `auto` without a start).
    LocalParameters<dim> level_local_parameters = local_parameters;
    if (!geometry.has_nonlocal_model())
      level_local_parameters.graded_mesh_layers = 0;
    std::unique_ptr<typename Physics::Nonlocal> nonlocal;
    std::unique_ptr<typename Physics::Local>    local;
    CouplingSolution                            solution;
    SolverChoice                                choice;
    const unsigned int                          cycles =
      geometry.has_local_model() ? local_parameters.adaptive_cycles : 0;
    ModelErrorField<dim> model_error_field;
    // The estimate's reference: the caller's, or the level's own.
    LevelReference<Physics>  own_reference;
    LevelReference<Physics> &level_reference =
      reference ? *reference : own_reference;
    for (unsigned int cycle = 0; cycle <= cycles; ++cycle)
      {
        ConditionalOStream silent(out.get_stream(), false);
        TimerOutput timer(silent, TimerOutput::never, TimerOutput::wall_times);
        // Each phase of the level announced, once the run is long.
        const auto enter = [&](const std::string &phase) {
          progress.report([&] { return label + ": " + phase; });
          timer.enter_subsection(phase);
        };
        LevelRecord record;
        record.h       = h;
        record.horizon = eps;
        record.cycle   = cycle;

        enter("setup meshes");
        if (cycle == 0)
          {
            if (geometry.has_nonlocal_model())
              nonlocal = physics.make_nonlocal(geometry);
            if (geometry.has_local_model())
              local = physics.make_local(geometry, level_local_parameters);
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

        if (cycle == 0)
          {
            choice =
              choose_solvers(physics.coupling(),
                             nonlocal_parameters.operator_storage,
                             nonlocal ? nonlocal->get_model().owned.size() : 0,
                             nonlocal ?
                               internal::bonds_per_particle(*nonlocal) :
                               0,
                             dim,
                             nonlocal && local);
            if (!choice.description.empty())
              out << label << ": " << choice.description << std::endl;
            if (!choice.note.empty())
              out << "note: " << choice.note << std::endl;
          }
        if (nonlocal && cycle == 0)
          {
            enter("assemble nonlocal");
            physics.assemble(*nonlocal, choice.matrix_free);
            timer.leave_subsection();
          }
        if (local)
          {
            enter("assemble local");
            physics.assemble(*local);
            timer.leave_subsection();
          }

        const CouplingParameters &coupling = choice.coupling;
        OverlapQuadrature<dim>    overlap;
        if (nonlocal && local)
          {
            enter("assemble coupling");
            overlap = create_overlap_quadrature(geometry,
                                                eps,
                                                *nonlocal,
                                                local->get_dof_handler());
            if (coupling.method == CouplingMethod::alternating_schwarz ||
                coupling.method == CouplingMethod::alternating_schwarz_aitken)
              add_control_traces(overlap,
                                 *nonlocal,
                                 local->get_model(),
                                 local->get_dof_handler());
            if constexpr (dim == 1)
              if (coupling.method == CouplingMethod::force_blending ||
                  coupling.method == CouplingMethod::energy_blending)
                {
                  add_blending_nodes(overlap,
                                     geometry,
                                     *nonlocal,
                                     local->get_dof_handler());
                  if (coupling.method == CouplingMethod::energy_blending)
                    overlap.blending_nodes.energy =
                      physics.weighted_forms(*nonlocal, *local);
                }
            timer.leave_subsection();
          }
        enter("solve");
        solution = solve_level(nonlocal ? &nonlocal->get_model() : nullptr,
                               local ? &local->get_model() : nullptr,
                               overlap,
                               coupling,
                               record,
                               progress);
        timer.leave_subsection();
        solutions.push_back(solution);

        enter("postprocess");
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
                               geometry.nonlocal_region(),
                               geometry.tolerance(),
                               record);
          }
        const std::string report = physics.postprocess(
          nonlocal.get(), local.get(), solution, local_field, record);
        timer.leave_subsection();

        model_error_field = ModelErrorField<dim>();
        // Each point's block indicator, for the output of a model cycle.
        std::vector<double> block_indicator;
        if constexpr (dim > 1)
          if (model_error_estimate || true_model_error)
            {
              enter("model error estimate");
              record.model_error =
                estimate_level_model_error(physics,
                                           nonlocal.get(),
                                           *local,
                                           solution,
                                           local_field,
                                           region_reference,
                                           level_reference,
                                           progress,
                                           model_error_field);
              if (model_adaptivity)
                {
                  model_error_field.block_indicators =
                    model_adaptivity->block_indicators(model_error_field,
                                                       MPI_COMM_WORLD);
                  for (const Point<dim> &p : model_error_field.points)
                    block_indicator.push_back(
                      model_error_field
                        .block_indicators[model_adaptivity->block_of(p)]);
                }
              timer.leave_subsection();
            }

        if (!output_directory.empty() && write_vtu)
          {
            enter("output");
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
            if constexpr (dim > 1)
              if (record.model_error.computed)
                {
                  std::vector<std::pair<std::string, std::vector<double>>>
                    fields{
                      {"model_error_indicator", model_error_field.indicator},
                      {"boundary_layer", model_error_field.boundary_layer}};
                  if (model_adaptivity)
                    fields.emplace_back("block_indicator", block_indicator);
                  PointCloudOutput<dim> points(model_error_field.points,
                                               fields);
                  files.model_error.emplace_back(
                    step,
                    write_parallel_vtu(points,
                                       output_directory,
                                       "model_error" + suffix,
                                       MPI_COMM_WORLD));
                  write_level_collection(directory + "model_error.pvd",
                                         files.model_error);
                }
            if (physics.grouped_collection)
              write_grouped_collection(directory + "scene.pvd",
                                       {files.nonlocal, files.local});
            timer.leave_subsection();
          }
        record_timings(timer, record);

        out << label
            << (cycle > 0 ? ", cycle " + std::to_string(cycle) : std::string())
            << ": h = " << h << ", eps = " << eps << ", " << physics.dofs_label
            << " = " << record.n_nonlocal_dofs
            << ", local dofs = " << record.n_local_dofs
            << ", controls = " << record.n_controls
            << ", iterations = " << record.solver.iterations
            << ", J = " << std::scientific << std::setprecision(3)
            << record.mismatch_J << std::defaultfloat << std::endl
            << report;
        if (record.model_error.computed)
          out << "  model error estimate: " << std::scientific
              << std::setprecision(3) << record.model_error.estimate
              << " (short waves " << record.model_error.estimate_short
              << ", long " << record.model_error.estimate_long << "), relative "
              << record.model_error.relative;
        if (record.model_error.has_true_error)
          out << "; true error " << record.model_error.true_error
              << ", relative " << record.model_error.true_relative
              << ", effectivity " << std::defaultfloat << std::setprecision(3)
              << record.model_error.effectivity;
        if (record.model_error.computed)
          out << std::defaultfloat << std::endl;
        summary.levels.push_back(record);
      }
    return model_error_field;
  }



  template <int dim>
  template <typename Physics>
  ModelErrorRecord
  Scene<dim>::estimate_level_model_error(
    const Physics                       &physics,
    const typename Physics::Nonlocal    *nonlocal,
    const typename Physics::Local       &local,
    const CouplingSolution              &solution,
    const TrilinosWrappers::MPI::Vector &local_field,
    const TrilinosWrappers::MPI::Vector *region_reference,
    LevelReference<Physics>             &reference,
    Progress                            &progress,
    ModelErrorField<dim>                &field) const
  {
    if (!reference.nonlocal)
      {
        // The nonlocal model of the level on the whole body: the reference
        // whose residual at the composite field is the estimate's, solved
        // for the true error.
        reference.whole_body        = geometry;
        reference.whole_body.models = Geometry<dim>::Models::nonlocal_only;
        reference.whole_body.set_nonlocal_boxes({geometry.body});
        reference.nonlocal = physics.make_nonlocal(reference.whole_body);
        const SolverChoice choice =
          choose_solvers(physics.coupling(),
                         nonlocal_parameters.operator_storage,
                         reference.nonlocal->get_model().owned.size(),
                         internal::bonds_per_particle(*reference.nonlocal),
                         dim,
                         false);
        physics.assemble(*reference.nonlocal,
                         !true_model_error || choice.matrix_free);
        if (true_model_error)
          {
            LevelRecord reference_record;
            reference.solution = solve_level(&reference.nonlocal->get_model(),
                                             nullptr,
                                             OverlapQuadrature<dim>(),
                                             choice.coupling,
                                             reference_record,
                                             progress);
          }
        // The long waves' representer: the local model of the level on the
        // whole body, on the level's uniform mesh (no hanging nodes).
        reference.local_body             = geometry;
        reference.local_body.models      = Geometry<dim>::Models::local_only;
        reference.representer_parameters = local_parameters;
        reference.representer_parameters.graded_mesh_layers = 0;
        reference.representer =
          physics.make_local(reference.local_body,
                             reference.representer_parameters);
        physics.assemble(*reference.representer);
      }
    std::array<bool, 2 * dim> dirichlet;
    for (unsigned int f = 0; f < 2 * dim; ++f)
      dirichlet[f] = physics.fully_dirichlet(f);
    return estimate_model_error(geometry,
                                nonlocal,
                                solution.fields[nonlocal_model],
                                local.get_dof_handler(),
                                local_field,
                                *reference.nonlocal,
                                physics.collar_depth,
                                dirichlet,
                                true_model_error ?
                                  &reference.solution.fields[nonlocal_model] :
                                  nullptr,
                                region_reference,
                                &reference.representer->get_dof_handler(),
                                &reference.representer->get_model(),
                                reference.operators,
                                &field);
  }
} // namespace ltn

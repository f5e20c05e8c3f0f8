#include <deal.II/base/timer.h>

#include <ltn/app/diffusion_scene.h>
#include <ltn/app/level_solve.h>
#include <ltn/base/field_errors.h>
#include <ltn/base/input_error.h>
#include <ltn/coupling/overlap_quadrature.h>
#include <ltn/nonlocal/nonlocal_weak_form_1d.h>
#include <ltn/nonlocal/particle_diffusion.h>
#include <ltn/output/field_output.h>
#include <ltn/output/nonlocal_output.h>
#include <ltn/scene/elasticity_data.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <type_traits>

namespace ltn
{
  namespace
  {
    /** The nonlocal discretization of a dimension. */
    template <int dim>
    using NonlocalDiffusion =
      std::conditional_t<dim == 1, NonlocalWeakForm1D, ParticleDiffusion<dim>>;

    template <int dim>
    std::unique_ptr<NonlocalDiffusion<dim>>
    make_nonlocal(const Geometry<dim>      &geometry,
                  const Kernel             &kernel,
                  const NonlocalParameters &parameters,
                  const double              h,
                  const MPI_Comm            communicator)
    {
      if constexpr (dim == 1)
        return std::make_unique<NonlocalWeakForm1D>(geometry,
                                                    kernel,
                                                    parameters.degree,
                                                    h);
      else
        return std::make_unique<ParticleDiffusion<dim>>(
          geometry, kernel, parameters.particle_spacing(h), communicator);
    }
  } // namespace



  template <int dim>
  void
  DiffusionScene<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "1",
                      Patterns::Integer(1, 3),
                      "Space dimension of the scene.");
    Geometry<dim>::declare_parameters(prm);
    NonlocalParameters::declare_parameters(prm);
    LocalParameters<dim>::declare_parameters(prm);
    ProblemData::declare_parameters(prm);
    Discretization::declare_parameters(prm);
    CouplingParameters::declare_parameters(prm);
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
  }



  template <int dim>
  DiffusionScene<dim>::DiffusionScene(ParameterHandler  &prm,
                                      const std::string &scene_name)
    : scene_name(scene_name)
  {
    Assert(prm.get_integer("Dimension") == dim, ExcInternalError());
    geometry.parse_parameters(prm);
    nonlocal_parameters.parse_parameters(prm);
    local_parameters.parse_parameters(prm);
    problem_data.parse_parameters(prm);
    discretization.parse_parameters(prm);
    coupling_parameters.parse_parameters(prm);
    check_input(dim > 1 || !nonlocal_parameters.matrix_free,
                "Nonlocal model/Operator",
                "matrix-free",
                "`assembled` in 1D (its nonlocal model is a finite element "
                "weak form, not a particle lattice)");
    check_input(
      dim > 1 || coupling_parameters.controls.collar_layer_weight == 0,
      "Coupling/Collar layer weight",
      std::to_string(coupling_parameters.controls.collar_layer_weight),
      "0 or `auto` in 1D (the weight comes from the particle lattice's "
      "surrogate of 2D and 3D models)");
    check_input(dim > 1 ||
                  !coupling_parameters.controls.surrogate_nonlocal_block,
                "Coupling/Nonlocal control block",
                "surrogate extension",
                "`diagonal` in 1D (the surrogate lives on the particle "
                "lattice of 2D and 3D models)");
    coupling_parameters.check_operator(nonlocal_parameters.matrix_free,
                                       geometry.has_local_model() &&
                                         geometry.has_nonlocal_model());
    prm.enter_subsection("Output");
    output_directory = prm.get("Directory");
    write_vtu        = prm.get_bool("Write VTU");
    prm.leave_subsection();

    check_input(local_parameters.dirichlet_components.empty(),
                "Local model/Dirichlet components",
                local_parameters.dirichlet_components_text,
                "empty in a diffusion scene: only elasticity scenes have "
                "components");

    const double h0 = discretization.mesh_size(0);
    // The largest horizon of the study is on the coarsest level.
    const double eps0 = nonlocal_parameters.horizon(h0);
    geometry.validate(h0, eps0, eps0);
    local_parameters.validate(geometry);

    if constexpr (dim > 1)
      if (geometry.has_nonlocal_model())
        nonlocal_parameters.validate_particles(geometry,
                                               local_parameters.degree,
                                               h0);
    // What only elasticity scenes use must not be set here.
    ElasticityData::check_unused(prm);

    check_input(!local_parameters.dirichlet_faces.empty(),
                "Local model/Dirichlet boundaries",
                "",
                "at least one face: with Neumann conditions alone the "
                "solution is only determined up to a constant");

    // A study must stay within what a mesh can hold.
    const double finest = discretization.mesh_size(discretization.n_levels - 1);
    for (unsigned int d = 0; d < dim; ++d)
      check_input((geometry.body.upper[d] - geometry.body.lower[d]) / finest <=
                    1e5,
                  "Discretization/Mesh size",
                  to_string(h0),
                  "the finest level (mesh size " + to_string(finest) +
                    ") may have at most 1e5 cells across the body");

    // Nonlocal Neumann conditions cannot be prescribed: where Omega_n touches
    // the body's boundary, its collar needs the volume constraint.
    for (unsigned int face = 0; face < 2 * dim; ++face)
      check_input(!geometry.has_nonlocal_model() ||
                    !geometry.nonlocal_face_on_body_boundary(face) ||
                    local_parameters.dirichlet_faces.count(face) == 1,
                  "Local model/Dirichlet boundaries",
                  Geometry<dim>::face_name(face) + " missing",
                  "the nonlocal region touches face " +
                    Geometry<dim>::face_name(face) +
                    " of the body, whose collar needs the volume constraint: "
                    "list it among the Dirichlet boundaries (put Neumann "
                    "conditions on faces of the local region only)");

    for (unsigned int level = 0; level < discretization.n_levels; ++level)
      {
        const double h = discretization.mesh_size(level);
        problem_data.functions<dim>(nonlocal_parameters.kernel(dim, h), h);
      }
  }



  template <int dim>
  RunSummary
  DiffusionScene<dim>::run(const std::string  &output_directory,
                           ConditionalOStream &out)
  {
    Timer total_timer;
    solutions.clear();
    // 2D and 3D models are distributed over all ranks; the 1D ones are
    // serial (p4est has no 1D meshes), every rank solving all of it.
    const MPI_Comm communicator = (dim == 1) ? MPI_COMM_SELF : MPI_COMM_WORLD;

    RunSummary summary;
    summary.scene = scene_name;
    summary.dim   = dim;
    summary.model = "diffusion";

    std::vector<std::pair<double, std::string>> nonlocal_files, local_files;

    for (unsigned int level = 0; level < discretization.n_levels; ++level)
      {
        const double h      = discretization.mesh_size(level);
        const Kernel kernel = nonlocal_parameters.kernel(dim, h);
        const double eps    = kernel.horizon();
        const auto   data   = problem_data.functions<dim>(kernel, h);

        // The models of the scene: both, or one on the whole body. The local
        // mesh may be refined adaptively within a level.
        std::unique_ptr<NonlocalDiffusion<dim>> nonlocal;
        std::unique_ptr<PoissonProblem<dim>>    local;
        CouplingSolution                        solution;

        for (unsigned int cycle = 0;
             cycle <= (geometry.has_local_model() ?
                         local_parameters.adaptive_cycles :
                         0);
             ++cycle)
          {
            ConditionalOStream silent(out.get_stream(), false);
            TimerOutput        timer(silent,
                              TimerOutput::never,
                              TimerOutput::wall_times);
            LevelRecord        record;
            record.h       = h;
            record.horizon = eps;
            record.cycle   = cycle;

            timer.enter_subsection("setup meshes");
            if (cycle == 0)
              {
                if (geometry.has_nonlocal_model())
                  nonlocal = make_nonlocal<dim>(
                    geometry, kernel, nonlocal_parameters, h, communicator);
                if (geometry.has_local_model())
                  local = std::make_unique<PoissonProblem<dim>>(
                    geometry, local_parameters, h, communicator);
              }
            else
              // In 2D/3D the particles of the overlap observe the local field:
              // its cells there keep at least p particle spacings (see the
              // check of the spacing in the constructor).
              local->refine(solution.fields[local_model],
                            [&](const Point<dim> &center, const double size) {
                              return dim == 1 || !nonlocal ||
                                     !geometry.in_overlap(center, eps + size) ||
                                     size / 2 >=
                                       local_parameters.degree *
                                         nonlocal_parameters.particle_spacing(
                                           h) *
                                         (1 - 1e-12);
                            });
            timer.leave_subsection();

            if (nonlocal && cycle == 0)
              {
                timer.enter_subsection("assemble nonlocal");
                if constexpr (dim == 1)
                  nonlocal->assemble(*data.nonlocal_rhs,
                                     *data.volume_constraint_data);
                else
                  nonlocal->assemble(*data.nonlocal_rhs,
                                     *data.volume_constraint_data,
                                     nonlocal_parameters.matrix_free);
                timer.leave_subsection();
              }
            if (local)
              {
                timer.enter_subsection("assemble local");
                local->assemble(*data.local_rhs,
                                *data.boundary_data,
                                *data.boundary_gradient);
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
                                   coupling_parameters,
                                   record);
            timer.leave_subsection();
            solutions.push_back(solution);

            timer.enter_subsection("postprocess");
            record.n_nonlocal_dofs =
              nonlocal ? nonlocal->get_model().owned.size() : 0;
            record.n_local_dofs = local ? local->get_dof_handler().n_dofs() : 0;
            record.n_particles  = record.n_nonlocal_dofs;
            if (data.exact_solution)
              {
                const ErrorNorms nonlocal_errors =
                  nonlocal ? nonlocal->errors(solution.fields[nonlocal_model],
                                              *data.exact_solution) :
                             ErrorNorms();
                record_errors<dim>(nonlocal ? &nonlocal_errors : nullptr,
                                   local ? &local->get_dof_handler() : nullptr,
                                   local ? local->get_model().ghosted(
                                             solution.fields[local_model]) :
                                           TrilinosWrappers::MPI::Vector(),
                                   *data.exact_solution,
                                   geometry.nonlocal_region,
                                   geometry.tolerance(),
                                   record);
              }
            timer.leave_subsection();

            if (!output_directory.empty() && write_vtu)
              {
                timer.enter_subsection("output");
                // One file per solve: level, or level and adaptive cycle.
                const unsigned int step = summary.levels.size();
                const std::string  suffix =
                  "_level-" + Utilities::int_to_string(step, 2);
                if (nonlocal)
                  {
                    nonlocal_files.emplace_back(
                      step,
                      write_nonlocal_vtu(*nonlocal,
                                         solution.fields[nonlocal_model],
                                         data.exact_solution.get(),
                                         output_directory,
                                         "nonlocal_field" + suffix));
                    write_level_collection(output_directory +
                                             "/nonlocal_field.pvd",
                                           nonlocal_files);
                  }
                if (local)
                  {
                    local_files.emplace_back(
                      step,
                      write_field_vtu<dim>(
                        local->get_dof_handler(),
                        local->get_model().ghosted(
                          solution.fields[local_model]),
                        data.exact_solution.get(),
                        [&](const Point<dim> &p) {
                          return geometry.local_region_of(p, eps);
                        },
                        output_directory,
                        "local_field" + suffix));
                    write_level_collection(output_directory +
                                             "/local_field.pvd",
                                           local_files);
                  }
                timer.leave_subsection();
              }

            record_timings(timer, record);

            out << "level " << level
                << (cycle > 0 ? ", cycle " + std::to_string(cycle) :
                                std::string())
                << ": h = " << h << ", eps = " << eps
                << ", nonlocal dofs = " << record.n_nonlocal_dofs
                << ", local dofs = " << record.n_local_dofs
                << ", controls = " << record.n_controls
                << ", iterations = " << record.iterations
                << ", J = " << std::scientific << std::setprecision(3)
                << record.mismatch_J << std::defaultfloat << std::endl;
            summary.levels.push_back(record);
          }
      }
    summary.total_time = total_timer.wall_time();
    return summary;
  }



  template <int dim>
  const std::vector<CouplingSolution> &
  DiffusionScene<dim>::get_solutions() const
  {
    return solutions;
  }



  template <int dim>
  const std::string &
  DiffusionScene<dim>::get_output_directory() const
  {
    return output_directory;
  }

  template class DiffusionScene<1>;
  template class DiffusionScene<2>;
  template class DiffusionScene<3>;
} // namespace ltn

#include <ltn/base/input_error.h>
#include <ltn/local/poisson_problem.h>
#include <ltn/nonlocal/nonlocal_weak_form_1d.h>
#include <ltn/nonlocal/particle_diffusion.h>
#include <ltn/problem/elasticity_data.h>
#include <ltn/scene/diffusion_scene.h>
#include <ltn/scene/scene.templates.h>

#include <functional>
#include <memory>
#include <type_traits>

namespace ltn
{
  namespace
  {
    /** The problem's functions of the level with mesh size @p h and kernel
     * @p kernel, whose horizon and plane-wave symbol the expressions use. */
    template <int dim>
    DiffusionData::Functions<dim>
    level_functions(const DiffusionData &data,
                    const Kernel        &kernel,
                    const double         h)
    {
      return data.functions<dim>(
        kernel.horizon(),
        [&kernel](const double k) { return kernel.plane_wave_symbol(k); },
        h);
    }

    /** The nonlocal discretization of a dimension. */
    template <int dim>
    using NonlocalDiffusion =
      std::conditional_t<dim == 1, NonlocalWeakForm1D, ParticleDiffusion<dim>>;

    /**
     * A level of a diffusion scene, for Scene::run_level(). Neither copied
     * nor moved (its parsed functions are const): it is made where it is
     * returned, `return DiffusionLevel{...}`.
     */
    template <int dim>
    struct DiffusionLevel : SceneLevel<dim>
    {
      using Nonlocal = NonlocalDiffusion<dim>;
      using Local    = PoissonProblem<dim>;
      using SceneLevel<dim>::geometry;
      using SceneLevel<dim>::nonlocal_parameters;
      using SceneLevel<dim>::local_parameters;
      using SceneLevel<dim>::coupling_parameters;
      using SceneLevel<dim>::h;

      const MPI_Comm                      communicator;
      const Kernel                        kernel;
      const DiffusionData::Functions<dim> data;
      /**
       * With a blending on the particle lattice (2D, 3D): the layout of the
       * nonlocal region and the overlap, for the blending function; the
       * level's own geometry is the whole body. Null otherwise.
       */
      const Geometry<dim>  *blended_layout;
      const double          eps                = kernel.horizon();
      const double          collar_depth       = eps;
      const std::string     nonlocal_file      = "nonlocal_field";
      const std::string     local_file         = "local_field";
      const std::string     dofs_label         = "nonlocal dofs";
      static constexpr bool grouped_collection = false;

      /** The level's nonlocal model on @p layout (kept alive by the caller). */
      std::unique_ptr<Nonlocal>
      make_nonlocal(const Geometry<dim> &layout) const
      {
        if constexpr (dim == 1)
          return std::make_unique<NonlocalWeakForm1D>(
            layout, kernel, nonlocal_parameters.degree, h);
        else
          return std::make_unique<ParticleDiffusion<dim>>(
            layout,
            kernel,
            nonlocal_parameters.particle_spacing(h),
            communicator);
      }

      /**
       * The level's local model on @p layout with @p parameters (kept alive
       * by the caller).
       */
      std::unique_ptr<Local>
      make_local(const Geometry<dim>        &layout,
                 const LocalParameters<dim> &parameters) const
      {
        return std::make_unique<Local>(layout, parameters, h, communicator);
      }

      void
      assemble(Nonlocal                   &nonlocal,
               [[maybe_unused]] const bool matrix_free) const
      {
        if constexpr (dim == 1)
          nonlocal.assemble(*data.nonlocal_rhs, *data.volume_constraint_data);
        else if (blended_layout)
          nonlocal.assemble_blended(coupling_parameters.method ==
                                        CouplingMethod::force_blending ?
                                      LatticeBlending::force :
                                      LatticeBlending::energy,
                                    BlendingFunction<dim>(*blended_layout),
                                    *data.nonlocal_rhs,
                                    *data.local_rhs,
                                    *data.volume_constraint_data);
        else
          nonlocal.assemble(*data.nonlocal_rhs,
                            *data.volume_constraint_data,
                            matrix_free);
      }

      /** Is face @p face of the body a Dirichlet face? */
      bool
      fully_dirichlet(const unsigned int face) const
      {
        return local_parameters.dirichlet_faces.count(face) == 1;
      }

      void
      assemble(Local &local) const
      {
        local.assemble(*data.local_rhs,
                       *data.boundary_data,
                       *data.boundary_gradient);
      }

      const CouplingParameters &
      coupling() const
      {
        return coupling_parameters;
      }

      /**
       * The weighted forms of energy-based blending (1D): the nonlocal
       * model's with `beta`, the local model's with `1 - beta`.
       */
      std::array<std::shared_ptr<const WeightedForm>, 2>
      weighted_forms(const Nonlocal &nonlocal, const Local &local) const
      {
        const BlendingFunction<dim>                        beta(geometry);
        std::array<std::shared_ptr<const WeightedForm>, 2> forms;
        forms[nonlocal_model] = std::make_shared<const WeightedForm>(
          nonlocal.weighted_form(*data.nonlocal_rhs, beta));
        forms[local_model] = std::make_shared<const WeightedForm>(
          local.weighted_form(*data.local_rhs, beta));
        return forms;
      }

      const Function<dim> *
      exact_solution() const
      {
        return data.exact_solution.get();
      }

      types::global_dof_index
      n_particles(const Nonlocal &nonlocal) const
      {
        return nonlocal.get_model().owned.size();
      }

      /** Diffusion measures nothing beyond the errors. */
      std::string
      postprocess(const Nonlocal *,
                  const Local *,
                  const CouplingSolution &,
                  const TrilinosWrappers::MPI::Vector &,
                  LevelRecord &) const
      {
        return "";
      }

      std::string
      write_local(const Local                                     &local,
                  const TrilinosWrappers::MPI::Vector             &field,
                  const std::function<Region(const Point<dim> &)> &region_of,
                  const std::string                               &directory,
                  const std::string                               &name) const
      {
        return write_field_vtu<dim>(local.get_dof_handler(),
                                    field,
                                    exact_solution(),
                                    region_of,
                                    directory,
                                    name);
      }
    };
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
    DiffusionData::declare_parameters(prm);
    Discretization::declare_parameters(prm);
    CouplingParameters::declare_parameters(prm);
    Scene<dim>::declare_output_parameters(prm);
  }



  template <int dim>
  DiffusionScene<dim>::DiffusionScene(ParameterHandler  &prm,
                                      const std::string &scene_name)
    : Scene<dim>(scene_name)
  {
    Assert(prm.get_integer("Dimension") == dim, ExcInternalError());
    this->parse_parameters(prm, [&] { problem_data.parse_parameters(prm); });
    check_input(dim > 1 || nonlocal_parameters.operator_storage !=
                             OperatorStorage::matrix_free,
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
    coupling_parameters.check_physics(true);
    coupling_parameters.check_operator(nonlocal_parameters.operator_storage ==
                                         OperatorStorage::matrix_free,
                                       geometry.has_local_model() &&
                                         geometry.has_nonlocal_model());
    // Blending in 1D identifies the two meshes' nodes by position.
    const CouplingMethod method   = coupling_parameters.method;
    const bool           blending = coupling_parameters.blending();
    const std::string    method_name =
      selection_name(coupling_method_names(), method);
    check_input(!blending || dim > 1 ||
                  nonlocal_parameters.degree == local_parameters.degree,
                "Local model/Finite element degree",
                std::to_string(local_parameters.degree),
                "the nonlocal model's degree (" +
                  std::to_string(nonlocal_parameters.degree) + ") with " +
                  method_name +
                  ": its field lives on the nodes both meshes "
                  "share");
    check_input(!blending || dim > 1 || local_parameters.adaptive_cycles == 0 ||
                  !geometry.has_nonlocal_model(),
                "Local model/Adaptive refinement cycles",
                std::to_string(local_parameters.adaptive_cycles),
                "0 with " + method_name +
                  ": its field lives on the nodes both meshes share");
    check_input(
      (method != CouplingMethod::energy_blending && !(blending && dim > 1)) ||
        local_parameters.dirichlet_faces.size() == 2 * dim,
      "Local model/Dirichlet boundaries",
      std::to_string(local_parameters.dirichlet_faces.size()) + " faces",
      "every face of the body with " + method_name +
        (dim == 1 ? " (its weighted local energy carries no "
                    "boundary flux)" :
                    " (on the particle lattice of the body, whose "
                    "collar carries the boundary data)"));
    // On the lattice, blending replaces the particle model's rows: they
    // must be assembled, and solved by a factorization (force blending's
    // are not symmetric).
    check_input(!blending || dim == 1 ||
                  nonlocal_parameters.operator_storage !=
                    OperatorStorage::matrix_free,
                "Nonlocal model/Operator",
                "matrix-free",
                "`assembled` or `auto` with " + method_name +
                  " (its rows are not the shared stencil's)");
    check_input(!blending || dim == 1 ||
                  !coupling_parameters.model_solvers.iterative(),
                "Coupling/Model solvers",
                selection_name(model_solver_names(),
                               coupling_parameters.model_solvers.kind),
                "`direct` or `auto` with " + method_name +
                  " (one factorization of the blended rows)");
    check_input(!blending || !geometry.automatic_region,
                "Geometry/Nonlocal regions",
                "auto",
                "boxes with " + method_name +
                  " (its blending function needs the region)");
    check_input(local_parameters.dirichlet_components.empty(),
                "Local model/Dirichlet components",
                local_parameters.dirichlet_components_text,
                "empty in a diffusion scene: only elasticity scenes have "
                "components");

    const double h0 = discretization.mesh_size(0);
    // The largest horizon of the study is on the coarsest level.
    const double eps0 = nonlocal_parameters.horizon(h0);
    if (geometry.automatic_region)
      // No cracks: the loop starts from the local model alone.
      this->start_model_adaptivity({}, eps0, 3 * eps0);
    geometry.validate(h0, eps0, eps0);
    local_parameters.validate(geometry);
    if (blending && dim > 1)
      {
        // One field on the lattice of the whole body; the region and the
        // overlap stay in the blending function's layout.
        blended_layout  = geometry;
        geometry.models = Geometry<dim>::Models::nonlocal_only;
        geometry.set_nonlocal_boxes({geometry.body});
      }

    if constexpr (dim > 1)
      if (geometry.has_nonlocal_model())
        {
          nonlocal_parameters.validate_particles(geometry,
                                                 local_parameters.degree,
                                                 h0);
          // One unknown per particle, a collar one horizon deep.
          nonlocal_parameters.check_particle_count(
            geometry,
            discretization.mesh_size(discretization.n_levels - 1),
            1,
            1,
            MPI_COMM_WORLD);
        }
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
        level_functions<dim>(problem_data,
                             nonlocal_parameters.kernel(dim, h),
                             h);
      }
  }



  template <int dim>
  RunSummary
  DiffusionScene<dim>::run(const std::string  &output_directory,
                           ConditionalOStream &out)
  {
    return this->run_levels(
      "diffusion", output_directory, out, [&](const double h) {
        const Kernel kernel = nonlocal_parameters.kernel(dim, h);
        // 2D and 3D models are distributed over all ranks; the 1D ones are
        // serial (p4est has no 1D meshes), every rank solving all of it.
        return DiffusionLevel<dim>{this->level(h),
                                   (dim == 1) ? MPI_COMM_SELF : MPI_COMM_WORLD,
                                   kernel,
                                   level_functions<dim>(problem_data,
                                                        kernel,
                                                        h),
                                   blended_layout ? &*blended_layout : nullptr};
      });
  }



  template class DiffusionScene<1>;
  template class DiffusionScene<2>;
  template class DiffusionScene<3>;
} // namespace ltn

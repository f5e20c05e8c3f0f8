#include <ltn/base/discrete_model.h>
#include <ltn/base/input_error.h>
#include <ltn/local/elasticity_problem.h>
#include <ltn/nonlocal/particle_elasticity.h>
#include <ltn/output/elasticity_output.h>
#include <ltn/output/fracture_measurements.h>
#include <ltn/problem/diffusion_data.h>
#include <ltn/scene/elasticity_scene.h>
#include <ltn/scene/scene.templates.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <memory>
#include <sstream>

namespace ltn
{
  namespace
  {
    /**
     * The opening fields of @p cracks for the coarse level (`Crack opening
     * coarse fields`, doc/discretization.md, 'A coarse level for the
     * controls'): per crack and
     * per direction t along it (orthonormal; its edges' in 3D), the
     * displacement n (n.(x - c)) (t.(x - c))^2, n its normal, c its centre.
     */
    template <int dim>
    std::vector<AffineProductField>
    crack_opening_fields(const std::vector<Crack<dim>> &cracks)
    {
      const auto to_array = [](const Tensor<1, dim> &v) {
        return DiscreteModel::padded<dim>(Point<dim>(v));
      };
      std::vector<AffineProductField> fields;
      for (const Crack<dim> &crack : cracks)
        {
          Point<dim>                  centre = crack.corners[0];
          std::vector<Tensor<1, dim>> along;
          for (unsigned int e = 1; e < dim; ++e)
            {
              Tensor<1, dim> edge = crack.corners[e] - crack.corners[0];
              centre += 0.5 * edge;
              for (const Tensor<1, dim> &t : along)
                edge -= (edge * t) * t;
              along.push_back(edge / edge.norm());
            }
          const Tensor<1, dim> normal = crack.normal();
          // g.x + h = g.(x - c).
          const auto about_centre = [&](const Tensor<1, dim> &g) {
            return std::make_pair(to_array(g), -(g * centre));
          };
          for (const Tensor<1, dim> &t : along)
            fields.push_back(
              {to_array(normal),
               {about_centre(normal), about_centre(t), about_centre(t)}});
        }
      return fields;
    }



    /** "x=0.5, y=1" into (direction, coordinate) pairs. */
    template <int dim>
    std::vector<std::pair<unsigned int, double>>
    parse_section_planes(const std::string   &text,
                         const Geometry<dim> &geometry,
                         const double         h)
    {
      const Box<dim>                              &body = geometry.body;
      std::vector<std::pair<unsigned int, double>> planes;
      const std::string parameter = "Postprocess/Section planes";
      for (const std::string &item : Utilities::split_string_list(text))
        {
          const auto        parts = Utilities::split_string_list(item, '=');
          const std::string axes  = "xyz";
          const auto        d     = parts.size() == 2 && parts[0].size() == 1 ?
                                      axes.find(parts[0][0]) :
                                      std::string::npos;
          double            c     = 0;
          bool              ok    = d < dim;
          try
            {
              std::size_t end = 0;
              c               = ok ? std::stod(parts[1], &end) : 0;
              ok              = ok && end == parts[1].size();
            }
          catch (const std::exception &)
            {
              ok = false;
            }
          check_input(ok,
                      parameter,
                      item,
                      "planes `axis=coordinate` with an axis among the "
                      "first " +
                        std::to_string(dim) + " of x, y, z");
          check_input(c > body.lower[d] && c < body.upper[d],
                      parameter,
                      item,
                      "planes that cut the body, strictly between " +
                        to_string(body.lower[d]) + " and " +
                        to_string(body.upper[d]));
          const double cells = (c - body.lower[d]) / h;
          check_input(std::abs(cells - std::round(cells)) < 1e-8 * cells,
                      parameter,
                      item,
                      "planes of mesh faces: coordinates at whole multiples "
                      "of the mesh size " +
                        to_string(h) + " from the body's lower corner");
          check_input(geometry.has_local_model(),
                      parameter,
                      item,
                      "no planes: they are measured on the local model, "
                      "which a `nonlocal only` scene does not have");
          // The local mesh has a hole where only the nonlocal model lives:
          // a plane through it would miss part of the force.
          if (geometry.has_nonlocal_model())
            {
              std::string holes;
              for (const auto &[lower, upper] :
                   geometry.nonlocal_region().shrunk_extent(d))
                holes += (holes.empty() ? "" : " and ") + to_string(lower) +
                         " < " + "xyz"[d] + " < " + to_string(upper);
              check_input(!geometry.nonlocal_region().shrunk_region_crosses(d,
                                                                            c),
                          parameter,
                          item,
                          "planes that the local mesh covers whole: outside " +
                            holes + ", where only the nonlocal model lives");
            }
          planes.emplace_back(d, c);
        }
      return planes;
    }

    /**
     * `Postprocess/Reference crack opening` @p text with the constants of
     * @p material and of a level of horizon @p eps and mesh size @p h.
     */
    template <int dim>
    std::unique_ptr<Expression<dim>>
    reference_opening(const std::string &text,
                      const Material    &material,
                      const double       eps,
                      const double       h)
    {
      return std::make_unique<Expression<dim>>(
        "Postprocess/Reference crack opening",
        text,
        std::map<std::string, double>{{"E", material.youngs_modulus},
                                      {"nu", material.poisson_ratio},
                                      {"lambda", material.lambda(dim)},
                                      {"mu", material.mu()},
                                      {"Eprime", material.crack_modulus(dim)},
                                      {"pi", numbers::PI},
                                      {"eps", eps},
                                      {"h", h}});
    }

    /**
     * A level of an elasticity scene, for Scene::run_level(). Neither
     * copied nor moved (its parsed functions are const): it is made where
     * it is returned, `return ElasticityLevel{...}`.
     */
    template <int dim>
    struct ElasticityLevel : SceneLevel<dim>
    {
      using Nonlocal = ParticleElasticity<dim>;
      using Local    = ElasticityProblem<dim>;
      using SceneLevel<dim>::geometry;
      using SceneLevel<dim>::nonlocal_parameters;
      using SceneLevel<dim>::local_parameters;
      using SceneLevel<dim>::coupling_parameters;
      using SceneLevel<dim>::h;

      const Material                                     &material;
      const CrackSet<dim>                                &crack_set;
      const std::vector<std::pair<unsigned int, double>> &section_planes;
      const std::string                   &reference_crack_opening;
      const Kernel                         influence;
      const ElasticityData::Functions<dim> f;
      const double                         eps = influence.horizon();
      // LPS reads two horizons out: the dilatations of the particles next to
      // Omega_n need their own neighbourhoods.
      const double          collar_depth       = 2 * eps;
      const std::string     nonlocal_file      = "particles";
      const std::string     local_file         = "local_mesh";
      const std::string     dofs_label         = "particle dofs";
      static constexpr bool grouped_collection = true;

      /** The level's nonlocal model on @p layout (kept alive by the caller). */
      std::unique_ptr<Nonlocal>
      make_nonlocal(const Geometry<dim> &layout) const
      {
        return std::make_unique<Nonlocal>(layout,
                                          influence,
                                          nonlocal_parameters.particle_spacing(
                                            h),
                                          material.lambda(dim),
                                          material.mu(),
                                          crack_set.cracks,
                                          MPI_COMM_WORLD);
      }

      /**
       * The level's local model on @p layout with @p parameters (kept alive
       * by the caller).
       */
      std::unique_ptr<Local>
      make_local(const Geometry<dim>        &layout,
                 const LocalParameters<dim> &parameters) const
      {
        return std::make_unique<Local>(layout,
                                       parameters,
                                       material.lambda(dim),
                                       material.mu(),
                                       h,
                                       MPI_COMM_WORLD);
      }

      void
      assemble(Nonlocal &nonlocal, const bool matrix_free) const
      {
        nonlocal.assemble(*f.body_force,
                          *f.volume_constraint_data,
                          matrix_free);
      }

      /** Is face @p face of the body Dirichlet in every component? */
      bool
      fully_dirichlet(const unsigned int face) const
      {
        return local_parameters.dirichlet_mask(face, dim)
                 .n_selected_components() == dim;
      }

      void
      assemble(Local &local) const
      {
        local.assemble(*f.body_force,
                       *f.boundary_data,
                       *f.traction,
                       *f.pressure);
      }

      CouplingParameters
      coupling() const
      {
        return coupling_parameters.at_lps_level(geometry.overlap_width / eps,
                                                crack_opening_fields(
                                                  crack_set.cracks),
                                                dim);
      }

      const Function<dim> *
      exact_solution() const
      {
        return f.exact_solution.get();
      }

      types::global_dof_index
      n_particles(const Nonlocal &nonlocal) const
      {
        return nonlocal.get_lattice().n_particles();
      }

      /**
       * What a user of fracture mechanics checks: the force through the
       * section planes, the resultant of the applied loads, the opening of
       * every crack (into `record.extras`, and the report's lines).
       */
      std::string
      postprocess(const Nonlocal                      *nonlocal,
                  const Local                         *local,
                  const CouplingSolution              &solution,
                  const TrilinosWrappers::MPI::Vector &local_field,
                  LevelRecord                         &record) const;

      std::string
      write_local(const Local                                     &local,
                  const TrilinosWrappers::MPI::Vector             &field,
                  const std::function<Region(const Point<dim> &)> &region_of,
                  const std::string                               &directory,
                  const std::string                               &name) const
      {
        return write_elasticity_vtu<dim>(local.get_dof_handler(),
                                         field,
                                         material,
                                         exact_solution(),
                                         region_of,
                                         directory,
                                         name);
      }
    };



    template <int dim>
    std::string
    ElasticityLevel<dim>::postprocess(
      const Nonlocal                      *nonlocal,
      const Local                         *local,
      const CouplingSolution              &solution,
      const TrilinosWrappers::MPI::Vector &local_field,
      LevelRecord                         &record) const
    {
      JsonValue   mechanics = JsonValue::object();
      std::string report;
      if (local)
        {
          report += measure_section_forces(*local,
                                           local_field,
                                           section_planes,
                                           geometry.body,
                                           mechanics["section_forces"]);
          report += measure_applied_forces(*local,
                                           local_parameters,
                                           *f.traction,
                                           *f.pressure,
                                           mechanics["applied_forces"]);
        }
      if (nonlocal)
        {
          std::unique_ptr<Expression<dim>> reference;
          if (!reference_crack_opening.empty())
            reference =
              reference_opening<dim>(reference_crack_opening, material, eps, h);
          report += measure_crack_openings(*nonlocal,
                                           solution.fields[nonlocal_model],
                                           crack_set.cracks.size(),
                                           reference.get(),
                                           mechanics["crack_openings"]);
        }
      record.extras = mechanics;
      return report;
    }
  } // namespace



  template <int dim>
  void
  ElasticityScene<dim>::declare_parameters(ParameterHandler &prm)
  {
    Material::declare_parameters(prm);
    CrackSet<dim>::declare_parameters(prm);
    ElasticityData::declare_parameters(prm);
    prm.enter_subsection("Postprocess");
    {
      prm.declare_entry("Section planes",
                        "",
                        Patterns::Anything(),
                        "Elasticity: planes of the local region, as "
                        "`x=0.5, x=3.5`, through which the force (the "
                        "integral of sigma e_x over the plane's faces) and "
                        "the mean stress are reported. Each must be a plane "
                        "of mesh faces.");
      prm.declare_entry("Reference crack opening",
                        "",
                        Patterns::Anything(),
                        "Elasticity: an expression of x, y, z for the normal "
                        "opening of every crack, e.g. the classical "
                        "`4*sigma/Eprime*sqrt(a^2 - x^2)` of a crack of "
                        "length 2a (constants: E, nu, lambda, mu, Eprime = "
                        "the plane-strain or plane-stress modulus of the "
                        "classical profile, pi, eps, h). The summary reports "
                        "the relative L2 difference of the computed "
                        "opening. Empty: none.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  ElasticityScene<dim>::ElasticityScene(ParameterHandler  &prm,
                                        const std::string &scene_name)
    : Scene<dim>(scene_name)
  {
    this->parse_parameters(prm, [&] {
      material.parse_parameters(prm);
      crack_set.parse_parameters(prm);
      data.parse_parameters(prm);
      // What only diffusion scenes use must not be set here.
      DiffusionData::check_unused(prm);
    });
    coupling_parameters.check_physics(false);
    coupling_parameters.check_operator(nonlocal_parameters.operator_storage ==
                                         OperatorStorage::matrix_free,
                                       geometry.has_local_model() &&
                                         geometry.has_nonlocal_model());
    prm.enter_subsection("Postprocess");
    const std::string planes = prm.get("Section planes");
    reference_crack_opening  = prm.get("Reference crack opening");
    prm.leave_subsection();

    const double h0 = discretization.mesh_size(0);
    // LPS reaches two horizons: the collar must hold the dilatations'
    // neighbourhoods of the particles next to Omega_n.
    const double eps0 = nonlocal_parameters.horizon(h0);
    // The outermost collar particles lie two stencil radii R = round(eps/h_p)
    // out, centres (2 R - 1/2) h_p from Omega_n: more than 2 eps when eps/h_p
    // is just above a half-integer.
    const double spacing0 = nonlocal_parameters.particle_spacing(h0);
    const double radius   = std::floor(eps0 / spacing0 + 0.5);
    const double range    = std::max(2 * eps0, (2 * radius - 0.5) * spacing0);
    if (geometry.automatic_region)
      {
        // Each crack in the part of the start left to the nonlocal model
        // alone, three horizons beyond its overlap band.
        std::vector<Box<dim>> starts;
        for (const Crack<dim> &crack : crack_set.cracks)
          starts.push_back(crack.bounding_box());
        this->start_model_adaptivity(starts, range, 3 * eps0);
      }
    geometry.validate(h0, range, eps0);
    local_parameters.validate(geometry);
    if (geometry.has_nonlocal_model())
      {
        nonlocal_parameters.validate_particles(geometry,
                                               local_parameters.degree,
                                               h0);
        // The displacement and the dilatation, a collar two horizons deep.
        nonlocal_parameters.check_particle_count(geometry,
                                                 discretization.mesh_size(
                                                   discretization.n_levels - 1),
                                                 2,
                                                 dim + 1,
                                                 MPI_COMM_WORLD);
      }
    section_planes = parse_section_planes<dim>(planes, geometry, h0);
    if (this->model_adaptivity)
      {
        // A section plane may cross the overlap band, not the part of the
        // region left to the nonlocal model alone: `auto` keeps away.
        std::vector<Box<dim>> plane_boxes;
        for (const auto &[axis, coordinate] : section_planes)
          {
            Box<dim> plane    = geometry.body;
            plane.lower[axis] = coordinate;
            plane.upper[axis] = coordinate;
            plane_boxes.push_back(plane);
          }
        this->model_adaptivity->keep_away_from(plane_boxes);
      }
    check_input(!local_parameters.dirichlet_faces.empty(),
                "Local model/Dirichlet boundaries",
                "",
                "at least one face: with tractions alone the displacement "
                "is only determined up to a rigid motion");
    // Rigid translations must be held: each component fixed on some face.
    for (unsigned int component = 0; component < dim; ++component)
      {
        bool fixed = false;
        for (const unsigned int face : local_parameters.dirichlet_faces)
          fixed =
            fixed || local_parameters.dirichlet_mask(face, dim)[component];
        check_input(fixed || !geometry.has_local_model(),
                    "Local model/Dirichlet components",
                    local_parameters.dirichlet_components_text,
                    std::string("a Dirichlet condition on the ") +
                      "xyz"[component] +
                      " displacement on some face: without one the body "
                      "can move freely along " +
                      "xyz"[component] + " and the system is singular");
      }
    // Nonlocal Neumann conditions cannot be prescribed: where Omega_n
    // touches the body's boundary, its collar needs the volume constraint
    // of every component.
    for (unsigned int face = 0; face < 2 * dim; ++face)
      check_input(
        !geometry.has_nonlocal_model() ||
          !geometry.nonlocal_face_on_body_boundary(face) ||
          local_parameters.dirichlet_mask(face, dim).n_selected_components() ==
            dim,
        "Local model/Dirichlet boundaries",
        Geometry<dim>::face_name(face) + " missing",
        "the nonlocal region touches face " + Geometry<dim>::face_name(face) +
          " of the body, whose collar needs the volume constraint "
          "of every displacement component: list it among the "
          "Dirichlet boundaries, with all components (put "
          "tractions and pressures on faces of the local region "
          "only)");

    std::vector<double> spacings;
    for (unsigned int level = 0; level < discretization.n_levels; ++level)
      {
        const double h = discretization.mesh_size(level);
        spacings.push_back(nonlocal_parameters.particle_spacing(h));
        data.functions<dim>(material, nonlocal_parameters.horizon(h), h);
      }
    crack_set.validate(geometry, spacings);
    if (!reference_crack_opening.empty())
      // Parsed once here, to stop on a malformed one before the run.
      reference_opening<dim>(reference_crack_opening, material, eps0, h0);
  }



  template <int dim>
  RunSummary
  ElasticityScene<dim>::run(const std::string  &output_directory,
                            ConditionalOStream &out)
  {
    return this->run_levels(
      "elasticity", output_directory, out, [&](const double h) {
        const Kernel influence = nonlocal_parameters.kernel(dim, h);
        return ElasticityLevel<dim>{this->level(h),
                                    material,
                                    crack_set,
                                    section_planes,
                                    reference_crack_opening,
                                    influence,
                                    data.functions<dim>(material,
                                                        influence.horizon(),
                                                        h)};
      });
  }



  template class ElasticityScene<2>;
  template class ElasticityScene<3>;
} // namespace ltn

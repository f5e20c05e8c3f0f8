#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_refinement.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>

#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>

#include <ltn/base/input_error.h>
#include <ltn/local/poisson_problem.h>

#include <cmath>

namespace ltn
{
  template <int dim>
  void
  PoissonProblem<dim>::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Local model");
    {
      prm.declare_entry("Finite element degree",
                        "1",
                        Patterns::Integer(1, 4),
                        "Degree p of the continuous FE_Q(p) elements of the "
                        "local Poisson problem.");
      prm.declare_entry("Dirichlet boundaries",
                        "x+",
                        Patterns::List(Patterns::Selection("x-|x+|y-|y+|z-|z+"),
                                       0,
                                       6),
                        "Faces of the body with the Dirichlet condition "
                        "u = `Problem data/Boundary data` (and, where the "
                        "nonlocal region touches them, the volume constraint "
                        "on its physical collar). The other faces of the "
                        "local region on the body's boundary get the Neumann "
                        "condition du/dn = `Problem data/Boundary gradient` "
                        ". n.");
      prm.declare_entry("Adaptive refinement cycles",
                        "0",
                        Patterns::Integer(0, 20),
                        "On every level, after the first coupled solve, "
                        "refine the local mesh this many times by Kelly's "
                        "error indicator, solving again each time (one line "
                        "each in the convergence table; particles and "
                        "horizon stay those of the level).");
      prm.declare_entry("Refinement fraction",
                        "0.3",
                        Patterns::Double(0, 1),
                        "The fraction of cells, with the largest indicators, "
                        "that an adaptive cycle refines.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  PoissonProblem<dim>::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Local model");
    {
      degree = prm.get_integer("Finite element degree");
      dirichlet_faces.clear();
      for (const std::string &name :
           Utilities::split_string_list(prm.get("Dirichlet boundaries")))
        dirichlet_faces.insert(
          Geometry<dim>::face_number(name, "Local model/Dirichlet boundaries"));
      adaptive_cycles     = prm.get_integer("Adaptive refinement cycles");
      refinement_fraction = prm.get_double("Refinement fraction");
    }
    prm.leave_subsection();
  }



  namespace
  {
    /** A distributed mesh in 2D and 3D, a serial one in 1D. */
    template <int dim>
    std::unique_ptr<Triangulation<dim>>
    make_triangulation(const MPI_Comm communicator)
    {
      if constexpr (dim == 1)
        {
          AssertThrow(Utilities::MPI::n_mpi_processes(communicator) == 1,
                      ExcMessage("1D meshes are serial"));
          return std::make_unique<Triangulation<1>>();
        }
      else
        return std::make_unique<parallel::distributed::Triangulation<dim>>(
          communicator);
    }

    /**
     * The number of times a mesh of size @p h can be coarsened so that the
     * body and the local region stay unions of its cells.
     */
    template <int dim>
    unsigned int
    coarsening_steps(const Geometry<dim> &geometry, const double h)
    {
      const Box<dim> hole    = geometry.shrunk_nonlocal_region();
      const auto     aligned = [&](const double length, const double size) {
        const double n = length / size;
        return std::abs(n - std::round(n)) < 1e-8 * std::max(1., n);
      };
      unsigned int steps = 0;
      while (steps < 20)
        {
          const double size = h * (1 << (steps + 1));
          bool         fits = true;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double origin = geometry.body.lower[d];
              fits = fits && aligned(geometry.body.upper[d] - origin, size) &&
                     (!geometry.has_nonlocal_model() ||
                      (aligned(hole.lower[d] - origin, size) &&
                       aligned(hole.upper[d] - origin, size)));
            }
          if (!fits)
            break;
          ++steps;
        }
      return steps;
    }
  } // namespace



  template <int dim>
  PoissonProblem<dim>::PoissonProblem(const Geometry<dim> &geometry,
                                      const Parameters    &parameters,
                                      const double         h,
                                      const MPI_Comm       communicator)
    : geometry(geometry)
    , parameters(parameters)
    , communicator(communicator)
    , triangulation(make_triangulation<dim>(communicator))
    , fe(parameters.degree)
    , dof_handler(*triangulation)
  {
    // A coarse mesh of the body, as coarse as the geometry allows, minus the
    // cells of the shrunk nonlocal region (the geometry is aligned with h,
    // see Geometry::validate()); then refined to h. A coarse mesh with few
    // cells keeps p4est's replicated forest small.
    const unsigned int        steps = coarsening_steps(geometry, h);
    const double              H     = h * (1 << steps);
    std::vector<unsigned int> repetitions(dim);
    for (unsigned int d = 0; d < dim; ++d)
      repetitions[d] = static_cast<unsigned int>(
        std::round((geometry.body.upper[d] - geometry.body.lower[d]) / H));
    Triangulation<dim> body_mesh;
    GridGenerator::subdivided_hyper_rectangle(body_mesh,
                                              repetitions,
                                              geometry.body.lower,
                                              geometry.body.upper);
    std::set<typename Triangulation<dim>::active_cell_iterator> removed;
    for (const auto &cell : body_mesh.active_cell_iterators())
      if (!geometry.in_local_region(cell->center()))
        removed.insert(cell);
    GridGenerator::create_triangulation_with_removed_cells(body_mesh,
                                                           removed,
                                                           *triangulation);

    // Body faces keep deal.II's colorized numbering; the rest is Gamma_c.
    // Set on the coarse mesh (all of it, on every rank), inherited by the
    // refined cells.
    const double tol = geometry.tolerance();
    for (const auto &cell : triangulation->cell_iterators_on_level(0))
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<dim>   center = cell->face(f)->center();
            types::boundary_id id     = control_boundary_id;
            for (unsigned int face = 0; face < 2 * dim; ++face)
              {
                const double body_coordinate = (face % 2 == 0) ?
                                                 geometry.body.lower[face / 2] :
                                                 geometry.body.upper[face / 2];
                if (std::abs(center[face / 2] - body_coordinate) <= tol)
                  id = face;
              }
            cell->face(f)->set_boundary_id(id);
          }
    triangulation->refine_global(steps);
    setup_dofs();
  }



  template <int dim>
  void
  PoissonProblem<dim>::setup_dofs()
  {
    dof_handler.distribute_dofs(fe);
    model.communicator = communicator;
    model.owned        = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, model.relevant);
    hanging_nodes.clear();
    hanging_nodes.reinit(model.relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_nodes);
    hanging_nodes.close();
  }



  template <int dim>
  void
  PoissonProblem<dim>::refine(
    const TrilinosWrappers::MPI::Vector                   &solution,
    const std::function<bool(const Point<dim> &, double)> &may_refine)
  {
    Vector<float> indicators(triangulation->n_active_cells());
    KellyErrorEstimator<dim>::estimate(dof_handler,
                                       QGauss<dim - 1>(fe.degree + 1),
                                       {},
                                       model.ghosted(solution),
                                       indicators);
    if constexpr (dim == 1)
      GridRefinement::refine_and_coarsen_fixed_number(
        *triangulation, indicators, parameters.refinement_fraction, 0);
    else
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        static_cast<parallel::distributed::Triangulation<dim> &>(
          *triangulation),
        indicators,
        parameters.refinement_fraction,
        0);
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned() && cell->refine_flag_set() &&
          !may_refine(cell->center(), cell->extent_in_direction(0)))
        cell->clear_refine_flag();
    triangulation->execute_coarsening_and_refinement();
    setup_dofs();
  }



  template <int dim>
  void
  PoissonProblem<dim>::assemble(const Function<dim> &rhs,
                                const Function<dim> &boundary_data,
                                const Function<dim> &boundary_gradient)
  {
    const types::global_dof_index n_dofs = dof_handler.n_dofs();
    DynamicSparsityPattern        dsp(n_dofs, n_dofs, model.relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, hanging_nodes, true);
    for (const auto &line : hanging_nodes.get_lines())
      for (const auto &entry : line.entries)
        dsp.add(line.index, entry.first);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               model.owned,
                                               communicator,
                                               model.relevant);
    model.matrix.reinit(model.owned, model.owned, dsp, communicator);
    model.rhs = model.new_vector();

    const QGauss<dim>                    quadrature(fe.degree + 2);
    const QGauss<dim - 1>                face_quadrature(fe.degree + 2);
    FEValues<dim>                        fe_values(fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    FEFaceValues<dim>                    fe_face_values(fe,
                                     face_quadrature,
                                     update_values | update_normal_vectors |
                                       update_quadrature_points |
                                       update_JxW_values);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    Vector<double>                       gradient(dim);
    FullMatrix<double>                   cell_matrix(dofs_per_cell);
    Vector<double>                       cell_rhs(dofs_per_cell);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          cell_matrix = 0;
          cell_rhs    = 0;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double f = rhs.value(fe_values.quadrature_point(q));
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    cell_matrix(i, j) += fe_values.shape_grad(i, q) *
                                         fe_values.shape_grad(j, q) *
                                         fe_values.JxW(q);
                  cell_rhs(i) +=
                    f * fe_values.shape_value(i, q) * fe_values.JxW(q);
                }
            }

          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() != control_boundary_id &&
                parameters.dirichlet_faces.count(
                  cell->face(f)->boundary_id()) == 0)
              {
                fe_face_values.reinit(cell, f);
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  {
                    boundary_gradient.vector_value(
                      fe_face_values.quadrature_point(q), gradient);
                    double flux = 0;
                    for (unsigned int d = 0; d < dim; ++d)
                      flux += gradient[d] * fe_face_values.normal_vector(q)[d];
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      cell_rhs(i) += flux * fe_face_values.shape_value(i, q) *
                                     fe_face_values.JxW(q);
                  }
              }
          // Condensed: the equations of hanging nodes go to their masters.
          hanging_nodes.distribute_local_to_global(
            cell_matrix, cell_rhs, dofs, model.matrix, model.rhs);
        }
    model.matrix.compress(VectorOperation::add);
    model.rhs.compress(VectorOperation::add);

    // Roles of the owned degrees of freedom. A hanging node on Gamma_c
    // follows its masters: not a control of its own. Dirichlet data wins
    // over the control where Gamma_c meets a Dirichlet face.
    model.controls = DoFTools::extract_boundary_dofs(dof_handler,
                                                     ComponentMask(),
                                                     {control_boundary_id});
    model.controls = model.controls & model.owned;
    std::map<types::global_dof_index, double> dirichlet_values;
    for (const unsigned int face : parameters.dirichlet_faces)
      VectorTools::interpolate_boundary_values(dof_handler,
                                               face,
                                               boundary_data,
                                               dirichlet_values);
    model.fixed = IndexSet(n_dofs);
    for (const auto &entry : dirichlet_values)
      if (model.owned.is_element(entry.first))
        model.fixed.add_index(entry.first);
    model.fixed.compress();
    IndexSet hanging(n_dofs);
    for (const auto &line : hanging_nodes.get_lines())
      if (model.owned.is_element(line.index) &&
          !model.fixed.is_element(line.index))
        hanging.add_index(line.index);
    hanging.compress();
    model.controls.subtract_set(hanging);
    model.controls.subtract_set(model.fixed);

    // Close the model: identity rows for fixed and control degrees of
    // freedom, and a hanging node's own equation is its constraint.
    std::vector<types::global_dof_index> identity_rows;
    for (const IndexSet *rows : {&model.fixed, &model.controls, &hanging})
      identity_rows.insert(identity_rows.end(), rows->begin(), rows->end());
    model.matrix.clear_rows(identity_rows, 1.);
    for (const auto i : model.controls)
      model.rhs(i) = 0;
    for (const auto i : model.fixed)
      model.rhs(i) = dirichlet_values.at(i);
    for (const auto i : hanging)
      {
        for (const auto &entry : *hanging_nodes.get_constraint_entries(i))
          model.matrix.set(i, entry.first, -entry.second);
        model.rhs(i) = 0;
      }
    model.matrix.compress(VectorOperation::insert);
    model.rhs.compress(VectorOperation::insert);
  }



  template <int dim>
  const DoFHandler<dim> &
  PoissonProblem<dim>::get_dof_handler() const
  {
    return dof_handler;
  }



  template <int dim>
  const DiscreteModel &
  PoissonProblem<dim>::get_model() const
  {
    return model;
  }



  template class PoissonProblem<1>;
  template class PoissonProblem<2>;
  template class PoissonProblem<3>;
} // namespace ltn

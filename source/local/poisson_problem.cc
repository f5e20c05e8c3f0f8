#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_refinement.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

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



  template <int dim>
  PoissonProblem<dim>::PoissonProblem(const Geometry<dim> &geometry,
                                      const Parameters    &parameters,
                                      const double         h)
    : geometry(geometry)
    , parameters(parameters)
    , fe(parameters.degree)
    , dof_handler(triangulation)
  {
    // A uniform mesh of the body, minus the cells of the shrunk nonlocal
    // region (the geometry is aligned with h, see Geometry::validate()).
    std::vector<unsigned int> repetitions(dim);
    for (unsigned int d = 0; d < dim; ++d)
      repetitions[d] = static_cast<unsigned int>(
        std::round((geometry.body.upper[d] - geometry.body.lower[d]) / h));
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
                                                           triangulation);

    // Body faces keep deal.II's colorized numbering; the rest is Gamma_c.
    const double tol = geometry.tolerance();
    for (const auto &cell : triangulation.active_cell_iterators())
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
    setup_dofs();
  }



  template <int dim>
  void
  PoissonProblem<dim>::setup_dofs()
  {
    dof_handler.distribute_dofs(fe);
    support_points.resize(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                         dof_handler,
                                         support_points);
    hanging_nodes.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_nodes);
    hanging_nodes.close();
  }



  template <int dim>
  void
  PoissonProblem<dim>::refine(
    const Vector<double>                                  &solution,
    const std::function<bool(const Point<dim> &, double)> &may_refine)
  {
    Vector<float> indicators(triangulation.n_active_cells());
    KellyErrorEstimator<dim>::estimate(
      dof_handler, QGauss<dim - 1>(fe.degree + 1), {}, solution, indicators);
    GridRefinement::refine_and_coarsen_fixed_number(
      triangulation, indicators, parameters.refinement_fraction, 0);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->refine_flag_set() &&
          !may_refine(cell->center(), cell->extent_in_direction(0)))
        cell->clear_refine_flag();
    triangulation.execute_coarsening_and_refinement();
    setup_dofs();
  }



  template <int dim>
  void
  PoissonProblem<dim>::assemble(const Function<dim> &rhs,
                                const Function<dim> &boundary_data,
                                const Function<dim> &boundary_gradient)
  {
    const types::global_dof_index n_dofs = dof_handler.n_dofs();
    DynamicSparsityPattern        dsp(n_dofs);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, hanging_nodes, true);
    for (const auto &line : hanging_nodes.get_lines())
      for (const auto &entry : line.entries)
        dsp.add(line.index, entry.first);
    model.sparsity.copy_from(dsp);
    model.matrix.reinit(model.sparsity);
    model.rhs.reinit(n_dofs);

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
              parameters.dirichlet_faces.count(cell->face(f)->boundary_id()) ==
                0)
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

    // A hanging node's own equation is its constraint.
    for (const auto &line : hanging_nodes.get_lines())
      {
        for (auto entry = model.matrix.begin(line.index);
             entry != model.matrix.end(line.index);
             ++entry)
          entry->value() = 0;
        model.matrix.set(line.index, line.index, 1.);
        for (const auto &entry : line.entries)
          model.matrix.add(line.index, entry.first, -entry.second);
        model.rhs[line.index] = 0;
      }

    // Roles: Dirichlet data wins over the control where Gamma_c meets a
    // Dirichlet face.
    model.roles.assign(n_dofs, DofRole::free);
    const IndexSet control_dofs =
      DoFTools::extract_boundary_dofs(dof_handler,
                                      ComponentMask(),
                                      {control_boundary_id});
    for (const auto i : control_dofs)
      model.roles[i] = DofRole::control;
    // A hanging node on Gamma_c follows its masters: not a control of its own.
    for (const auto &line : hanging_nodes.get_lines())
      model.roles[line.index] = DofRole::free;

    model.fixed_values.reinit(n_dofs);
    std::map<types::global_dof_index, double> dirichlet_values;
    for (const unsigned int face : parameters.dirichlet_faces)
      VectorTools::interpolate_boundary_values(dof_handler,
                                               face,
                                               boundary_data,
                                               dirichlet_values);
    for (const auto &entry : dirichlet_values)
      {
        model.roles[entry.first]        = DofRole::fixed;
        model.fixed_values[entry.first] = entry.second;
      }
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



  template <int dim>
  const std::vector<Point<dim>> &
  PoissonProblem<dim>::get_support_points() const
  {
    return support_points;
  }

  template class PoissonProblem<1>;
  template class PoissonProblem<2>;
  template class PoissonProblem<3>;
} // namespace ltn

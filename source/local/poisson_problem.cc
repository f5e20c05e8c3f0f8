#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>

#include <deal.II/numerics/vector_tools.h>

#include <ltn/local/closed_model.h>
#include <ltn/local/poisson_problem.h>

namespace ltn
{
  template <int dim>
  PoissonProblem<dim>::PoissonProblem(const Geometry<dim>        &geometry,
                                      const LocalParameters<dim> &parameters,
                                      const double                h,
                                      const MPI_Comm              communicator)
    : Base(geometry, parameters, h, communicator, parameters.degree)
  {}



  template <int dim>
  void
  PoissonProblem<dim>::assemble(const Function<dim> &rhs,
                                const Function<dim> &boundary_data,
                                const Function<dim> &boundary_gradient)
  {
    reinit_local_model(dof_handler, hanging_nodes, model);

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

    std::map<types::global_dof_index, double> dirichlet_values;
    for (const unsigned int face : parameters.dirichlet_faces)
      VectorTools::interpolate_boundary_values(dof_handler,
                                               face,
                                               boundary_data,
                                               dirichlet_values);
    close_local_model(
      dof_handler, hanging_nodes, dirichlet_values, control_boundary_id, model);
  }



  template class PoissonProblem<1>;
  template class PoissonProblem<2>;
  template class PoissonProblem<3>;
} // namespace ltn

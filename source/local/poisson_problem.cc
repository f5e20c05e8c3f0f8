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
    this->close_model(boundary_data);
  }



  template <int dim>
  WeightedForm
  PoissonProblem<dim>::weighted_form(const Function<dim>         &rhs,
                                     const BlendingFunction<dim> &beta) const
  {
    AssertThrow(hanging_nodes.n_constraints() == 0,
                ExcMessage("a weighted form on a mesh with hanging nodes"));
    WeightedForm form;
    form.matrix.reinit(model.matrix);
    form.matrix = 0;
    form.load   = model.new_vector();

    std::array<std::vector<double>, dim> kinks;
    for (unsigned int d = 0; d < dim; ++d)
      kinks[d] = beta.kinks(d);
    // Products of shape gradients are of degree 2p - 2, with the affine
    // weight 2p - 1: p + 1 Gauss points per direction of each piece would
    // do; the load is integrated as assemble() does, with p + 2.
    const QGauss<1>                      rule(fe.degree + 2);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    FullMatrix<double>                   cell_matrix(dofs_per_cell);
    Vector<double>                       cell_load(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // The cell's pieces between the kinks, as a quadrature on the
          // unit cell (cells are boxes aligned with the axes).
          const Point<dim> lower = cell->vertex(0);
          const Point<dim> upper =
            cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1);
          std::vector<Point<dim>> points(1);
          std::vector<double>     weights(1, 1.);
          for (unsigned int d = 0; d < dim; ++d)
            {
              std::vector<double> cuts = {lower[d]};
              for (const double k : kinks[d])
                if (k > lower[d] && k < upper[d])
                  cuts.push_back(k);
              cuts.push_back(upper[d]);
              std::vector<Point<dim>> next_points;
              std::vector<double>     next_weights;
              for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
                {
                  const double lo =
                    (cuts[c] - lower[d]) / (upper[d] - lower[d]);
                  const double hi =
                    (cuts[c + 1] - lower[d]) / (upper[d] - lower[d]);
                  for (unsigned int q = 0; q < rule.size(); ++q)
                    for (std::size_t m = 0; m < points.size(); ++m)
                      {
                        Point<dim> p = points[m];
                        p[d]         = lo + (hi - lo) * rule.point(q)[0];
                        next_points.push_back(p);
                        next_weights.push_back(weights[m] * rule.weight(q) *
                                               (hi - lo));
                      }
                }
              points.swap(next_points);
              weights.swap(next_weights);
            }
          const Quadrature<dim> pieces(points, weights);
          FEValues<dim>         fe_values(fe,
                                  pieces,
                                  update_values | update_gradients |
                                    update_quadrature_points |
                                    update_JxW_values);
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          cell_matrix = 0;
          cell_load   = 0;
          for (unsigned int q = 0; q < pieces.size(); ++q)
            {
              const Point<dim> &x = fe_values.quadrature_point(q);
              const double      w = (1 - beta.value(x)) * fe_values.JxW(q);
              const double      f = rhs.value(x);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    cell_matrix(i, j) += w * fe_values.shape_grad(i, q) *
                                         fe_values.shape_grad(j, q);
                  cell_load(i) += w * f * fe_values.shape_value(i, q);
                }
            }
          form.matrix.add(dofs, cell_matrix);
          form.load.add(dofs, cell_load);
        }
    form.matrix.compress(VectorOperation::add);
    form.load.compress(VectorOperation::add);
    return form;
  }



  template class PoissonProblem<1>;
  template class PoissonProblem<2>;
  template class PoissonProblem<3>;
} // namespace ltn

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>

#include <deal.II/numerics/vector_tools.h>

#include <ltn/local/closed_model.h>
#include <ltn/local/elasticity_problem.h>

#include <cmath>
#include <map>
#include <vector>

namespace ltn
{
  namespace
  {
    /** Hooke's law: `lambda tr(eps) I + 2 mu eps`. */
    template <int dim>
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &strain,
           const double                   lambda,
           const double                   mu)
    {
      return lambda * trace(strain) * unit_symmetric_tensor<dim>() +
             2 * mu * strain;
    }



    /** `traction - pressure n` at a point with unit normal @p normal. */
    template <int dim>
    Tensor<1, dim>
    applied_traction(const Function<dim>  &traction,
                     const Function<dim>  &pressure,
                     const Point<dim>     &point,
                     const Tensor<1, dim> &normal)
    {
      Tensor<1, dim> t;
      const double   p = pressure.value(point);
      for (unsigned int c = 0; c < dim; ++c)
        t[c] = traction.value(point, c) - p * normal[c];
      return t;
    }
  } // namespace



  template <int dim>
  ElasticityProblem<dim>::ElasticityProblem(
    const Geometry<dim>        &geometry,
    const LocalParameters<dim> &parameters,
    const double                lambda,
    const double                mu,
    const double                h,
    const MPI_Comm              communicator)
    : Base(geometry,
           parameters,
           h,
           communicator,
           FE_Q<dim>(parameters.degree),
           dim)
    , lambda_value(lambda)
    , mu_value(mu)
    , tolerance(geometry.tolerance())
  {
    // Strongly elliptic (the energy of any nonzero strain is positive).
    AssertThrow(mu > 0 && lambda + 2. * mu / dim > 0,
                ExcMessage("the Lamé parameters must satisfy mu > 0 and "
                           "lambda + 2 mu / dim > 0"));
  }



  template <int dim>
  void
  ElasticityProblem<dim>::assemble(const Function<dim> &body_force,
                                   const Function<dim> &boundary_data,
                                   const Function<dim> &traction,
                                   const Function<dim> &pressure)
  {
    AssertThrow(body_force.n_components == dim &&
                  boundary_data.n_components == dim &&
                  traction.n_components == dim && pressure.n_components == 1,
                ExcMessage("body force, boundary data and traction need dim "
                           "components, the pressure one"));
    reinit_local_model(dof_handler, hanging_nodes, model);

    // The stiffness's integrand is a product of two gradients, of degree
    // 2p in each coordinate on the axis-parallel box cells of LtN's meshes:
    // p + 1 Gauss points per direction integrate it exactly. The loads get
    // one point more.
    const QGauss<dim>                    stiffness_quadrature(fe.degree + 1);
    const QGauss<dim>                    quadrature(fe.degree + 2);
    const QGauss<dim - 1>                face_quadrature(fe.degree + 2);
    FEValues<dim>                        stiffness_values(fe,
                                   stiffness_quadrature,
                                   update_gradients | update_JxW_values);
    FEValues<dim>                        fe_values(fe,
                            quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    FEFaceValues<dim>                    fe_face_values(fe,
                                     face_quadrature,
                                     update_values | update_normal_vectors |
                                       update_quadrature_points |
                                       update_JxW_values);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    // Each shape function has one nonzero component (FESystem of FE_Q):
    // phi_i = s_i e_{c_i}; g_i = grad s_i below.
    std::vector<unsigned int> components(dofs_per_cell);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      components[i] = fe.system_to_component_index(i).first;
    std::vector<Tensor<1, dim>> gradients(dofs_per_cell);
    Vector<double>              force(dim);
    FullMatrix<double>          cell_matrix(dofs_per_cell);
    Vector<double>              cell_rhs(dofs_per_cell);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          stiffness_values.reinit(cell);
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          cell_matrix = 0;
          cell_rhs    = 0;
          for (unsigned int q = 0; q < stiffness_quadrature.size(); ++q)
            {
              const double JxW = stiffness_values.JxW(q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                gradients[i] = stiffness_values.shape_grad(i, q);
              // lambda div(phi_i) div(phi_j) + 2 mu eps(phi_i) : eps(phi_j)
              // with div(phi_i) = (g_i)_{c_i} and
              // 2 eps_i : eps_j = delta_{c_i c_j} g_i . g_j
              //                   + (g_i)_{c_j} (g_j)_{c_i};
              // the lower triangle here, the upper one after the cell's
              // quadrature (the form is symmetric).
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  const Tensor<1, dim> &g_i = gradients[i];
                  const unsigned int    c_i = components[i];
                  for (unsigned int j = 0; j <= i; ++j)
                    {
                      const Tensor<1, dim> &g_j = gradients[j];
                      const unsigned int    c_j = components[j];
                      double value = lambda_value * g_i[c_i] * g_j[c_j] +
                                     mu_value * g_i[c_j] * g_j[c_i];
                      if (c_i == c_j)
                        value += mu_value * (g_i * g_j);
                      cell_matrix(i, j) += value * JxW;
                    }
                }
            }
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              body_force.vector_value(fe_values.quadrature_point(q), force);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                cell_rhs(i) += force[components[i]] *
                               fe_values.shape_value(i, q) * fe_values.JxW(q);
            }

          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            for (unsigned int j = i + 1; j < dofs_per_cell; ++j)
              cell_matrix(i, j) = cell_matrix(j, i);

          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() != control_boundary_id)
              {
                const ComponentMask fixed =
                  parameters.dirichlet_mask(cell->face(f)->boundary_id(), dim);
                if (fixed.n_selected_components(dim) == dim)
                  continue;
                fe_face_values.reinit(cell, f);
                for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                  {
                    const Tensor<1, dim> t =
                      applied_traction(traction,
                                       pressure,
                                       fe_face_values.quadrature_point(q),
                                       fe_face_values.normal_vector(q));
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      {
                        const unsigned int c = components[i];
                        if (!fixed[c])
                          cell_rhs(i) += t[c] *
                                         fe_face_values.shape_value(i, q) *
                                         fe_face_values.JxW(q);
                      }
                  }
              }
          // Condensed: the equations of hanging nodes go to their masters.
          hanging_nodes.distribute_local_to_global(
            cell_matrix, cell_rhs, dofs, model.matrix, model.rhs);
        }
    this->close_model(boundary_data);
  }



  template <int dim>
  Tensor<1, dim>
  ElasticityProblem<dim>::section_force(
    const TrilinosWrappers::MPI::Vector &ghosted_solution,
    const unsigned int                   d,
    const double                         c) const
  {
    AssertThrow(d < dim, ExcIndexRange(d, 0, dim));
    const FEValuesExtractors::Vector     displacement(0);
    const QGauss<dim - 1>                face_quadrature(fe.degree + 1);
    FEFaceValues<dim>                    fe_face_values(fe,
                                     face_quadrature,
                                     update_gradients | update_JxW_values);
    std::vector<SymmetricTensor<2, dim>> strains(face_quadrature.size());

    Tensor<1, dim> force;
    unsigned int   n_faces = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          {
            const auto   face       = cell->face(f);
            const double coordinate = face->center()[d];
            // Cartesian cells: the face is normal to e_d iff its centre is
            // off the cell's centre in direction d.
            const bool upper = coordinate > cell->center()[d] + tolerance;
            const bool lower = coordinate < cell->center()[d] - tolerance;
            if (std::abs(coordinate - c) > tolerance ||
                !(upper || (lower && face->at_boundary())))
              continue;
            ++n_faces;
            fe_face_values.reinit(cell, f);
            fe_face_values[displacement].get_function_symmetric_gradients(
              ghosted_solution, strains);
            for (unsigned int q = 0; q < face_quadrature.size(); ++q)
              {
                const SymmetricTensor<2, dim> sigma =
                  stress(strains[q], lambda_value, mu_value);
                for (unsigned int k = 0; k < dim; ++k)
                  force[k] += sigma[k][d] * fe_face_values.JxW(q);
              }
          }
    AssertThrow(Utilities::MPI::sum(n_faces, communicator) > 0,
                ExcMessage("no face of the local mesh lies in the plane x_" +
                           std::to_string(d) + " = " + std::to_string(c)));
    return Utilities::MPI::sum(force, communicator);
  }



  template <int dim>
  Tensor<1, dim>
  ElasticityProblem<dim>::applied_force(const Function<dim> &traction,
                                        const Function<dim> &pressure,
                                        const unsigned int   face) const
  {
    AssertThrow(face < 2 * dim, ExcIndexRange(face, 0, 2 * dim));
    AssertThrow(traction.n_components == dim && pressure.n_components == 1,
                ExcMessage("the traction needs dim components, the pressure "
                           "one"));
    const QGauss<dim - 1> face_quadrature(fe.degree + 2);
    FEFaceValues<dim>     fe_face_values(fe,
                                     face_quadrature,
                                     update_normal_vectors |
                                       update_quadrature_points |
                                       update_JxW_values);
    Tensor<1, dim>        force;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == face)
            {
              fe_face_values.reinit(cell, f);
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                force += applied_traction(traction,
                                          pressure,
                                          fe_face_values.quadrature_point(q),
                                          fe_face_values.normal_vector(q)) *
                         fe_face_values.JxW(q);
            }
    return Utilities::MPI::sum(force, communicator);
  }



  template <int dim>
  double
  ElasticityProblem<dim>::lambda() const
  {
    return lambda_value;
  }



  template <int dim>
  double
  ElasticityProblem<dim>::mu() const
  {
    return mu_value;
  }



  template class ElasticityProblem<2>;
  template class ElasticityProblem<3>;
} // namespace ltn

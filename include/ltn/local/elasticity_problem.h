#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/local/local_problem.h>
#include <ltn/problem/geometry.h>

namespace ltn
{
  using namespace dealii;

  /**
   * The local elasticity model: the Navier–Cauchy equations
   * `-div sigma(u) = b`, `sigma = lambda tr(eps) I + 2 mu eps`,
   * `eps = (grad u + grad u^T) / 2`, on the local region `Omega_l`
   * (in 2D plane strain or plane stress, by the `lambda` given), discretized
   * by `FESystem(FE_Q(p), dim)` on a LocalMesh.
   *
   * Faces of `Omega_l` on the body's boundary carry physical data: on the
   * faces in `Dirichlet boundaries` the components that
   * LocalParameters::dirichlet_mask() selects are fixed to the boundary
   * data; the traction `t = traction - pressure n` acts on the other
   * components of those faces and on all components of the other body
   * faces. Every component of the degrees of freedom on `Gamma_c` is a
   * virtual control (where not fixed, and not a hanging node); the model is
   * closed as close_local_model() describes.
   */
  template <int dim>
  class ElasticityProblem : public LocalProblem<dim, FESystem<dim>>
  {
  public:
    /**
     * Mesh `Omega_l` of @p geometry with size @p h over @p communicator,
     * with Lamé parameters @p lambda and @p mu.
     */
    ElasticityProblem(const Geometry<dim>        &geometry,
                      const LocalParameters<dim> &parameters,
                      const double                lambda,
                      const double                mu,
                      const double                h,
                      const MPI_Comm              communicator);

    /**
     * Assemble the stiffness matrix and the load vector of the body force
     * @p body_force (`dim` components) and of the traction
     * `t = traction - pressure n` (@p traction with `dim` components,
     * @p pressure with one) on the body faces that are not Dirichlet faces
     * for a component, and fix the Dirichlet degrees of freedom to
     * @p boundary_data (`dim` components; only the masked ones are used).
     */
    void
    assemble(const Function<dim> &body_force,
             const Function<dim> &boundary_data,
             const Function<dim> &traction,
             const Function<dim> &pressure);

    /** The first Lamé parameter. */
    double
    lambda() const;

    /** The shear modulus. */
    double
    mu() const;

    /**
     * The force through the plane `x_d = c`: the integral of
     * `sigma(u_h) e_d` over the faces of the locally owned cells that lie in
     * that plane, each face counted once, from the cell on its lower side
     * (from the only cell where the plane is a lower face of the mesh),
     * summed over all ranks. @p ghosted_solution holds the values of the
     * locally relevant degrees of freedom. Throws (ExcMessage) if no face of
     * the mesh lies in that plane.
     */
    Tensor<1, dim>
    section_force(const TrilinosWrappers::MPI::Vector &ghosted_solution,
                  const unsigned int                   d,
                  const double                         c) const;

    /**
     * The applied resultant on body face @p face (`0 .. 2dim-1`): the
     * integral of `t = traction - pressure n` over the part of it that
     * bounds `Omega_l`, summed over all ranks.
     */
    Tensor<1, dim>
    applied_force(const Function<dim> &traction,
                  const Function<dim> &pressure,
                  const unsigned int   face) const;

  private:
    using Base = LocalProblem<dim, FESystem<dim>>;
    using Base::communicator;
    using Base::control_boundary_id;
    using Base::dof_handler;
    using Base::fe;
    using Base::hanging_nodes;
    using Base::model;
    using Base::parameters;

    const double lambda_value;
    const double mu_value;
    const double tolerance;
  };
} // namespace ltn

#pragma once

#include <deal.II/base/function.h>

#include <deal.II/fe/fe_q.h>

#include <ltn/local/local_problem.h>
#include <ltn/problem/blending_function.h>
#include <ltn/problem/geometry.h>

namespace ltn
{
  using namespace dealii;

  /**
   * The local model: Poisson's equation `-Laplace u = f` on the local region
   * `Omega_l`, discretized by continuous `FE_Q(p)`.
   * Faces of `Omega_l` on the body's boundary carry physical data: Dirichlet
   * `u = g` on the faces listed in `Dirichlet boundaries`, Neumann
   * `du/dn = q . n` (a given flux vector `q`) on the others. The boundary
   * `Gamma_c` of `Omega_l` inside the nonlocal region carries the virtual
   * control `theta_l`.
   *
   * The mesh is a LocalMesh and can be refined adaptively (Kelly); hanging
   * nodes stay unknowns of the model with their constraints as equations
   * (see close_local_model()).
   */
  template <int dim>
  class PoissonProblem : public LocalProblem<dim, FE_Q<dim>>
  {
  public:
    PoissonProblem(const Geometry<dim>        &geometry,
                   const LocalParameters<dim> &parameters,
                   const double                h,
                   const MPI_Comm              communicator);

    /**
     * Assemble the stiffness matrix and the load vector of @p rhs and of the
     * Neumann flux @p boundary_gradient (a `dim`-component function whose
     * normal component is `du/dn`), and fix the Dirichlet degrees of freedom
     * to @p boundary_data.
     */
    void
    assemble(const Function<dim> &rhs,
             const Function<dim> &boundary_data,
             const Function<dim> &boundary_gradient);

    /**
     * For energy-based blending (doc/baseline_couplings.md, 'Energy-based
     * blending'): the stiffness form with the coefficient `1 - beta` and the
     * load of `(1 - beta) rhs`, every row a test function (Dirichlet and
     * control rows too; hanging nodes are not supported, nor are Neumann
     * fluxes). Each cell is integrated on the boxes that the planes of
     * `beta.kinks()` cut it into: exact where `beta` is affine on them (in
     * 1D, everywhere).
     */
    WeightedForm
    weighted_form(const Function<dim>         &rhs,
                  const BlendingFunction<dim> &beta) const;

  private:
    using Base = LocalProblem<dim, FE_Q<dim>>;
    using Base::control_boundary_id;
    using Base::dof_handler;
    using Base::fe;
    using Base::hanging_nodes;
    using Base::model;
    using Base::parameters;
  };
} // namespace ltn

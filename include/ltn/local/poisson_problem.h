#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/tria.h>

#include <ltn/base/discrete_model.h>
#include <ltn/scene/geometry.h>

#include <set>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The local model: Poisson's equation `-Laplace u = f` on the local region
   * `Omega_l`, discretized by continuous `FE_Q(p)` on a uniform mesh.
   * Faces of `Omega_l` on the body's boundary carry physical data: Dirichlet
   * `u = g` on the faces listed in `Dirichlet boundaries`, Neumann
   * `du/dn = q . n` (a given flux vector `q`) on the others. The boundary
   * `Gamma_c` of `Omega_l` inside the nonlocal region carries the virtual
   * control `theta_l`.
   */
  template <int dim>
  class PoissonProblem
  {
  public:
    /** The boundary id of `Gamma_c`; the body's faces keep ids 0..2dim-1. */
    static constexpr types::boundary_id control_boundary_id = 2 * dim;

    struct Parameters
    {
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm);

      unsigned int           degree = 1;
      std::set<unsigned int> dirichlet_faces;
    };

    PoissonProblem(const Geometry<dim> &geometry,
                   const Parameters    &parameters,
                   const double         h);

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

    const DoFHandler<dim> &
    get_dof_handler() const;

    const DiscreteModel &
    get_model() const;

    /** The support point of each degree of freedom. */
    const std::vector<Point<dim>> &
    get_support_points() const;

  private:
    const Geometry<dim>    &geometry;
    const Parameters       &parameters;
    Triangulation<dim>      triangulation;
    FE_Q<dim>               fe;
    DoFHandler<dim>         dof_handler;
    std::vector<Point<dim>> support_points;
    DiscreteModel           model;
  };
} // namespace ltn

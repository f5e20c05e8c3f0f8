#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/scene/geometry.h>

#include <functional>
#include <memory>
#include <set>

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
   *
   * The mesh can be refined adaptively (Kelly). A hanging node stays an
   * unknown of the model, with its constraint as its equation,
   * `u_j - sum_k c_jk u_k = 0`, while the equations of the other degrees of
   * freedom are condensed; so the solution is conforming and the coupling
   * evaluates it with the ordinary shape functions.
   *
   * In 2D and 3D the mesh is a parallel::distributed::Triangulation over
   * the given communicator; in 1D (which p4est does not have) it is serial,
   * and the communicator must have one rank.
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
      unsigned int           adaptive_cycles     = 0;
      double                 refinement_fraction = 0.3;
    };

    PoissonProblem(const Geometry<dim> &geometry,
                   const Parameters    &parameters,
                   const double         h,
                   const MPI_Comm       communicator);

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
     * Refine the cells with the largest Kelly error indicators of
     * @p solution (a `refinement fraction` of them, over all ranks), except
     * those for which @p may_refine (given the cell's centre and size) says
     * no, and set up the degrees of freedom anew; assemble() must follow.
     */
    void
    refine(const TrilinosWrappers::MPI::Vector                   &solution,
           const std::function<bool(const Point<dim> &, double)> &may_refine);

    const DoFHandler<dim> &
    get_dof_handler() const;

    const DiscreteModel &
    get_model() const;

  private:
    /** Distribute degrees of freedom, support points, hanging nodes. */
    void
    setup_dofs();

    const Geometry<dim>                      &geometry;
    const Parameters                         &parameters;
    const MPI_Comm                            communicator;
    const std::unique_ptr<Triangulation<dim>> triangulation;
    FE_Q<dim>                                 fe;
    DoFHandler<dim>                           dof_handler;
    AffineConstraints<double>                 hanging_nodes;
    DiscreteModel                             model;
  };
} // namespace ltn

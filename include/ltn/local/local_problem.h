#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/local/closed_model.h>
#include <ltn/local/local_mesh.h>
#include <ltn/local/local_parameters.h>
#include <ltn/problem/geometry.h>

#include <functional>
#include <utility>

namespace ltn
{
  using namespace dealii;

  /**
   * What the local models (PoissonProblem, ElasticityProblem) share: the
   * finite element `FE` on a LocalMesh of `Omega_l`, its degrees of freedom
   * (hanging nodes stay unknowns with their constraints as equations, see
   * close_local_model()), adaptive refinement, and the DiscreteModel the
   * coupling reads. The physics assembles the model.
   */
  template <int dim, typename FE>
  class LocalProblem
  {
  public:
    /** The boundary id of `Gamma_c`; the body's faces keep ids 0..2dim-1. */
    static constexpr types::boundary_id control_boundary_id =
      LocalMesh<dim>::control_boundary_id;

    /**
     * Refine the cells with the largest Kelly error indicators of
     * @p solution (all components; a `refinement fraction` of them, over
     * all ranks), except those for which @p may_refine (given the cell's
     * centre and size) says no, and set up the degrees of freedom anew;
     * the physics' `assemble()` must follow.
     */
    void
    refine(const TrilinosWrappers::MPI::Vector                   &solution,
           const std::function<bool(const Point<dim> &, double)> &may_refine);

    const DoFHandler<dim> &
    get_dof_handler() const;

    const DiscreteModel &
    get_model() const;

  protected:
    /** Not deleted through this base. */
    ~LocalProblem() = default;

    /**
     * Mesh `Omega_l` of @p geometry with size @p h over @p communicator and
     * distribute the degrees of freedom of the element built from
     * @p fe_arguments.
     */
    template <typename... FEArguments>
    LocalProblem(const Geometry<dim>        &geometry,
                 const LocalParameters<dim> &parameters,
                 const double                h,
                 const MPI_Comm              communicator,
                 FEArguments &&...fe_arguments)
      : parameters(parameters)
      , communicator(communicator)
      , mesh(geometry, h, parameters.graded_mesh_layers, communicator)
      , fe(std::forward<FEArguments>(fe_arguments)...)
      , dof_handler(mesh.get_triangulation())
    {
      setup_local_dofs(dof_handler, fe, communicator, hanging_nodes, model);
    }

    /**
     * Sum the ranks' contributions to the assembled model and close it: the
     * components LocalParameters::dirichlet_mask() selects on the Dirichlet
     * faces take @p boundary_data, the hanging nodes and the controls are
     * as close_local_model() says.
     */
    void
    close_model(const Function<dim> &boundary_data);

    const LocalParameters<dim> &parameters;
    const MPI_Comm              communicator;
    LocalMesh<dim>              mesh;
    const FE                    fe;
    DoFHandler<dim>             dof_handler;
    AffineConstraints<double>   hanging_nodes;
    DiscreteModel               model;
  };
} // namespace ltn

#pragma once

#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe.h>

#include <deal.II/lac/affine_constraints.h>

#include <ltn/base/discrete_model.h>

#include <map>

namespace ltn
{
  using namespace dealii;

  /**
   * @name A local (finite element) model as a DiscreteModel closed by its
   * controls.
   *
   * A hanging node stays an unknown of the model, with its constraint as its
   * equation, `u_j - sum_k c_jk u_k = 0`, while the cell contributions are
   * condensed onto its masters; so the field is conforming and the coupling
   * evaluates it with the ordinary shape functions. The steps, in order:
   * setup_local_dofs() after every change of the mesh, then for each
   * assembly reinit_local_model(), the condensed assembly into
   * `model.matrix` and `model.rhs` (e.g. by
   * `hanging_nodes.distribute_local_to_global()`, followed by `compress()`)
   * and close_local_model().
   */
  /** @{ */

  /**
   * Distribute the degrees of freedom of @p fe on @p dof_handler and set
   * @p model's communicator and owned and relevant index sets, and
   * @p hanging_nodes to the (closed) hanging node constraints of the
   * relevant degrees of freedom.
   */
  template <int dim>
  void
  setup_local_dofs(DoFHandler<dim>           &dof_handler,
                   const FiniteElement<dim>  &fe,
                   const MPI_Comm             communicator,
                   AffineConstraints<double> &hanging_nodes,
                   DiscreteModel             &model);

  /**
   * Size @p model's matrix for the cell couplings condensed by
   * @p hanging_nodes plus the hanging nodes' own constraint rows, and set
   * it and the right-hand side to zero.
   */
  template <int dim>
  void
  reinit_local_model(const DoFHandler<dim>           &dof_handler,
                     const AffineConstraints<double> &hanging_nodes,
                     DiscreteModel                   &model);

  /**
   * Assign the roles of the owned degrees of freedom and close the
   * assembled (and compressed) @p model: the degrees of freedom in
   * @p dirichlet_values are fixed to those values; the others on the
   * boundary with id @p control_boundary_id (all components) are controls,
   * except hanging nodes, which follow their masters. Fixed and control
   * rows become identity rows (right-hand side the value, or 0), a hanging
   * node's row its constraint (right-hand side 0).
   *
   * @p dirichlet_values may hold values of degrees of freedom that this rank
   * does not own; they are ignored.
   */
  template <int dim>
  void
  close_local_model(
    const DoFHandler<dim>                           &dof_handler,
    const AffineConstraints<double>                 &hanging_nodes,
    const std::map<types::global_dof_index, double> &dirichlet_values,
    const types::boundary_id                         control_boundary_id,
    DiscreteModel                                   &model);

  /** @} */
} // namespace ltn

#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace ltn
{
  using namespace dealii;

  /** What a degree of freedom of a model is to the coupling. */
  enum class DofRole : unsigned char
  {
    /** An unknown of the model's own equations. */
    free,
    /** A virtual control: `theta_n` on the control collar, `theta_l` on
       `Gamma_c`. */
    control,
    /** Fixed by physical data (volume constraint or Dirichlet condition). */
    fixed
  };

  /**
   * The narrow interface through which the coupling sees a model, distributed
   * over the ranks of `communicator`: each rank owns the rows of some degrees
   * of freedom (`owned`) and reads the values of those its rows touch
   * (`relevant`, which contains `owned`).
   *
   * The model is closed by its controls: `matrix` `M` and `rhs` `r` hold
   *
   *   free dof i:     sum_j A_ij x_j = F_i    (the model's own equation),
   *   fixed dof i:    x_i = g_i               (physical data),
   *   control dof i:  x_i = 0                 (identity row, zero data),
   *
   * so that the model's field for controls `theta` solves
   * `M x = r + S theta`, with `S` placing `theta` in the control rows.
   */
  struct DiscreteModel
  {
    DiscreteModel()                      = default;
    DiscreteModel(const DiscreteModel &) = delete;
    DiscreteModel &
    operator=(const DiscreteModel &) = delete;

    MPI_Comm                       communicator = MPI_COMM_SELF;
    IndexSet                       owned;
    IndexSet                       relevant;
    TrilinosWrappers::SparseMatrix matrix;
    TrilinosWrappers::MPI::Vector  rhs;
    /** The owned control and fixed degrees of freedom. */
    IndexSet controls;
    IndexSet fixed;

    /** The role of an owned degree of freedom. */
    DofRole
    role(const types::global_dof_index i) const;

    /** A zero vector over the owned degrees of freedom. */
    TrilinosWrappers::MPI::Vector
    new_vector() const;

    /** @p field with its values on the relevant degrees of freedom. */
    TrilinosWrappers::MPI::Vector
    ghosted(const TrilinosWrappers::MPI::Vector &field) const;

    /** The number of control degrees of freedom on all ranks. */
    types::global_dof_index
    n_controls() const;
  };
} // namespace ltn

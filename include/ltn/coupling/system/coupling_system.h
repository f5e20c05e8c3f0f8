#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/base/solver_statistics.h>
#include <ltn/coupling/system/overlap_quadrature.h>
#include <ltn/model_solvers/model_solver.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** Which of the two models: index into the arrays of CouplingSystem. */
  enum ModelIndex : unsigned int
  {
    nonlocal_model = 0,
    local_model    = 1
  };

  /**
   * The pieces of the discrete optimality problem (section 4 of the design)
   * that every solver of it shares:
   *
   *   minimize J_h = 1/2 sum_q w_q (E_q u_n - P_q u_l)^2 + alpha/2 |theta|^2
   *   subject to M_n u_n = r_n + S_n theta_n and M_l u_l = r_l + S_l theta_l,
   *
   * with each model closed by its controls (DiscreteModel). Each rank holds
   * the overlap points it owns; fields are distributed vectors over the
   * models' owned degrees of freedom.
   */
  template <int dim>
  class CouplingSystem
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    CouplingSystem(const DiscreteModel          &nonlocal,
                   const DiscreteModel          &local,
                   const OverlapQuadrature<dim> &overlap,
                   const double                  tikhonov_parameter);

    /**
     * The mismatch `d_q = E_q u_n - P_q u_l` at this rank's points; an empty
     * vector (on every rank) stands for a zero field, whose rows are skipped.
     */
    std::vector<double>
    mismatch(const VectorType &u_nonlocal, const VectorType &u_local) const;

    /** `J_h` without the Tikhonov term, summed over all ranks. */
    double
    objective(const VectorType &u_nonlocal, const VectorType &u_local) const;

    /**
     * The gradient of `1/2 sum_q w_q d_q^2` with respect to each model's
     * degrees of freedom, for a given mismatch @p d at this rank's points:
     * `E^T W d` and `-P^T W d`.
     */
    void
    mismatch_gradient(const std::vector<double> &d,
                      VectorType                &gradient_nonlocal,
                      VectorType                &gradient_local) const;

    /** The part of mismatch_gradient() of model @p k alone. */
    VectorType
    mismatch_gradient(const unsigned int k, const std::vector<double> &d) const;

    /**
     * `B^T W B x` for the fields @p u_nonlocal and @p u_local: the gradient
     * of the mismatch term at them, into @p gradient_nonlocal and
     * @p gradient_local.
     */
    void
    observe(const VectorType &u_nonlocal,
            const VectorType &u_local,
            VectorType       &gradient_nonlocal,
            VectorType       &gradient_local) const;

    /**
     * The diagonal of `B_k^T W B_k` over the degrees of freedom of model
     * @p k (`B_k` is `E` or `-P`): how strongly the mismatch observes each
     * degree of freedom directly, `sum_q w_q (B_k)_qi^2`.
     */
    VectorType
    observation_diagonal(const unsigned int k) const;

    /**
     * `B_k^T W B_k`, assembled over the degrees of freedom of model @p k:
     * the mismatch's gradient for a field of model @p k alone (the other's
     * zero) as one sparse product over that model's unknowns, instead of a
     * pass over all overlap points and back.
     */
    TrilinosWrappers::SparseMatrix
    observation_gram(const unsigned int k) const;

    /** The number of controls of both models. */
    types::global_dof_index
    n_controls() const;

    MPI_Comm
    communicator() const;

    std::array<const DiscreteModel *, 2> models;
    const OverlapQuadrature<dim>        &overlap;
    const double                         alpha;
    /**
     * Per model, its owned degrees of freedom and those the rows of this
     * rank's overlap points touch.
     */
    std::array<IndexSet, 2> overlap_columns;

  private:
    /**
     * This rank's overlap points in a numbering over all ranks (ranks in
     * order, each its points in order).
     */
    IndexSet points;
    /**
     * Per model the unsigned rows `E_q` or `P_q` of this rank's points, as
     * a distributed sparse matrix (points x the model's degrees of freedom):
     * Trilinos imports the values the rows read and exports the transposed
     * product's contributions to other ranks' degrees of freedom.
     */
    std::array<TrilinosWrappers::SparseMatrix, 2> observation;

    /**
     * `sum_q sum_{(i, b) in row q of B_k} contribution(q, b) e_i` over the
     * owned degrees of freedom of model @p k, for the unsigned rows `E_q`
     * or `P_q` of this rank's points.
     */
    VectorType
    sum_over_rows(
      const unsigned int                                k,
      const std::function<double(std::size_t, double)> &contribution) const;
  };

  /** A solution of the optimality system, with the solver's statistics. */
  struct CouplingSolution : SolverStatistics
  {
    /** Each model's field on its owned degrees of freedom. */
    std::array<TrilinosWrappers::MPI::Vector, 2> fields;
  };
} // namespace ltn

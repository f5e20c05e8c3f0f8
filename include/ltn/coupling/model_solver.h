#pragma once

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/coupling/coupling_system.h>

namespace ltn
{
  using namespace dealii;

  /**
   * One model's own solver, as the reduced-space method sees it: a black box
   * that solves the model's equations for given controls (forward) and the
   * transposed equations (adjoint). The model's equations split as
   * `A_ff u_f + A_fc theta = F_f - A_fx g` over free (f), control (c) and
   * fixed (x) degrees of freedom; `A_ff` is factorized once (UMFPACK).
   */
  class ModelSolver
  {
  public:
    ModelSolver(const DiscreteModel &model, const ModelUnknowns &unknowns);

    /**
     * The model's field on all degrees of freedom for controls @p theta;
     * with @p with_data, the load and fixed data enter, otherwise they are
     * taken as zero (the linear part of the control-to-state map).
     */
    Vector<double>
    forward(const Vector<double> &theta, const bool with_data) const;

    /**
     * The adjoint of the control-to-state map of forward() (without data):
     * for a gradient @p z with respect to all degrees of freedom, the
     * gradient with respect to the controls,
     * `z_c - A_fc^T A_ff^{-T} z_f`.
     */
    Vector<double>
    adjoint(const Vector<double> &z) const;

  private:
    const DiscreteModel &model;
    const ModelUnknowns &unknowns;
    SparsityPattern      free_free_sparsity, free_control_sparsity;
    SparseMatrix<double> free_free, free_control;
    Vector<double>       data_rhs;
    SparseDirectUMFPACK  direct;
  };
} // namespace ltn

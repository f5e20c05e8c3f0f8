#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/direct_solver.h>
#include <ltn/base/discrete_model.h>

#include <memory>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * A closed model's matrix `M` factorized once (MUMPS), for solves with `M`
   * and `M^T` (doc/discretization.md, 'The reduced space'). Outside the
   * free block
   * (controls and fixed degrees of freedom, O) the rows of `M` are
   * identities; the rows of hanging nodes (C, DiscreteModel::constrained)
   * are their constraints, `x_c - sum_k c_ck x_k = 0`, and their columns
   * are zero but for the diagonal (the assembly condensed them):
   * `M = [[M_FF, 0, M_FO], [M_CF, I, M_CO], [0, 0, I]]`.
   *
   * Where the model declares `M_FF` symmetric positive definite
   * (DiscreteModel::symmetric_free_block, with no eliminated degrees of
   * freedom: nonlocal diffusion, and the FEM models), the factorization
   * is the Cholesky-type `L D L^T` of `blockdiag(M_FF, I)`, half the
   * entries and flops of the `L U` of `M`; the solves move the rest to the
   * right-hand side:
   *
   *   M x = b:    blockdiag(M_FF, I) x = b - M_{.O} b_O, then
   *               x_C = b_C - (M_C. x) (off the diagonal);
   *   M^T y = g:  blockdiag(M_FF, I) y = g - (M_C.^T g_C)_F, then
   *               y_O = g_O - (M^T (y_F, y_C, 0))_O.
   *
   * Other models are factorized whole (`L U`).
   */
  class ModelDirectSolver
  {
  public:
    explicit ModelDirectSolver(const DiscreteModel &model);

    /** Solve `M x = b` (@p transpose: `M^T x = b`); @p x and @p b are
     * distinct vectors (b_C is read after x is written). */
    void
    solve(TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &b,
          const bool                           transpose) const;

    /**
     * The same for all @p b at once, the factors read once. Forward: the
     * free block's right-hand sides `b - M_{.O} b_O` and, after the solve
     * of `blockdiag(M_FF, I)`, the constrained rows `x_C = b_C - M_C. x`
     * off the diagonal, each one sparse product with all columns.
     */
    void
    solve(std::vector<TrilinosWrappers::MPI::Vector>       &x,
          const std::vector<TrilinosWrappers::MPI::Vector> &b,
          const bool                                        transpose) const;

    /** Is only the free block factorized (symmetric positive definite)? */
    bool
    factorizes_free_block() const;

  private:
    /** `g - (M_C.^T g_C)_F`: the right-hand side of `M^T y = g` for
     * `blockdiag(M_FF, I)`. */
    TrilinosWrappers::MPI::Vector
    free_block_transposed_rhs(const TrilinosWrappers::MPI::Vector &g) const;

    /** `y_O = g_O - (M^T (y_F, y_C, 0))_O` after `blockdiag(M_FF, I)`
     * solved for the rest of `M^T y = g`. */
    void
    complete_transposed(TrilinosWrappers::MPI::Vector &y) const;

    const DiscreteModel &model;
    /** The owned degrees of freedom outside the free block (O). */
    IndexSet outside;
    /** The owned free ones whose rows are equations (F). */
    IndexSet free;
    bool     free_block_only;
    /** Has the model constrained degrees of freedom on any rank? */
    bool any_constrained;
    /** `M`'s entries in the columns O, in the rows F and C (sparse
     * products: the columns and rows a solve needs, not all of `M`). */
    TrilinosWrappers::SparseMatrix to_outside;
    /** `M`'s rows C off their diagonal. */
    TrilinosWrappers::SparseMatrix constraints;
    std::unique_ptr<DirectSolver>  direct;
  };
} // namespace ltn

#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/coupling/direct_solver.h>

#include <memory>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * A closed model's matrix `M` factorized once (MUMPS), for solves with `M`
   * and `M^T` (doc/discretization.md, section 10). Outside the free block
   * (controls and fixed degrees of freedom, O) the rows of `M` are
   * identities, `M = [[M_FF, M_FO], [0, I]]`.
   *
   * Where the model declares `M_FF` symmetric positive definite
   * (DiscreteModel::symmetric_free_block, with no eliminated and no
   * constrained degrees of freedom: nonlocal diffusion, and the FEM models
   * on meshes without hanging nodes), the factorization
   * is the Cholesky-type `L D L^T` of `blockdiag(M_FF, I)`, half the
   * entries and flops of the `L U` of `M`; the solves move `M_FO` to the
   * right-hand side:
   *
   *   M x = b:    blockdiag(M_FF, I) x = b - M t + t,  t = (0, b_O);
   *   M^T y = g:  blockdiag(M_FF, I) y = g, then y_O = g_O - (M^T (y_F, 0))_O.
   *
   * Other models are factorized whole (`L U`).
   */
  class ModelDirectSolver
  {
  public:
    explicit ModelDirectSolver(const DiscreteModel &model);

    /** Solve `M x = b` (@p transpose: `M^T x = b`). */
    void
    solve(TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &b,
          const bool                           transpose) const;

    /** The same for all @p b at once, the factors read once. */
    void
    solve(std::vector<TrilinosWrappers::MPI::Vector>       &x,
          const std::vector<TrilinosWrappers::MPI::Vector> &b,
          const bool                                        transpose) const;

    /** Is only the free block factorized (symmetric positive definite)? */
    bool
    factorizes_free_block() const;

  private:
    /** `b - M t + t` with `t = (0, b_O)`: the right-hand side of `M x = b`
     * for `blockdiag(M_FF, I)`. */
    TrilinosWrappers::MPI::Vector
    free_block_rhs(const TrilinosWrappers::MPI::Vector &b) const;

    /** `y_O = g_O - (M^T (y_F, 0))_O` after `blockdiag(M_FF, I) y = g`. */
    void
    complete_transposed(TrilinosWrappers::MPI::Vector &y) const;

    const DiscreteModel &model;
    /** The owned degrees of freedom outside the free block. */
    IndexSet                      outside;
    bool                          free_block_only;
    std::unique_ptr<DirectSolver> direct;
  };
} // namespace ltn

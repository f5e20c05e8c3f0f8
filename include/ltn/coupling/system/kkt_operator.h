#pragma once

#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ltn/coupling/system/coupling_system.h>

namespace ltn
{
  using namespace dealii;

  /**
   * The full-space optimality system of solve_full_space_direct() as an
   * operator, without assembling it (doc/discretization.md, 'The
   * full-space system without a matrix'):
   *
   *   [ B^T W B + alpha R   s M^T Z       ] [ x  ]   [ 0   ]
   *   [ s Z M               s^2 (I - Z)   ] [ mu ] = [ s r ],
   *
   * on block vectors `[x_n | x_l | mu_n | mu_l]` over the models' owned
   * degrees of freedom; `Z` zeroes the entries at the controls (so `Z M` is
   * `C`, the model's matrix with its control rows emptied) and `R = I - Z`.
   * The multipliers are scaled by `s` (`mu = s mu_scaled`) and their rows
   * by `s`, which keeps the system symmetric: with `s` the ratio of the
   * sizes of `B^T W B` and `M`, a residual reduction means as much for the
   * optimality rows as for the models' equations (their scales differ by
   * the overlap weights, `h^d`). Each product costs one `M` and one `M^T`
   * per model, matrix-free or assembled, and one mismatch.
   */
  template <int dim>
  class KktOperator
  {
  public:
    using BlockVectorType = TrilinosWrappers::MPI::BlockVector;

    explicit KktOperator(const CouplingSystem<dim> &system);

    /** A zero vector of the system's unknowns. */
    BlockVectorType
    new_vector() const;

    /** The right-hand side `[0 | 0 | r_n | r_l]`. */
    BlockVectorType
    rhs() const;

    void
    vmult(BlockVectorType &dst, const BlockVectorType &src) const;

    /** `Z x` for a vector @p x of model @p k: zero at its controls. */
    void
    zero_controls(const unsigned int k, TrilinosWrappers::MPI::Vector &x) const;

    const CouplingSystem<dim> &system;
    /** The scale `s` of the multipliers. */
    double scale;
  };
} // namespace ltn

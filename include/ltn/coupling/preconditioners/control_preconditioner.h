#pragma once

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ltn/coupling/preconditioners/affine_product_field.h>
#include <ltn/coupling/preconditioners/control_coarse_space.h>
#include <ltn/coupling/preconditioners/surrogate_hessian_block.h>
#include <ltn/coupling/system/reduced_hessian.h>

#include <memory>
#include <optional>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** How the reduced Hessian is preconditioned (`Control preconditioner`). */
  struct ControlPreconditionerSettings
  {
    /** Precondition at all; without, the reduced-space CG runs plain. */
    bool enabled = true;
    /** The coarse level's polynomial degree; none: one level only. */
    std::optional<unsigned int> coarse_degree = 1u;
    /**
     * The nonlocal controls' block of the block-diagonal level: `D_n +
     * alpha I`, or the inverse of the SurrogateHessianBlock (`Nonlocal
     * control block`).
     */
    bool surrogate_nonlocal_block = false;
    /**
     * `s` of `Coupling/Collar layer weight`: `D_n` scaled by
     * `1 + s c_i / max_j c_j`, `c_i` the weight of control `i`'s bonds into
     * `Omega_n` in the lattice surrogate; 0: `D_n` alone.
     */
    double collar_layer_weight = 0;
    /**
     * Displacement fields added to the nonlocal controls' polynomial
     * columns of the reduced-space CG's coarse level (`Crack opening coarse
     * fields`).
     */
    std::vector<AffineProductField> nonlocal_coarse_fields;
  };

  /**
   * A block-diagonal preconditioner for the reduced Hessian
   * (doc/discretization.md, 'Preconditioning the reduced Hessian'):
   *
   *   P = diag(D_n + alpha I, H_ll),
   *
   * - `H_ll`, the Hessian block of the local controls (on `Gamma_c`),
   *   the Gram matrix of the observed local fields of the local controls (one
   *   forward solve of the local model per local control), factored by
   *   Cholesky, replicated
   *   on every rank. It carries the ill-conditioning: the high frequencies
   *   along `Gamma_c` are damped within a few elements of it and barely seen
   *   on the overlap, so its condition number grows like a power of `1/h`.
   *   There are few of them: they live on an interface of the coarse mesh.
   * - `D_n`, the diagonal of `S_n^T E^T W E S_n`: each control particle lies
   *   in the overlap and is observed directly with its volume, which bounds
   *   `H_nn` from below; its other part, through the nonlocal solve, is
   *   smooth. The nonlocal controls fill a volume collar of particles, far
   *   too many for explicit columns. It misses the smooth part of `H_nn`,
   *   the fields the collar drives into `Omega_n` that the overlap
   *   observes over its width `w`: the condition number of
   *   `D_n^{-1} H_nn` grows like `w / eps`. With `surrogate_nonlocal_block`
   *   the block is instead the SurrogateHessianBlock, which models that
   *   part and is inverted exactly (doc/discretization.md, 'A surrogate
   *   model of the nonlocal control block').
   *   With a `collar_layer_weight` `s > 0`, `D_n` is scaled by
   *   `1 + s c_i / max_j c_j` on the collar layer whose bonds reach into
   *   `Omega_n`, where the top modes of `D_n^{-1} H_nn` live ('A coarse
   *   level for the controls', "The collar layer's weight").
   */
  template <int dim>
  class ControlPreconditioner
  {
  public:
    using BlockVectorType = TrilinosWrappers::MPI::BlockVector;

    /**
     * With @p coarse_degree, a second level: the ControlCoarseSpace of
     * polynomials up to that degree, and `P` inside its balancing (the
     * full-space GMRES's elimination; the reduced-space CG deflates by
     * those polynomials instead, and takes `P` alone). Without
     * @p with_local_block, `P` is the identity on the local controls: the
     * reduced-space CG deflates by every local control, so its residuals
     * vanish there.
     */
    ControlPreconditioner(const ReducedHessian<dim>        &hessian,
                          const std::optional<unsigned int> coarse_degree,
                          const bool   with_local_block         = true,
                          const bool   surrogate_nonlocal_block = false,
                          const double collar_layer_weight      = 0);

    void
    vmult(BlockVectorType &dst, const BlockVectorType &src) const;

    /** The number of local controls, the size of the explicit block. */
    unsigned int
    n_explicit_controls() const;

    /** The number of coarse modes; 0 without a second level. */
    unsigned int
    n_coarse_modes() const;

    /**
     * The size of the saddle-point system that inverts the model of the
     * nonlocal controls' block (SurrogateHessianBlock); 0 without it.
     */
    types::global_dof_index
    n_nonlocal_block_unknowns() const;

  private:
    /** `P^{-1} src`, the block-diagonal level. */
    void
    apply_block_diagonal(BlockVectorType       &dst,
                         const BlockVectorType &src) const;

    /** `D_n + alpha I` over this rank's nonlocal controls. */
    TrilinosWrappers::MPI::Vector nonlocal_diagonal;
    /** The model of `H_nn`, or null (`D_n + alpha I` alone). */
    std::unique_ptr<const SurrogateHessianBlock> nonlocal_block;
    /** The Cholesky factor of `H_ll`. */
    LAPACKFullMatrix<double>                  local_block;
    std::unique_ptr<const ControlCoarseSpace> coarse;
  };
} // namespace ltn

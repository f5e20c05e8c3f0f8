#pragma once

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ltn/coupling/preconditioners/affine_product_field.h>
#include <ltn/coupling/system/reduced_hessian.h>

#include <functional>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The coarse level of the two-level preconditioner of the reduced Hessian
   * `H` (doc/discretization.md, 'A coarse level for the controls'): for
   * orthonormal columns `Z`,
   * `H Z` is computed once (one product per column), and `E = Z^T H Z` is
   * factored by Cholesky and replicated on every rank. balance() applies
   * the balancing preconditioner
   *
   *   Q + (I - Q H) P^{-1} (I - H Q),    Q = Z E^{-1} Z^T,
   *
   * which is symmetric positive definite whenever `P` is: CG stays CG. It
   * inverts `H` exactly on the span of `Z`.
   */
  class ControlCoarseSpace
  {
  public:
    using BlockVectorType = TrilinosWrappers::MPI::BlockVector;
    using Operator =
      std::function<void(BlockVectorType &, const BlockVectorType &)>;

    /** The coarse level spanned by @p Z (orthonormal) for the operator @p H. */
    ControlCoarseSpace(std::vector<BlockVectorType> Z, const Operator &H);

    /** Not copyable: a copied LAPACKFullMatrix forgets its factorization. */
    ControlCoarseSpace(const ControlCoarseSpace &) = delete;
    ControlCoarseSpace &
    operator=(const ControlCoarseSpace &) = delete;

    /** `dst = Q src + (I - Q H) P^{-1} (I - H Q) src`, `P^{-1}` @p smooth. */
    void
    balance(BlockVectorType       &dst,
            const BlockVectorType &src,
            const Operator        &smooth) const;

    /** The number of coarse modes, the columns of `Z`. */
    unsigned int
    size() const;

  private:
    /** `E^{-1} Y^T v` for the columns @p Y (`Z` or `H Z`). */
    Vector<double>
    coarse_solve(const std::vector<BlockVectorType> &Y,
                 const BlockVectorType              &v) const;

    std::vector<BlockVectorType> Z, HZ;
    /** The Cholesky factor of `E = Z^T H Z`. */
    LAPACKFullMatrix<double> coarse_matrix;
  };

  /**
   * A smooth field of the coarse space, on the controls of one model, with
   * the same field at all of that model's nodes where it has them.
   */
  struct PolynomialControlField
  {
    /** The model whose controls the field lives on. */
    unsigned int model;
    /** One of the given fields, not a monomial one. */
    bool given = false;
    /** The field at the controls, zero at the other model's. */
    TrilinosWrappers::MPI::BlockVector controls;
    /**
     * The field at every degree of freedom of the model (zero at the
     * components it has no polynomial for), when the model has
     * a lattice (ModelLattice::node_positions); otherwise empty.
     */
    TrilinosWrappers::MPI::Vector extension;
  };

  /**
   * The coarse modes of the two-level control preconditioner: per model in
   * @p models and per component of its field, the monomials of total degree
   * up to @p degree at its controls (coordinates centred and scaled to
   * [-1, 1] over that model's controls), then, where the model's field is a
   * displacement, the given @p fields, orthonormalized. The slowest modes
   * of the block-diagonally preconditioned Hessian are such smooth fields,
   * which both models represent and the overlap barely tells apart.
   */
  template <int dim>
  std::vector<PolynomialControlField>
  polynomial_control_fields(const ReducedHessian<dim>             &hessian,
                            const unsigned int                     degree,
                            const std::vector<unsigned int>       &models,
                            const std::vector<AffineProductField> &fields = {});

  /** One unit vector per control of model @p k, in that model's controls. */
  template <int dim>
  std::vector<TrilinosWrappers::MPI::Vector>
  unit_control_fields(const ReducedHessian<dim> &hessian, const unsigned int k);
} // namespace ltn

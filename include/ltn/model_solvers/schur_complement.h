#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>

#include <array>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * A model's system `M x = b` (with @p transpose, `M^T x = b`) with the
   * degrees of freedom `t` whose block of `M` is diagonal (the dilatation
   * of LPS, `DiscreteModel::eliminated`) eliminated (doc/discretization.md,
   * 'Iterative model solvers'). With `u` the rest, `M = [[A, B], [C, D]]`,
   *
   *   S u = g,  S = A - B D^-1 C,  g = b_u - B D^-1 b_t,
   *   t = D^-1 (b_t - C u),
   *
   * and the residual of the whole system is then `(g - S u, 0)`: a Krylov
   * method on `S` keeps its tolerance for `M`. A product with `S` is two
   * partial ones with `M`: its `t`-rows of `[v; 0]` (`C v`), then its
   * `u`-rows of `[v; -D^-1 C v]`; matrix-free, the two cost one whole
   * product, where a Krylov method on `M` preconditioned by the same
   * factorization needs three. Vectors keep the model's numbering, zero at
   * `t`. For a model without such degrees of freedom `S = M`.
   */
  class SchurComplement
  {
  public:
    /**
     * @p same_model: a Schur complement of the same model, whose rows near
     * the controls and fixed data (vmult_from_outside()) are taken instead
     * of found again.
     */
    SchurComplement(const DiscreteModel   &model,
                    const bool             transpose,
                    const SchurComplement *same_model = nullptr);

    /** `dst = S src`; the entries of @p src at `t` are ignored. */
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /**
     * `dst = S src` for @p src zero in the free block and at `t` (the
     * controls' and fixed data's values): only the rows within two bonds
     * of those degrees of freedom (one without `t`) are computed, the rest
     * are zero.
     */
    void
    vmult_from_outside(TrilinosWrappers::MPI::Vector       &dst,
                       const TrilinosWrappers::MPI::Vector &src) const;

    /**
     * `S src` at the degrees of freedom outside the free block and `t`
     * (the controls and fixed data); the other entries of @p dst are
     * unspecified. Only the rows that these read are computed.
     */
    void
    vmult_at_outside(TrilinosWrappers::MPI::Vector       &dst,
                     const TrilinosWrappers::MPI::Vector &src) const;

    /**
     * `dst = Z S Z src`, with `Z` zeroing all but the free degrees of
     * freedom that are kept: the free block `S_FF` of `S`, whose other rows
     * are identities (controls and fixed data).
     */
    void
    vmult_free_block(TrilinosWrappers::MPI::Vector       &dst,
                     const TrilinosWrappers::MPI::Vector &src) const;

    /** `Z v`: zero the entries of @p v outside the free block. */
    void
    restrict_to_free_block(TrilinosWrappers::MPI::Vector &v) const;

    /**
     * The free block on vectors of its own degrees of freedom only (44 to
     * 60 % of the model's on the 3D bars of benchmarks/scaling): entry `i`
     * of such a vector is the model's owned entry `free_positions()[i]`. A
     * Krylov method on the free block then updates and reduces only those.
     */
    TrilinosWrappers::MPI::Vector
    new_free_vector() const;

    /** This rank's free degrees of freedom, local positions, ascending. */
    const std::vector<unsigned int> &
    free_positions() const;

    /** The entries of @p v in the free block, as a vector of it. */
    void
    extract_free(TrilinosWrappers::MPI::Vector       &free_part,
                 const TrilinosWrappers::MPI::Vector &v) const;

    /** `v = Z^T free_part`: @p v zero outside the free block. */
    void
    insert_free(TrilinosWrappers::MPI::Vector       &v,
                const TrilinosWrappers::MPI::Vector &free_part) const;

    /** `dst = S_FF src` on vectors of the free block (new_free_vector()). */
    void
    vmult_free_vector(TrilinosWrappers::MPI::Vector       &dst,
                      const TrilinosWrappers::MPI::Vector &src) const;

    /** The right-hand side `g` of `S u = g` for @p b. */
    TrilinosWrappers::MPI::Vector
    reduce(const TrilinosWrappers::MPI::Vector &b) const;

    /** Complete @p x, holding `u`, with `t = D^-1 (b_t - C u)` for @p b. */
    void
    recover(TrilinosWrappers::MPI::Vector       &x,
            const TrilinosWrappers::MPI::Vector &b) const;

    /** Bytes this rank holds (the diagonal and work vectors). */
    std::size_t
    memory_consumption() const;

  private:
    /**
     * `dst = diag(mask) S diag(mask) src`; @p near_rows as for
     * product_of_work_vector().
     */
    void
    masked_product(TrilinosWrappers::MPI::Vector          &dst,
                   const TrilinosWrappers::MPI::Vector    &src,
                   const TrilinosWrappers::MPI::Vector    &mask,
                   const std::array<const RowRanges *, 2> &near_rows = {
                     {nullptr, nullptr}}) const;

    /**
     * `dst = S v` at the rows `u` (the other entries unspecified), for the
     * work vector `v` as the caller set it; overwrites `v`, and `w` unless
     * @p dst is `w`. With @p near_rows, only the rows `t` within
     * `near_rows[0]` and the rows `u` (or, without `t`, all rows) within
     * `near_rows[1]` are computed (DiscreteModel::vmult_rows()).
     */
    void
    product_of_work_vector(TrilinosWrappers::MPI::Vector          &dst,
                           const std::array<const RowRanges *, 2> &near_rows = {
                             {nullptr, nullptr}}) const;

    const DiscreteModel &model;
    const bool           transpose;
    /** Does the model have eliminated degrees of freedom on any rank? */
    bool eliminates = false;
    /** `1 / D` at `t`, 0 elsewhere. */
    TrilinosWrappers::MPI::Vector inverse_diagonal;
    /**
     * The owned positions of this rank's `t`, for the update of `t` in each
     * product, which then passes over them alone.
     */
    std::vector<unsigned int> eliminated_positions;
    /** 1 at `u`, 0 at `t`. */
    TrilinosWrappers::MPI::Vector kept;
    /** 1 at the free degrees of freedom in `u`, 0 elsewhere. */
    TrilinosWrappers::MPI::Vector free;
    /** Their owned positions, and the partition of vectors over them. */
    std::vector<unsigned int>             free_list;
    IndexSet                              free_partition;
    mutable TrilinosWrappers::MPI::Vector v, w;
    /**
     * The rows within 0, 1 and 2 bonds of the degrees of freedom outside
     * the free block and `t` (DiscreteModel::rows_near()).
     */
    std::vector<RowRanges> near_outside;
  };
} // namespace ltn

#pragma once

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>

namespace ltn
{
  using namespace dealii;

  /**
   * The preconditioner of a model's iterative solver (doc/discretization.md,
   * section 16): algebraic multigrid (Trilinos ML, one V-cycle) on the
   * model's surrogate, or on its matrix where it has none. Where the model
   * has eliminated degrees of freedom `t` (the dilatation of LPS), whose
   * block `D` of `M` is diagonal, `M = [[A, B], [C, D]]` factors as
   *
   *   M = [[I, B D^-1], [0, I]] [[S, 0], [C, D]],  S = A - B D^-1 C,
   *
   * and the preconditioner is this factorization with AMG on the surrogate
   * in place of `S^-1`:
   *
   *   v = r_u - B D^-1 r_t,  u = AMG(v),  t = D^-1 (r_t - C u),
   *
   * two products with `M` (of `M^T` when preconditioning the transposed
   * system) per application. The preconditioned operator then has the
   * eigenvalues of `AMG(S)` and ones.
   */
  class ModelPreconditioner
  {
  public:
    /** Build for @p model, for `M` or, with @p transpose, for `M^T`. */
    ModelPreconditioner(const DiscreteModel &model, const bool transpose);

    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /** Bytes this rank holds for the multigrid hierarchy (estimated). */
    std::size_t
    memory_consumption() const;

  private:
    /** `M x` or `M^T x`. */
    void
    apply_model(TrilinosWrappers::MPI::Vector       &dst,
                const TrilinosWrappers::MPI::Vector &src) const;

    const DiscreteModel              &model;
    const bool                        transpose;
    TrilinosWrappers::PreconditionAMG amg;
    /** Does the model have eliminated degrees of freedom on any rank? */
    bool eliminates = false;
    /** `1 / D` at the eliminated degrees of freedom, 0 elsewhere. */
    TrilinosWrappers::MPI::Vector inverse_diagonal;
    /** 1 at the other degrees of freedom, 0 at the eliminated ones. */
    TrilinosWrappers::MPI::Vector         kept;
    mutable TrilinosWrappers::MPI::Vector t, v, w;
  };
} // namespace ltn

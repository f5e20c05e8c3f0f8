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
   * eliminates degrees of freedom (SchurComplement), it stands in for the
   * inverse of the Schur complement; the surrogate's rows there are
   * identities. The same hierarchy serves `M` and `M^T`.
   */
  class ModelPreconditioner
  {
  public:
    explicit ModelPreconditioner(const DiscreteModel &model);

    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /** Bytes this rank holds for the multigrid hierarchy (estimated). */
    std::size_t
    memory_consumption() const;

  private:
    TrilinosWrappers::PreconditionAMG amg;
  };
} // namespace ltn

#pragma once

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/model_solvers/component_v_cycle.h>
#include <ltn/model_solvers/stencil_matrix.h>

#include <array>
#include <memory>

namespace ltn
{
  using namespace dealii;

  /** The tuning of ModelPreconditioner on a lattice surrogate. */
  struct SurrogateMultigridSettings
  {
    /**
     * The weight of the lattice surrogate's inverse diagonal that the
     * preconditioner adds to its multigrid cycle, over the ratio of the
     * long-wave moduli (LatticeSurrogate::long_wave_ratio;
     * doc/discretization.md, 'Iterative model solvers'): the two terms
     * overlap at wavelengths between `h` and `eps`, hence less than 1; one
     * value serves 2D diffusion (`eps = 3h`), 2D LPS with a crack and the 3D
     * cracked bar (`eps = 2h`) alike.
     */
    double short_wave_factor = 0.6;
    /**
     * The most rows the surrogate's multigrid hierarchy leaves on its
     * coarsest level, which it solves directly, on a 2D and on a 3D lattice
     * (doc/discretization.md, 'Iterative model solvers', "The hierarchy's
     * size"): the coarse levels of a 3D lattice are dense enough that a
     * direct solve of a thousand rows or more costs as much as the finest
     * level's smoothing; a 2D lattice's stay sparse, so that a larger
     * coarsest level saves iterations at little cost.
     */
    std::array<unsigned int, 2> coarsest_rows = {{2000, 200}};
  };



  /**
   * The preconditioner of a model's iterative solver (doc/discretization.md,
   * 'Iterative model solvers'): algebraic multigrid (Trilinos ML, one
   * V-cycle) on the
   * model's matrix, or on its scalar surrogate, one V-cycle per component
   * the surrogate stands in for, plus a weight
   * (SurrogateMultigridSettings::short_wave_factor) times the surrogate's
   * inverse diagonal. Where the model eliminates degrees
   * of freedom (SchurComplement) it stands in for the inverse of the Schur
   * complement, and is the identity at the eliminated ones. The same
   * hierarchy serves `M` and `M^T`.
   */
  class ModelPreconditioner
  {
  public:
    /**
     * With @p subset (owned positions, ascending: SchurComplement's free
     * degrees of freedom), vmult_subset() works on vectors of those entries
     * only; a subset needs the model's lattice surrogate.
     */
    explicit ModelPreconditioner(
      const DiscreteModel              &model,
      const std::vector<unsigned int>  &subset   = {},
      const SurrogateMultigridSettings &settings = {});

    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /**
     * `Z P Z^T` on vectors of the subset's entries (entry `i` the model's
     * owned entry `subset[i]`), `Z` the restriction to them.
     */
    void
    vmult_subset(TrilinosWrappers::MPI::Vector       &dst,
                 const TrilinosWrappers::MPI::Vector &src) const;

    /** Bytes this rank holds for the multigrid hierarchy (estimated). */
    std::size_t
    memory_consumption() const;

  private:
    /** `node_out` the V-cycle applied to each column of `node_in`. */
    void
    apply_cycle() const;

    /** Is `amg` built on the surrogate (not on the matrix)? */
    const bool         on_surrogate;
    const unsigned int node_dofs;
    const unsigned int surrogate_components;
    /** LatticeSurrogate::nodes. */
    const std::vector<unsigned int> nodes;
    /**
     * The model's matrix with identity rows at its constrained degrees of
     * freedom, which `amg` is built on when there are any; else empty.
     */
    TrilinosWrappers::SparseMatrix    amg_matrix;
    TrilinosWrappers::PreconditionAMG amg;
    /**
     * The surrogate's stencil, which gives the finest level of `amg` its
     * product where its rows are one; else empty.
     */
    std::unique_ptr<StencilMatrix> stencil;
    /**
     * The V-cycle on all components at once, where it repeats `amg`'s
     * (ComponentVCycle::usable()); else empty.
     */
    std::unique_ptr<ComponentVCycle> cycle;
    /**
     * A vector's values at the surrogate's nodes, a column per component,
     * and the cycle's result: all components at once, so that the
     * interleaved gather and scatter pass over a vector once.
     */
    std::unique_ptr<Epetra_MultiVector> node_in, node_out;
    /**
     * The short-wave weight over the surrogate's diagonal, per owned row.
     */
    std::vector<double> short_wave_scaling;
    /** The subset of the constructor. */
    std::vector<unsigned int> subset;
    /**
     * On the surrogate: per component `c` and node `i`, at `c n + i`, the
     * entry of a subset's vector the node's component is, or
     * `numbers::invalid_unsigned_int` if it is outside the subset.
     */
    std::vector<unsigned int> subset_entry;
    /**
     * Is the subset's entry of node `i`'s component `c` always
     * `surrogate_components i + c`, every entry one of them? (Then
     * `subset_entry` is left empty.)
     */
    bool interleaved = false;
  };
} // namespace ltn

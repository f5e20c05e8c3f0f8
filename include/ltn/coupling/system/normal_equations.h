#pragma once

#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <functional>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * Normal equations `(F^T W F + alpha I) x = b` with `F = B V` for the
   * controls `x = [x_0; x_1]` of two models, as the reduced space has them
   * (doc/discretization.md, 'The reduced space' and 'A coarse level for
   * the controls'): @p forward maps model k's
   * controls to its state (`V_k`, a forward solve, from an initial guess of
   * the state if one is given, else from the solver's own), @p observe takes
   * both states to an observation (`B`, the overlap mismatch at this rank's
   * points; an empty state, on every rank, is a zero one), @p
   * observe_transpose takes an observation `d` to model k's part of the
   * states' gradient `B^T W d`, and @p adjoint maps states' gradients to
   * the controls' (`V^T`, the adjoint solves).
   */
  struct NormalEquations
  {
    using BlockVectorType = TrilinosWrappers::MPI::BlockVector;
    using VectorType      = TrilinosWrappers::MPI::Vector;
    using States          = std::array<VectorType, 2>;
    using Observation     = std::vector<double>;

    std::function<VectorType(unsigned int      k,
                             const VectorType &controls,
                             const VectorType *initial_state)>
                                               forward;
    std::function<Observation(const States &)> observe;
    std::function<VectorType(unsigned int k, const Observation &)>
                                                   observe_transpose;
    std::function<BlockVectorType(const States &)> adjoint;
    /** A zero state of model k. */
    std::function<VectorType(unsigned int k)> new_state;
    /**
     * Nonzero exactly at the unknowns of model k that @p observe reads and
     * @p observe_transpose writes (for any rank's points).
     */
    std::function<VectorType(unsigned int k)> observed_unknowns;
    double                                    alpha;
    /**
     * Optional: the states of several controls of model k at once, as
     * forward() without a guess gives them one by one (a factorized model
     * solves for all of them reading its factors once).
     */
    std::function<std::vector<VectorType>(unsigned int k,
                                          const std::vector<VectorType> &)>
      forward_columns = {};
    /**
     * Optional, per model: `B_k^T W B_k u` for states `u` of model k alone
     * (the other's zero) from an assembled matrix, the gradients that
     * observe_transpose(k, observe(u)) gives by a pass over the overlap
     * points and back. A coarse column whose entries of `E` need no other
     * model's gradient then skips that pass. Called with @p n states, this
     * rank's entries of each (the model's locally owned size) one after
     * the other from @p u; writes the gradients the same way from @p g:
     * one sparse product for many columns.
     */
    std::array<std::function<void(unsigned int n, const double *u, double *g)>,
               2>
      observe_alone = {};

    /** `F^T W d`: the adjoint solves of the observed residual @p d. */
    BlockVectorType
    gradient(const Observation &d) const;
  };
} // namespace ltn

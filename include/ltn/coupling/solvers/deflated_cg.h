#pragma once

#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/vector.h>

#include <ltn/coupling/solvers/ritz_values.h>

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

  /**
   * The coarse space of a deflated CG on NormalEquations
   * (doc/discretization.md, 'A coarse level for the controls'): columns
   * `Z`, each in the controls
   * of one model k and kept only there, their states `V_k z` (one forward
   * solve each, no adjoint solve), and the Cholesky factor of
   * `E = Z^T A Z = (B V Z)^T W (B V Z) + alpha Z^T Z`, replicated on every
   * rank. The states, not their observations, are kept: a column of the
   * local model costs a vector of the local model's size. Each model's states
   * are packed into dense panels of this rank's entries, so that `E` and the
   * products with `(V Z)^T` are BLAS products, not one distributed inner
   * product per pair of columns.
   */
  class DeflationSpace
  {
  public:
    using BlockVectorType = NormalEquations::BlockVectorType;
    using VectorType      = NormalEquations::VectorType;
    using Observation     = NormalEquations::Observation;

    /**
     * A column of `Z`: controls of one model, zero on the other's, and
     * optionally a guess of its state (else empty), where its forward solve
     * starts.
     */
    struct Column
    {
      unsigned int model;
      VectorType   controls;
      VectorType   state_guess = {};
    };

    /**
     * @p block_bytes bounds a panel of states and a block of the gradients
     * `E` is formed from (tens of MB: never all of a model's states at
     * once).
     */
    DeflationSpace(std::vector<Column>    Z,
                   const NormalEquations &equations,
                   std::size_t            block_bytes = std::size_t(64) << 20);

    /** Not copyable: a copied LAPACKFullMatrix forgets its factorization. */
    DeflationSpace(const DeflationSpace &) = delete;
    DeflationSpace &
    operator=(const DeflationSpace &) = delete;

    /**
     * `E^{-1} Z^T A v` for @p v with its observation @p observed (`F v`):
     * `Z^T A v = (V Z)^T B^T W F v + alpha Z^T v` needs no adjoint solve.
     */
    Vector<double>
    solve_product(const BlockVectorType &v, const Observation &observed) const;

    /**
     * `v += Z c` and `observed += B (V Z) c`. The combined state `V Z c` is
     * formed at the observed unknowns alone.
     */
    void
    add(const Vector<double> &c,
        BlockVectorType      &v,
        Observation          &observed) const;

    /** `states += V Z c`, per model with columns. */
    void
    add_states(const Vector<double> &c, NormalEquations::States &states) const;

    /**
     * Do the columns span all of model @p k's controls? Then a vector
     * orthogonal to `Z`, as the deflated CG's residuals are, is zero there.
     */
    bool
    spans(const unsigned int k) const;

    /** The number of columns. */
    unsigned int
    size() const;

  private:
    /** One model's columns and their states. */
    struct ModelStates
    {
      /** The numbers of the model's columns in `Z`. */
      std::vector<unsigned int> columns;
      /** This rank's entries of a state. */
      std::size_t local_size = 0;
      /**
       * The states in panels of `panel_width` columns (the last one may be
       * narrower), column-major with `local_size` rows: a panel is tens of
       * MB, never the whole of a model's states, which would have to exist
       * beside their vectors while they are packed.
       */
      unsigned int                     panel_width = 1;
      std::vector<std::vector<double>> panels;

      /** The entries of the state in the @p a-th column of the model. */
      const double *
      state(const unsigned int a) const;

      /**
       * A gradient `B^T W d` is nonzero only at the observed unknowns (those
       * of the overlap's points, of their cells for the FEM model: 16,112
       * of the 35,440 of the cracked plate's graded mesh at spacing 1/320),
       * and an observation reads only them: the products with the states
       * are taken over these rows alone, from copies of the panels
       * restricted to them.
       */
      std::vector<std::size_t>         observed_rows;
      std::vector<std::vector<double>> packed_panels;

      /** Pack the panels' observed rows. */
      void
      pack_observed_rows();
    };

    /** Form `E` and factor it. */
    void
    form_coarse_matrix();

    /**
     * `y += (V_k Z_k)^T g` at model @p k's columns, over this rank's entries
     * of its gradients @p g (`local_size` rows, @p n_columns columns,
     * column-major): `y` is `m x n_columns`, column-major, with `m` the
     * model's columns. Only the rows of `y` from @p first_state on are
     * formed.
     */
    void
    add_state_products(const unsigned int   k,
                       const double        *g,
                       const unsigned int   n_columns,
                       std::vector<double> &y,
                       const unsigned int   first_state = 0) const;

    /** `E^{-1} y` in place. */
    void
    coarse_solve(Vector<double> &y) const;

    /** `z . v`, over the controls of @p z's model. */
    double
    dot(const Column &z, const BlockVectorType &v) const;

    const NormalEquations &equations;
    const MPI_Comm         communicator;
    /** The columns, each kept only in its model's controls. */
    std::vector<Column>        Z;
    std::array<ModelStates, 2> states;
    LAPACKFullMatrix<double>   coarse_matrix;
    const std::size_t          block_bytes;
  };

  /**
   * Deflated preconditioned CG (Saad, Yeung, Erhel and Guyomarc'h 2000) on
   * @p equations, with the coarse space @p coarse and the preconditioner
   * @p precondition (`dst = P^{-1} src`, symmetric positive definite): the
   * iterates start from the coarse solution and move only A-orthogonally to
   * `Z`. Each iteration costs one product with `F` (of the preconditioned
   * residual: forward solves) and one with `F^T W` (of the search direction,
   * whose observation is updated by the same recurrence as the direction:
   * adjoint solves), as plain CG does; the start costs one product with
   * `F^T W`. In exact arithmetic the iterates are those of CG with the
   * balancing preconditioner of ControlCoarseSpace started from the coarse
   * solution, which needs `A Z`: an adjoint solve per column more.
   *
   * The right-hand side is `b = -F^T W d` for the observation @p data (the
   * mismatch of the models' states without controls, in the reduced
   * space): the start needs no product with `F^T W` of `b` beside that of
   * the start's residual. @p x is overwritten. The iteration stops as
   * @p control says of the residual norm `|b - A x|` (in its recursive
   * form), so its tolerance is the caller's, given `|b|`; before each
   * iteration's products, @p before_products is called with that norm (an
   * outer method relaxes its inner solves with it). Throws
   * SolverControl::NoConvergence as deal.II's solvers do.
   *
   * If @p states is given (both models' vectors), `V x` is added to it: the
   * states of the iterates follow from those the iterations' forward solves
   * give, by the recurrences of the iterates, so they are exact to the inner
   * solves' tolerances, and a final solve for `x` starting from them has
   * little left to do.
   *
   * If @p ritz_values is given, it records each step length and direction
   * coefficient: the Ritz values of the preconditioned, deflated operator.
   */
  void
  solve_deflated_cg(
    const NormalEquations &equations,
    const DeflationSpace  &coarse,
    const std::function<void(NormalEquations::BlockVectorType &,
                             const NormalEquations::BlockVectorType &)>
                                                    &precondition,
    const NormalEquations::Observation              &data,
    NormalEquations::BlockVectorType                &x,
    SolverControl                                   &control,
    const std::function<void(double residual_norm)> &before_products,
    NormalEquations::States                         *states      = nullptr,
    RitzValues                                      *ritz_values = nullptr);
} // namespace ltn

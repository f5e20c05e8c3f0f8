#pragma once

#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ltn/coupling/system/normal_equations.h>

#include <array>
#include <functional>
#include <vector>

namespace ltn
{
  using namespace dealii;

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
} // namespace ltn

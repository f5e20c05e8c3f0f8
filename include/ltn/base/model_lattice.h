#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * A particle model's lattice surrogate for algebraic multigrid
   * (doc/discretization.md, 'Iterative model solvers'; built by
   * assemble_lattice_surrogate()): a scalar operator `L` close to the
   * model's (spectrally) in each of the first `components` components of a
   * node, which it does not couple (a vector Laplacian); the model's other
   * components are `DiscreteModel::eliminated`.
   */
  struct LatticeSurrogate
  {
    /**
     * `L`, one row per node of `Omega_n`, the collar's nodes being fixed by
     * the model.
     */
    TrilinosWrappers::SparseMatrix matrix;
    /**
     * `L`'s coupling to the collar, `C`: per row of `matrix`, the weight of
     * each bond it drops to a node of the collar, in the column of that node
     * (columns partitioned like the owned nodes). For values `y` on the
     * collar, `L v = C y` gives their discrete harmonic extension into
     * `Omega_n`, which the preconditioner of the nonlocal controls' Hessian
     * block observes (SurrogateHessianBlock).
     */
    TrilinosWrappers::SparseMatrix collar;
    /**
     * The node of each of this rank's rows of `matrix`, as its place among
     * the owned nodes; at the other nodes a preconditioner built on `L` is
     * the identity.
     */
    std::vector<unsigned int> nodes;
    /** The components `L` stands in for: the first ones of each node. */
    unsigned int components = 1;
    /** The lattice's dimension (2 or 3). */
    unsigned int dimension = 0;
    /**
     * The model's operator tends at long wavelengths to a modulus times the
     * Laplacian, `L` to `diagonal h^2 / (2 dim)` times it; their ratio
     * scales the short-wave term a preconditioner adds to its cycle on `L`
     * (ModelSolverSettings::short_wave_factor).
     */
    double long_wave_ratio = 0;
  };



  /**
   * A particle model's lattice as the solvers that exploit it see it: nodes
   * with `node_dofs` degrees of freedom each, numbered `node_dofs * node + c`
   * in the order of the model's owned ones, their positions, and the lattice
   * surrogate. The model describes how to build the surrogate; a solver that
   * needs it builds it on its first request (collective), so that a model
   * solved otherwise never holds it.
   *
   * It refers to the particle model that made it (its lattice and cracks):
   * no copy may outlive that model.
   */
  class ModelLattice
  {
  public:
    ModelLattice(const unsigned int                      node_dofs,
                 std::vector<std::array<double, 3>>      node_positions,
                 std::function<void(LatticeSurrogate &)> build_surrogate);

    /** Degrees of freedom per node. */
    const unsigned int node_dofs;
    /** Per owned node, where it sits (unused coordinates 0). */
    const std::vector<std::array<double, 3>> node_positions;

    /** The surrogate, built on the first call: collective. */
    const LatticeSurrogate &
    surrogate() const;

    /** Bytes this rank holds for the surrogate, once built. */
    std::size_t
    memory_consumption() const;

  private:
    std::function<void(LatticeSurrogate &)>   build_surrogate;
    mutable std::unique_ptr<LatticeSurrogate> built;
  };
} // namespace ltn

#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/direct_solver.h>
#include <ltn/base/discrete_model.h>
#include <ltn/model_solvers/model_solver.h>

#include <memory>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * A model of the nonlocal controls' block of the reduced Hessian, and its
   * inverse (doc/discretization.md, 'A surrogate model of the nonlocal
   * control block'). With the nonlocal model's
   * free (f) and control (c) unknowns, its field for controls `y` is `y` on
   * the collar and `G y = -(A^ff)^{-1} A^fc y` in `Omega_n`; the particle
   * quadrature observes each particle alone, so
   *
   *   H_nn = D_n + alpha I + G^T W_f G,
   *
   * `W_f` the observation weights of the free particles. `G` is replaced by
   * the lattice surrogate's harmonic extension, `G~ = L^{-1} C` per field
   * component the surrogate stands in for (LatticeSurrogate: `matrix`,
   * `collar`), which is right for the smooth control fields that
   * `D_n` alone misses:
   *
   *   H~ = D + sum_c C_c^T L^{-1} W_c L^{-1} C_c,
   *
   * `D` the given diagonal (`D_n + alpha I`). `H~ y = r` is the first row
   * of the sparse saddle-point system
   *
   *   [ D      0     -C^T ] [ y ]   [ r ]
   *   [ 0      W      L   ] [ v ] = [ 0 ]
   *   [ -C     L      0   ] [ l ]   [ 0 ]
   *
   * (per component; `v = L^{-1} C y` the surrogate's field, `l = -L^{-1} W
   * v`), which is factorized once (MUMPS): solve() costs one pair of
   * triangular solves of a matrix about three times the surrogate's size.
   */
  class SurrogateHessianBlock
  {
  public:
    /**
     * For the particle model @p model, solved by @p solver (whose control
     * numbering the vectors use), with `D` = @p diagonal over the controls
     * and the observation weights @p observation over the model's degrees
     * of freedom (CouplingSystem::observation_diagonal).
     */
    SurrogateHessianBlock(const DiscreteModel                 &model,
                          const ModelSolver                   &solver,
                          const TrilinosWrappers::MPI::Vector &diagonal,
                          const TrilinosWrappers::MPI::Vector &observation);

    ~SurrogateHessianBlock();

    /** `dst = H~ src`, over the controls (factorizes `L` on first use). */
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /** `dst = H~^{-1} src`. */
    void
    solve(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /** The size of the saddle-point system. */
    types::global_dof_index
    n_saddle_point_unknowns() const;

  private:
    /** Assemble the saddle-point system's matrix. */
    void
    assemble_saddle_point();

    const DiscreteModel &model;
    /** The model's lattice and surrogate (DiscreteModel::lattice). */
    const ModelLattice                  &lattice;
    const LatticeSurrogate              &surrogate;
    const ModelSolver                   &solver;
    const TrilinosWrappers::MPI::Vector &diagonal;
    /** Per component, `W_c` at the surrogate's rows. */
    std::vector<TrilinosWrappers::MPI::Vector> weights;
    /** This rank's unknowns of the saddle-point system: `y`, `v`, `l`. */
    IndexSet                       saddle_point_owned;
    TrilinosWrappers::SparseMatrix saddle_point;
    std::unique_ptr<DirectSolver>  saddle_point_solver;
    /** `L`'s factorization, for vmult(). */
    mutable std::unique_ptr<DirectSolver> surrogate_solver;
    /** Work vectors of the saddle-point system's layout. */
    mutable TrilinosWrappers::MPI::Vector saddle_point_rhs,
      saddle_point_solution;
  };
} // namespace ltn

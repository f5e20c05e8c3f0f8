#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/model_lattice.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** What a degree of freedom of a model is to the coupling. */
  enum class DofRole : unsigned char
  {
    /** An unknown of the model's own equations. */
    free,
    /** A virtual control: `theta_n` on the control collar, `theta_l` on
       `Gamma_c`. */
    control,
    /** Fixed by physical data (volume constraint or Dirichlet condition). */
    fixed
  };

  /**
   * The rows of `M` a product needs: all, or only those of the degrees of
   * freedom a SchurComplement keeps (not `DiscreteModel::eliminated`), or
   * only those of the eliminated ones.
   */
  enum class RowSubset : unsigned char
  {
    all,
    kept,
    eliminated
  };

  /**
   * Rows of a product on one rank: ranges `[first, end)` of positions among
   * its owned values, ascending and disjoint.
   */
  using RowRanges = std::vector<std::pair<unsigned int, unsigned int>>;

  /**
   * A model's operator `M` applied without an assembled matrix (the
   * LatticeOperator of particle models), on vectors over the model's owned
   * degrees of freedom.
   */
  class MatrixFreeOperator
  {
  public:
    virtual ~MatrixFreeOperator() = default;

    /**
     * `M src` (@p transpose: `M^T src`) at the rows of @p rows; the other
     * entries of @p dst are unspecified. With @p within, the rows outside
     * those ranges are computed as if @p src were zero wherever the rows
     * within do not read it: exact wherever it is (rows_near()).
     */
    virtual void
    vmult_rows(TrilinosWrappers::MPI::Vector       &dst,
               const TrilinosWrappers::MPI::Vector &src,
               const bool                           transpose,
               const RowSubset                      rows,
               const RowRanges                     *within) const = 0;

    /**
     * This rank's rows within @p layers bonds of the nonzero entries of
     * @p marked, for each number of layers from 0 to @p layers: layer 0
     * the particles of the nonzero entries, layer `l + 1` those that layer
     * `l` reads or that read it (the bonds are symmetric), all their rows.
     * A product of a vector that is zero outside layer 0 is zero outside
     * layer 1 (of `M` and of `M^T`), and its product again outside layer
     * 2. Collective.
     */
    virtual std::vector<RowRanges>
    rows_near(const TrilinosWrappers::MPI::Vector &marked,
              const unsigned int                   layers) const = 0;

    /** Bytes this rank holds for the operator. */
    virtual std::size_t
    memory_consumption() const = 0;
  };

  /**
   * The narrow interface through which the coupling sees a model, distributed
   * over the ranks of `communicator`: each rank owns the rows of some degrees
   * of freedom (`owned`) and reads the values of those its rows touch
   * (`relevant`, which contains `owned`).
   *
   * The model is closed by its controls: `matrix` `M` and `rhs` `r` hold
   *
   *   free dof i:     sum_j A_ij x_j = F_i    (the model's own equation),
   *   fixed dof i:    x_i = g_i               (physical data),
   *   control dof i:  x_i = 0                 (identity row, zero data),
   *
   * so that the model's field for controls `theta` solves
   * `M x = r + S theta`, with `S` placing `theta` in the control rows.
   */
  struct DiscreteModel
  {
    DiscreteModel()                      = default;
    DiscreteModel(const DiscreteModel &) = delete;
    DiscreteModel &
    operator=(const DiscreteModel &) = delete;

    MPI_Comm communicator = MPI_COMM_SELF;
    IndexSet owned;
    IndexSet relevant;
    /** `M` assembled; empty when `matrix_free` holds it instead. */
    TrilinosWrappers::SparseMatrix matrix;
    /** `M` applied without a matrix, or null. */
    std::shared_ptr<const MatrixFreeOperator> matrix_free;
    TrilinosWrappers::MPI::Vector             rhs;
    /** The owned control and fixed degrees of freedom. */
    IndexSet controls;
    IndexSet fixed;
    /**
     * The owned free degrees of freedom whose rows are constraints, not
     * equations: `x_i - sum_k c_ik x_k = 0` for a hanging node of a local
     * mesh. Algebraic multigrid sees them as identity rows.
     */
    IndexSet constrained;
    /**
     * Per owned control, in the order of `controls`: where it sits (unused
     * coordinates 0) and which component of the field it holds. The coarse
     * space of the reduced Hessian's preconditioner evaluates smooth fields
     * there.
     */
    std::vector<std::array<double, 3>> control_positions;
    std::vector<unsigned int>          control_components;
    /**
     * @name The structure of `M` that the model's solvers exploit.
     */
    /** @{ */
    /**
     * A particle model's lattice: its nodes and the surrogate that
     * multigrid and the control preconditioners build from it on demand;
     * null for models not numbered by nodes (the FEM models).
     */
    std::shared_ptr<const ModelLattice> lattice;
    /**
     * The owned degrees of freedom whose block of `M` is diagonal and
     * which a preconditioner eliminates first (the dilatation of LPS).
     */
    IndexSet eliminated;
    /**
     * Is the block of the Schur complement `S` (SchurComplement) on the
     * free degrees of freedom that are neither `eliminated` nor
     * `constrained` symmetric positive definite, and so the surrogate's?
     * Particle models' are (their operator is the Hessian of an energy):
     * their solvers may then use CG on it, for `M` and `M^T` alike
     * (doc/discretization.md, 'Iterative model solvers'; SchurComplement's
     * free block
     * keeps constrained rows, so not where there are any). So are the FEM
     * models' (symmetric bilinear forms, hanging nodes condensed), which a
     * direct solver then factorizes alone (ModelDirectSolver, 'The reduced
     * space').
     */
    bool symmetric_free_block = false;
    /**
     * Does `M` couple only the unknowns of a mesh's cells (the FEM models)?
     * A direct solver then orders it by nested dissection, not by the
     * minimum degree that suits nonlocal stencils' wide rows (DirectSolver).
     */
    bool mesh_couplings = false;
    /** The near null space for AMG: per mode, a flag per owned dof. */
    std::vector<std::vector<bool>> constant_modes;
    /** @} */

    /** `dst = M src`, assembled or matrix-free. */
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /** `dst = M^T src`. */
    void
    Tvmult(TrilinosWrappers::MPI::Vector       &dst,
           const TrilinosWrappers::MPI::Vector &src) const;

    /**
     * `M src` (@p transpose: `M^T src`) at the rows of @p rows; the other
     * entries of @p dst are unspecified. Matrix-free, the other rows are not
     * computed, and with @p within (MatrixFreeOperator::vmult_rows()) those
     * outside it as if @p src were zero where they read it; assembled, the
     * whole product is computed.
     */
    void
    vmult_rows(TrilinosWrappers::MPI::Vector       &dst,
               const TrilinosWrappers::MPI::Vector &src,
               const bool                           transpose,
               const RowSubset                      rows,
               const RowRanges                     *within = nullptr) const;

    /**
     * MatrixFreeOperator::rows_near(); assembled, every layer is all owned
     * rows (the whole product is computed anyway).
     */
    std::vector<RowRanges>
    rows_near(const TrilinosWrappers::MPI::Vector &marked,
              const unsigned int                   layers) const;

    /**
     * Bytes this rank holds for `M`, the right side and the lattice's
     * surrogate (once built).
     */
    std::size_t
    memory_consumption() const;

    /** The role of an owned degree of freedom. */
    DofRole
    role(const types::global_dof_index i) const;

    /** A zero vector over the owned degrees of freedom. */
    TrilinosWrappers::MPI::Vector
    new_vector() const;

    /** @p field with its values on the relevant degrees of freedom. */
    TrilinosWrappers::MPI::Vector
    ghosted(const TrilinosWrappers::MPI::Vector &field) const;

    /** The number of control degrees of freedom on all ranks. */
    types::global_dof_index
    n_controls() const;

    /**
     * Fill `control_positions` and `control_components` from
     * @p position_of and @p component_of, functions of an owned control.
     */
    template <int dim, typename PositionOf, typename ComponentOf>
    void
    locate_controls(const PositionOf  &position_of,
                    const ComponentOf &component_of)
    {
      control_positions.clear();
      control_components.clear();
      for (const auto i : controls)
        {
          control_positions.push_back(padded<dim>(position_of(i)));
          control_components.push_back(component_of(i));
        }
    }

    /** @p x with its unused coordinates 0. */
    template <int dim>
    static std::array<double, 3>
    padded(const Point<dim> &x)
    {
      std::array<double, 3> p = {{0., 0., 0.}};
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = x[d];
      return p;
    }
  };
} // namespace ltn

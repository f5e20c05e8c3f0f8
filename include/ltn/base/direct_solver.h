#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_MultiVector.h>

#include <memory>
#include <stdexcept>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * Thrown by DirectSolver when MUMPS finds the matrix numerically singular
   * (INFOG(1) = -10): with a small pivot threshold that can be round-off,
   * and a larger threshold may still factor it.
   */
  struct SingularFactorization : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  /**
   * A sparse direct solver for a distributed Trilinos matrix: MUMPS
   * (parallel multifrontal, with a fill-reducing ordering), called directly
   * rather than through Trilinos Amesos, for two things Amesos does not
   * offer (doc/discretization.md, 'The reduced space' and 'Iterative model
   * solvers'):
   *
   * - the transposed solve `A^T x = b` from the same factors (MUMPS's
   *   ICNTL(9)), which the adjoint of the reduced-space method needs;
   *   deal.II's TrilinosWrappers::SolverDirect has none, and Amesos needed
   *   the transpose formed and factorized a second time;
   * - many right-hand sides in one solve (`NRHS`), the factors read once for
   *   all of them; Amesos_Mumps solves a multivector one column at a time,
   *   which on the 2D cracked plate's 352 local coarse columns cost 58 % of
   *   the run.
   */
  class DirectSolver
  {
  public:
    /**
     * What the caller knows of the matrix. `symmetric` (indefinite allowed)
     * factorizes `L D L^T` from the lower triangle with 1x1 and 2x2 pivots:
     * half the factor's entries and flops of the general `L U`, and on
     * saddle points, whose zero diagonal blocks the general factorization
     * can pivot on only by delaying, far fewer delayed pivots.
     * `positive_definite` factorizes `L D L^T` from the lower triangle
     * without pivoting (the pivot threshold is not used).
     */
    enum class Symmetry
    {
      general,
      symmetric,
      positive_definite
    };

    /**
     * The fill-reducing ordering (doc/discretization.md, 'The reduced
     * space').
     * `minimum_degree`: approximate minimum degree with detection of
     * quasi-dense rows, for the wide rows of nonlocal stencils and the
     * optimality systems built on them. `nested_dissection`: for the
     * matrices of a mesh, whose unknowns couple only within cells.
     */
    enum class Ordering
    {
      minimum_degree,
      nested_dissection
    };

    /**
     * Factorize @p matrix with MUMPS's relative pivot threshold
     * @p pivot_threshold (a pivot must be at least this fraction of the
     * largest entry of its column), in the order @p ordering. Throws
     * SingularFactorization if MUMPS finds the matrix numerically singular.
     */
    explicit DirectSolver(const TrilinosWrappers::SparseMatrix &matrix,
                          const double   pivot_threshold = 0.5,
                          const Symmetry symmetry        = Symmetry::general,
                          const Ordering ordering = Ordering::minimum_degree);

    ~DirectSolver();

    /** Solve `A x = b`. */
    void
    solve(TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &b) const;

    /** Solve `A^T x = b`. */
    void
    solve_transposed(TrilinosWrappers::MPI::Vector       &x,
                     const TrilinosWrappers::MPI::Vector &b) const;

    /**
     * Solve `A x_j = b_j` (or `A^T x_j = b_j`) for all @p b at once; @p x
     * gets as many vectors, of the layout of @p b.
     */
    void
    solve(std::vector<TrilinosWrappers::MPI::Vector>       &x,
          const std::vector<TrilinosWrappers::MPI::Vector> &b,
          const bool                                        transpose) const;

    /**
     * The same on the columns of @p columns, in place: each right-hand side
     * is replaced by its solution.
     */
    void
    solve(Epetra_MultiVector &columns, const bool transpose) const;

    /** The entries of the factors, over all ranks (MUMPS's INFOG(29)). */
    double
    factor_entries() const;

  private:
    struct Mumps;
    std::unique_ptr<Mumps> mumps;
  };
} // namespace ltn

#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <stdexcept>

class Amesos_BaseSolver;
class Epetra_LinearProblem;
namespace EpetraExt
{
  class RowMatrix_Transpose;
}

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
   * A sparse direct solver for a distributed Trilinos matrix, through Amesos:
   * MUMPS (parallel multifrontal, with a fill-reducing ordering) where
   * Trilinos has it, KLU otherwise. deal.II's TrilinosWrappers::SolverDirect
   * has no transposed solve, which the adjoint of the reduced-space method
   * needs; here the transpose is formed once (EpetraExt) and factorized too.
   */
  class DirectSolver
  {
  public:
    /**
     * Factorize @p matrix, and with @p with_transpose its transpose, with
     * MUMPS's relative pivot threshold @p pivot_threshold (a pivot must be
     * at least this fraction of the largest entry of its column). Throws
     * SingularFactorization if MUMPS finds the matrix numerically singular.
     */
    DirectSolver(const TrilinosWrappers::SparseMatrix &matrix,
                 const bool                            with_transpose,
                 const double                          pivot_threshold = 0.5);

    ~DirectSolver();

    /** Solve `A x = b`. */
    void
    solve(TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &b) const;

    /** Solve `A^T x = b` (only if constructed @p with_transpose). */
    void
    solve_transposed(TrilinosWrappers::MPI::Vector       &x,
                     const TrilinosWrappers::MPI::Vector &b) const;

    /** The Amesos solver in use. */
    static std::string
    package();

  private:
    struct Factorization;

    std::unique_ptr<EpetraExt::RowMatrix_Transpose> transposer;
    std::unique_ptr<Factorization>                  forward;
    std::unique_ptr<Factorization>                  adjoint;
  };
} // namespace ltn

#include <deal.II/base/exceptions.h>

#include <ltn/coupling/direct_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <EpetraExt_Transpose_RowMatrix.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Teuchos_ParameterList.hpp>

#include <iostream>
#include <sstream>

namespace ltn
{
  struct DirectSolver::Factorization
  {
    Factorization(Epetra_CrsMatrix &matrix, const double pivot_threshold)
      : problem(&matrix, nullptr, nullptr)
    {
      // Pivoting on indefinite (saddle point) matrices needs more workspace
      // than MUMPS's estimate: when it runs out (INFOG(1) = -9, seen in 3D
      // on 2 ranks even with 100 % extra), start over with twice as much.
      for (int extra_workspace = 100;; extra_workspace *= 2)
        {
          Amesos factory;
          solver.reset(factory.Create(package(), problem));
          AssertThrow(solver,
                      ExcMessage("Amesos could not create " + package()));
          Teuchos::ParameterList parameters;
          parameters.set("PrintTiming", false);
          parameters.set("PrintStatus", false);
          solver->SetParameters(parameters);
          auto *mumps = dynamic_cast<Amesos_Mumps *>(solver.get());
          if (mumps != nullptr)
            {
              mumps->SetICNTL(14, extra_workspace);
              mumps->SetCNTL(1, pivot_threshold);
              // Approximate minimum degree with detection of quasi-dense
              // rows (the rows of wide nonlocal stencils): faster than
              // MUMPS's automatic choice on the 2D convergence scene (5.8 s
              // against 7.6 s in all).
              mumps->SetICNTL(7, 6);
            }
          // Amesos reports MUMPS's errors on std::cerr: keep them for our
          // message rather than print those of attempts that are retried.
          std::ostringstream    report;
          std::streambuf *const cerr_buffer = std::cerr.rdbuf(report.rdbuf());
          const int             symbolic    = solver->SymbolicFactorization();
          const int             numeric =
            symbolic == 0 ? solver->NumericFactorization() : 0;
          std::cerr.rdbuf(cerr_buffer);
          AssertThrow(symbolic == 0,
                      ExcMessage("the symbolic factorization failed: " +
                                 report.str()));
          if (numeric == 0)
            return;
          if (mumps != nullptr && mumps->GetINFOG()[0] == -10)
            throw SingularFactorization(
              "the matrix is singular: the numeric factorization failed: " +
              report.str());
          AssertThrow(mumps != nullptr && mumps->GetINFOG()[0] == -9 &&
                        extra_workspace < 1600,
                      ExcMessage("the matrix is singular: the numeric "
                                 "factorization failed: " +
                                 report.str()));
        }
    }

    void
    solve(TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &b)
    {
      problem.SetLHS(&x.trilinos_vector());
      problem.SetRHS(const_cast<Epetra_MultiVector *>(&b.trilinos_vector()));
      AssertThrow(solver->Solve() == 0, ExcMessage("the direct solve failed"));
    }

    Epetra_LinearProblem               problem;
    std::unique_ptr<Amesos_BaseSolver> solver;
  };



  DirectSolver::DirectSolver(const TrilinosWrappers::SparseMatrix &matrix,
                             const bool   with_transpose,
                             const double pivot_threshold)
  {
    auto &epetra = const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
    forward      = std::make_unique<Factorization>(epetra, pivot_threshold);
    if (with_transpose)
      {
        transposer = std::make_unique<EpetraExt::RowMatrix_Transpose>();
        adjoint =
          std::make_unique<Factorization>(dynamic_cast<Epetra_CrsMatrix &>(
                                            (*transposer)(epetra)),
                                          pivot_threshold);
      }
  }



  DirectSolver::~DirectSolver() = default;



  void
  DirectSolver::solve(TrilinosWrappers::MPI::Vector       &x,
                      const TrilinosWrappers::MPI::Vector &b) const
  {
    forward->solve(x, b);
  }



  void
  DirectSolver::solve_transposed(TrilinosWrappers::MPI::Vector       &x,
                                 const TrilinosWrappers::MPI::Vector &b) const
  {
    Assert(adjoint, ExcMessage("constructed without the transpose"));
    adjoint->solve(x, b);
  }



  std::string
  DirectSolver::package()
  {
    static const std::string name =
      Amesos().Query("Amesos_Mumps") ? "Amesos_Mumps" : "Amesos_Klu";
    return name;
  }
} // namespace ltn

// The sparse direct solver (MUMPS, doc/discretization.md, 'The reduced
// space' and 'Iterative model solvers') on a nonsymmetric matrix: A x = b
// and A^T x = b from the same
// factors, and many right-hand sides in one solve equal to one at a time.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ltn/base/direct_solver.h>

#include <catch2/catch.hpp>

#include <array>
#include <random>

using namespace ltn;

namespace
{
  /**
   * The square matrix whose row i (this rank's @p rows) holds the entries
   * `entries(i)`, pairs of column and value.
   */
  template <typename Entries>
  TrilinosWrappers::SparseMatrix
  matrix_of(const IndexSet &rows, const Entries &entries)
  {
    DynamicSparsityPattern pattern(rows.size(), rows.size(), rows);
    for (const auto i : rows)
      for (const auto &[j, value] : entries(i))
        pattern.add(i, j);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(rows, rows, pattern, MPI_COMM_WORLD);
    for (const auto i : rows)
      for (const auto &[j, value] : entries(i))
        matrix.set(i, j, value);
    matrix.compress(VectorOperation::insert);
    return matrix;
  }

  /**
   * A nonsymmetric, nonsingular n x n matrix: a convection-diffusion
   * stencil plus one far entry per row, so that A and A^T differ.
   */
  TrilinosWrappers::SparseMatrix
  nonsymmetric_matrix(const IndexSet &rows)
  {
    const unsigned int n = rows.size();
    return matrix_of(rows, [n](const unsigned int i) {
      return std::vector<std::pair<unsigned int, double>>{
        {i, 4.},
        {(i + 1) % n, -1.3},
        {(i + n - 1) % n, -0.7},
        {(i + 7) % n, 0.2 + 0.001 * i}};
    });
  }

  double
  relative_residual(const TrilinosWrappers::SparseMatrix &A,
                    const bool                            transpose,
                    const TrilinosWrappers::MPI::Vector  &x,
                    const TrilinosWrappers::MPI::Vector  &b)
  {
    TrilinosWrappers::MPI::Vector r(b);
    if (transpose)
      A.Tvmult(r, x);
    else
      A.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }
} // namespace



TEST_CASE("the direct solver solves A and A^T for one or many right-hand sides",
          "[solvers][unit]")
{
  // This rank's rows: on two ranks MUMPS gathers the right-hand sides, and
  // decides on sparse columns, over both.
  const unsigned int n = 300;
  const IndexSet     rows =
    Utilities::MPI::create_evenly_distributed_partitioning(MPI_COMM_WORLD, n);
  const TrilinosWrappers::SparseMatrix A = nonsymmetric_matrix(rows);
  const DirectSolver                   solver(
    A,
    0.5,
    DirectSolver::Symmetry::general,
    GENERATE(DirectSolver::Ordering::minimum_degree,
             DirectSolver::Ordering::nested_dissection));

  std::mt19937                               random(5);
  std::uniform_real_distribution<double>     uniform(-1., 1.);
  std::vector<TrilinosWrappers::MPI::Vector> b;
  // Dense right-hand sides, or sparse ones (a few entries each, one of them
  // none), which the solver hands MUMPS as sparse columns.
  const bool sparse = GENERATE(false, true);
  for (unsigned int j = 0; j < (sparse ? 6 : 4); ++j)
    {
      b.emplace_back(rows, MPI_COMM_WORLD);
      for (const auto i : rows)
        if (!sparse)
          b.back()(i) = uniform(random);
        else if (j > 0 && (i == 37 * j || (j == 5 && i % 101 == 3)))
          b.back()(i) = uniform(random);
      b.back().compress(VectorOperation::insert);
    }

  for (const bool transpose : {false, true})
    {
      std::vector<TrilinosWrappers::MPI::Vector> many;
      solver.solve(many, b, transpose);
      REQUIRE(many.size() == b.size());
      for (unsigned int j = 0; j < b.size(); ++j)
        {
          TrilinosWrappers::MPI::Vector one(b[j]);
          if (transpose)
            solver.solve_transposed(one, b[j]);
          else
            solver.solve(one, b[j]);
          INFO("sparse " << sparse << ", transpose " << transpose
                         << ", right-hand side " << j);
          if (b[j].l2_norm() == 0)
            {
              CHECK(many[j].linfty_norm() == 0);
              CHECK(one.linfty_norm() == 0);
              continue;
            }
          CHECK(relative_residual(A, transpose, one, b[j]) < 1e-14);
          CHECK(relative_residual(A, transpose, many[j], b[j]) < 1e-14);
          // A^T x = b is another system: its solution is not A's.
          if (transpose)
            CHECK(relative_residual(A, false, one, b[j]) > 1e-3);
          one -= many[j];
          CHECK(one.linfty_norm() < 1e-14 * many[j].linfty_norm());
        }
    }
}



TEST_CASE("nested dissection fills a mesh's matrix less than minimum degree",
          "[solvers][unit]")
{
  // The matrix of FE_Q(1) on an n^3 grid of nodes (every node coupled to
  // the 26 around it): the couplings of a mesh, which the FEM models'
  // factorizations are ordered for (doc/discretization.md, 'The reduced
  // space').
  const int          n    = 24;
  const unsigned int size = n * n * n;
  const IndexSet     rows =
    Utilities::MPI::create_evenly_distributed_partitioning(MPI_COMM_WORLD,
                                                           size);
  // Diagonally dominant: symmetric positive definite.
  const TrilinosWrappers::SparseMatrix matrix =
    matrix_of(rows, [n](const int i) {
      const int x = i % n, y = (i / n) % n, z = i / (n * n);
      std::vector<std::pair<int, double>> row{{i, 27.}};
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
            if ((dx != 0 || dy != 0 || dz != 0) && x + dx >= 0 && x + dx < n &&
                y + dy >= 0 && y + dy < n && z + dz >= 0 && z + dz < n)
              row.emplace_back(i + dx + n * (dy + n * dz), -1.);
      return row;
    });

  TrilinosWrappers::MPI::Vector b(rows, MPI_COMM_WORLD), x(b);
  b = 1.;
  std::array<double, 2> entries{};
  for (const auto ordering : {DirectSolver::Ordering::minimum_degree,
                              DirectSolver::Ordering::nested_dissection})
    {
      const DirectSolver solver(matrix,
                                0.5,
                                DirectSolver::Symmetry::positive_definite,
                                ordering);
      solver.solve(x, b);
      CHECK(relative_residual(matrix, false, x, b) < 1e-13);
      entries[ordering == DirectSolver::Ordering::nested_dissection] =
        solver.factor_entries();
    }
  INFO("factor entries: minimum degree " << entries[0] << ", nested dissection "
                                         << entries[1]);
  CHECK(entries[1] < 0.8 * entries[0]);
}

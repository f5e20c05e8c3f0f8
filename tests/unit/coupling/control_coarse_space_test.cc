// The balancing preconditioner of the two-level control preconditioner
// (doc/discretization.md, 'A coarse level for the controls'), on a small
// dense SPD operator: it
// inverts the operator exactly on the coarse span, is symmetric and positive
// definite, and cuts the CG iterations of a problem whose slowest modes the
// coarse span holds.

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <ltn/coupling/preconditioners/control_coarse_space.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "dense_controls.h"

using namespace ltn;
using dense_controls::apply;

namespace
{
  using BlockVectorType = TrilinosWrappers::MPI::BlockVector;
  const dense_controls::Blocks blocks{{{24, 8}}};
  const auto                  &block_sizes = blocks.sizes;
  const unsigned int           n           = 32;

  /**
   * `H = I + sum_j lambda_j s_j s_j^T` with the smooth vectors
   * `s_j(i) = cos(j pi i / n)`, j = 0, 1, 2, and a rough part: the smooth
   * modes are far from the rest of the spectrum.
   */
  FullMatrix<double>
  test_operator()
  {
    FullMatrix<double> H(n, n);
    for (unsigned int i = 0; i < n; ++i)
      {
        H(i, i) = 1 + 0.5 * std::sin(1.3 * i) * std::sin(1.3 * i);
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int l = 0; l < n; ++l)
            H(i, l) += 1e3 / (1 + j) * std::cos(j * M_PI * i / n) *
                       std::cos(j * M_PI * l / n);
      }
    return H;
  }

  /** The orthonormal smooth vectors s_0, s_1, s_2. */
  std::vector<BlockVectorType>
  smooth_columns()
  {
    std::vector<BlockVectorType> Z;
    for (unsigned int j = 0; j < 3; ++j)
      {
        BlockVectorType z = blocks.from_function(
          [j](unsigned int i) { return std::cos(j * M_PI * i / n); });
        for (const auto &q : Z)
          z.add(-(z * q), q);
        z /= z.l2_norm();
        Z.push_back(z);
      }
    return Z;
  }
} // namespace



TEST_CASE("the balancing coarse level inverts the operator on its span and "
          "is symmetric positive definite",
          "[solvers][unit]")
{
  const FullMatrix<double> H = test_operator();
  const auto H_op = [&](BlockVectorType &dst, const BlockVectorType &src) {
    apply(H, dst, src);
  };
  // P^{-1}: the inverse of H's diagonal.
  const auto jacobi = [&](BlockVectorType &dst, const BlockVectorType &src) {
    for (unsigned int i = 0; i < n; ++i)
      dst(i) = src(i) / H(i, i);
    dst.compress(VectorOperation::insert);
  };
  const auto               Z = smooth_columns();
  const ControlCoarseSpace coarse(Z, H_op);
  REQUIRE(coarse.size() == 3);

  // On the span: balance(H z) = z.
  BlockVectorType z = blocks.new_vector(), Hz = blocks.new_vector(),
                  Bz = blocks.new_vector();
  z.add(0.3, Z[0]);
  z.add(-1.1, Z[1]);
  z.add(2.0, Z[2]);
  H_op(Hz, z);
  coarse.balance(Bz, Hz, jacobi);
  Bz -= z;
  CHECK(Bz.l2_norm() < 1e-12 * z.l2_norm());

  // Symmetric and positive on two rough vectors.
  const BlockVectorType x = blocks.from_function(
    [](unsigned int i) { return std::sin(2.3 * i + 0.4); });
  const BlockVectorType y =
    blocks.from_function([](unsigned int i) { return std::cos(0.7 * i * i); });
  BlockVectorType Bx = blocks.new_vector(), By = blocks.new_vector();
  coarse.balance(Bx, x, jacobi);
  coarse.balance(By, y, jacobi);
  CHECK(std::abs(x * By - y * Bx) < 1e-12 * x.l2_norm() * By.l2_norm());
  CHECK(x * Bx > 0);
  CHECK(y * By > 0);

  // CG: the smooth modes, 1e3 times the rest, cost Jacobi-CG iterations
  // that the coarse level saves.
  struct Operator
  {
    std::function<void(BlockVectorType &, const BlockVectorType &)> f;
    void
    vmult(BlockVectorType &dst, const BlockVectorType &src) const
    {
      f(dst, src);
    }
  };
  const Operator H_cg{H_op};
  const Operator jacobi_cg{jacobi};
  const Operator two_level{
    [&](BlockVectorType &dst, const BlockVectorType &src) {
      coarse.balance(dst, src, jacobi);
    }};
  std::array<unsigned int, 2> iterations;
  for (const unsigned int variant : {0u, 1u})
    {
      BlockVectorType           solution = blocks.new_vector();
      ReductionControl          control(100, 0, 1e-10);
      SolverCG<BlockVectorType> cg(control);
      cg.solve(H_cg, solution, x, variant == 0 ? jacobi_cg : two_level);
      iterations[variant]      = control.last_step();
      BlockVectorType residual = blocks.new_vector();
      H_op(residual, solution);
      residual -= x;
      CHECK(residual.l2_norm() < 1e-9 * x.l2_norm());
    }
  INFO("CG iterations: Jacobi " << iterations[0] << ", two-level "
                                << iterations[1]);
  CHECK(iterations[1] + 3 <= iterations[0]);
}

// The deflated CG of the reduced-space solver (doc/discretization.md,
// 'A coarse level for the controls'), on small dense normal equations
// `(F^T W F + alpha I) x = b`
// whose slowest modes the coarse columns hold: it solves them, follows CG
// with the balancing preconditioner (which needs an adjoint solve per
// column), and needs one forward solve per column, one per iteration of
// each model whose controls the columns do not span, one adjoint solve per
// iteration and one more.

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <ltn/coupling/preconditioners/control_coarse_space.h>
#include <ltn/coupling/solvers/deflated_cg.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "dense_controls.h"

using namespace ltn;
using dense_controls::apply;
using dense_controls::DenseOperator;

namespace
{
  using BlockVectorType = TrilinosWrappers::MPI::BlockVector;
  using Observation     = NormalEquations::Observation;
  const dense_controls::Blocks blocks{{{200, 40}}};
  const auto                  &block_sizes = blocks.sizes;
  const unsigned int           n           = 240;
  /** Rows of F: a rough diagonal, three smooth rows, seven dense ones. */
  const unsigned int n_observations = n + 3 + 7;

  /**
   * `F`: `F^T W F` is a rough diagonal plus `10/(1+j) s_j s_j^T` for the
   * smooth `s_j(i) = cos(j pi i / n)`, j = 0, 1, 2, plus a dense part.
   */
  FullMatrix<double>
  observation_matrix()
  {
    FullMatrix<double> F(n_observations, n);
    for (unsigned int i = 0; i < n; ++i)
      F(i, i) = std::sqrt(1 + 0.5 * std::sin(1.3 * i) * std::sin(1.3 * i));
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int l = 0; l < n; ++l)
        F(n + j, l) = std::sqrt(10. / (1 + j)) * std::cos(j * M_PI * l / n);
    for (unsigned int r = n + 3; r < n_observations; ++r)
      for (unsigned int l = 0; l < n; ++l)
        F(r, l) = 0.3 * std::sin(0.37 * r * l + 0.2);
    return F;
  }

  std::vector<double>
  observation_weights()
  {
    std::vector<double> w(n_observations);
    for (unsigned int q = 0; q < n_observations; ++q)
      w[q] = 1 + 0.25 * std::cos(q);
    return w;
  }

  /**
   * The coarse columns, each in one block as the reduced space's are: the
   * smooth vectors s_0, s_1, s_2 on block 0, orthonormalized, and the unit
   * vectors of block 1. Their span holds the s_j.
   */
  std::vector<BlockVectorType>
  coarse_columns()
  {
    std::vector<BlockVectorType> Z;
    for (unsigned int j = 0; j < 3; ++j)
      {
        BlockVectorType z = blocks.from_function([j](unsigned int i) {
          return i < block_sizes[0] ? std::cos(j * M_PI * i / n) : 0.;
        });
        for (const auto &q : Z)
          z.add(-(z * q), q);
        z /= z.l2_norm();
        Z.push_back(z);
      }
    for (unsigned int i = 0; i < block_sizes[1]; ++i)
      {
        BlockVectorType z = blocks.new_vector();
        z.block(1)(i)     = 1.;
        z.compress(VectorOperation::insert);
        Z.push_back(z);
      }
    return Z;
  }

  /** The same columns, each kept in its own block, for the deflation. */
  std::vector<DeflationSpace::Column>
  deflation_columns()
  {
    std::vector<DeflationSpace::Column> columns;
    for (const auto &z : coarse_columns())
      {
        const unsigned int k = z.block(0).l2_norm() > 0 ? 0 : 1;
        columns.push_back({k, z.block(k)});
      }
    return columns;
  }

  /** Block @p k of @p x, a vector of that block's size. */
  TrilinosWrappers::MPI::Vector
  zero_state(const unsigned int k)
  {
    return blocks.new_vector().block(k);
  }

  /**
   * The normal equations of F and W, with the states the controls
   * themselves (`V = I`, `B = F`), counting the forward and adjoint
   * "solves".
   */
  struct CountedEquations
  {
    using States = NormalEquations::States;

    CountedEquations(const double alpha)
      : F(observation_matrix())
      , weights(observation_weights())
      , equations{[this](const unsigned int                   k,
                         const TrilinosWrappers::MPI::Vector &x,
                         const TrilinosWrappers::MPI::Vector *) {
                    ++n_forward[k];
                    return x;
                  },
                  [this](const States &u) {
                    // An empty state is a zero one.
                    Observation y(n_observations, 0.);
                    for (unsigned int q = 0; q < n_observations; ++q)
                      for (unsigned int l = 0; l < n; ++l)
                        {
                          const unsigned int k = l < block_sizes[0] ? 0 : 1;
                          if (u[k].size() > 0)
                            y[q] += F(q, l) * u[k](l - k * block_sizes[0]);
                        }
                    return y;
                  },
                  [this](const unsigned int k, const Observation &d) {
                    auto g = zero_state(k);
                    for (unsigned int i = 0; i < block_sizes[k]; ++i)
                      {
                        const unsigned int l   = i + k * block_sizes[0];
                        double             sum = 0;
                        for (unsigned int q = 0; q < n_observations; ++q)
                          sum += F(q, l) * weights[q] * d[q];
                        g(i) = sum;
                      }
                    g.compress(VectorOperation::insert);
                    return g;
                  },
                  [this](const States &g) {
                    ++n_adjoint;
                    BlockVectorType x = blocks.new_vector();
                    x.block(0)        = g[0];
                    x.block(1)        = g[1];
                    return x;
                  },
                  zero_state,
                  [](const unsigned int k) {
                    // F is dense: every unknown is observed.
                    auto observed = zero_state(k);
                    observed      = 1.;
                    return observed;
                  },
                  alpha}
    {}

    /**
     * The observation whose right-hand side `b = -F^T W d` the deflated CG
     * solves for: @p f at each observation.
     */
    static Observation
    data(const std::function<double(unsigned int)> &f)
    {
      Observation d(n_observations);
      for (unsigned int q = 0; q < n_observations; ++q)
        d[q] = f(q);
      return d;
    }

    /** `b = -F^T W d`, counting no adjoint solve. */
    BlockVectorType
    rhs(const Observation &d) const
    {
      BlockVectorType b = blocks.new_vector();
      for (const unsigned int k : {0u, 1u})
        b.block(k) = equations.observe_transpose(k, d);
      b *= -1.;
      return b;
    }

    /** `F^T W F + alpha I`, dense. */
    FullMatrix<double>
    matrix() const
    {
      FullMatrix<double> A(n, n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int l = 0; l < n; ++l)
          {
            for (unsigned int q = 0; q < n_observations; ++q)
              A(i, l) += F(q, i) * weights[q] * F(q, l);
            if (i == l)
              A(i, l) += equations.alpha;
          }
      return A;
    }

    const FullMatrix<double>    F;
    const std::vector<double>   weights;
    std::array<unsigned int, 2> n_forward = {{0, 0}};
    unsigned int                n_adjoint = 0;
    const NormalEquations       equations;
  };

  using Preconditioner =
    std::function<void(BlockVectorType &, const BlockVectorType &)>;

  /** Jacobi on the dense @p A (kept alive by the caller). */
  Preconditioner
  jacobi_of(const FullMatrix<double> &A)
  {
    return [&A](BlockVectorType &dst, const BlockVectorType &src) {
      for (unsigned int i = 0; i < n; ++i)
        dst(i) = src(i) / A(i, i);
      dst.compress(VectorOperation::insert);
    };
  }

  void
  no_preconditioner(BlockVectorType &dst, const BlockVectorType &src)
  {
    dst = src;
  }

  struct Balanced
  {
    void
    vmult(BlockVectorType &dst, const BlockVectorType &src) const
    {
      coarse.balance(dst, src, smooth);
    }
    const ControlCoarseSpace          &coarse;
    const ControlCoarseSpace::Operator smooth;
  };
} // namespace



TEST_CASE("the deflated CG solves the normal equations with the balancing "
          "preconditioner's iterations and no products with F^T per coarse "
          "column",
          "[solvers][unit]")
{
  for (const double alpha : {0., 0.3})
    {
      INFO("alpha = " << alpha);
      CountedEquations         counted(alpha);
      const FullMatrix<double> A      = counted.matrix();
      const Preconditioner     jacobi = jacobi_of(A);
      const Observation        d      = CountedEquations::data(
        [](unsigned int q) { return 1 + std::sin(0.9 * q) + 0.01 * q; });
      const BlockVectorType b = counted.rhs(d);

      // The exact solution, by LAPACK.
      LAPACKFullMatrix<double> lu(n, n);
      lu = A;
      lu.compute_lu_factorization();
      Vector<double> exact(n);
      for (unsigned int i = 0; i < n; ++i)
        exact(i) = b(i);
      lu.solve(exact);

      const DeflationSpace coarse(deflation_columns(), counted.equations);
      const unsigned int   m = 3 + block_sizes[1];
      REQUIRE(coarse.size() == m);
      // One forward solve of its own model per column, no adjoint solve.
      CHECK(counted.n_forward[0] == 3);
      CHECK(counted.n_forward[1] == block_sizes[1]);
      CHECK(counted.n_adjoint == 0);

      BlockVectorType x         = blocks.new_vector();
      unsigned int    callbacks = 0;
      SolverControl   control(100, 1e-12 * b.l2_norm());
      // The states V x (here x itself) are added to what the states held.
      NormalEquations::States states;
      for (const unsigned int k : {0u, 1u})
        {
          states[k] = zero_state(k);
          states[k].add(1., b.block(k));
        }
      solve_deflated_cg(
        counted.equations,
        coarse,
        jacobi,
        d,
        x,
        control,
        [&](double) { ++callbacks; },
        &states);
      for (const unsigned int k : {0u, 1u})
        {
          states[k] -= b.block(k);
          states[k] -= x.block(k);
          CHECK(states[k].l2_norm() < 1e-12 * x.l2_norm());
        }
      double error = 0, norm = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          error = std::max(error, std::abs(x(i) - exact(i)));
          norm  = std::max(norm, std::abs(exact(i)));
        }
      CHECK(error < 1e-10 * norm);
      const unsigned int iterations = control.last_step();

      CHECK(counted.n_adjoint == iterations + 1);
      CHECK(counted.n_forward[0] == 3 + iterations);
      // Block 1's unit columns span it: the residual is zero there, and the
      // directions' parts there are coarse corrections alone.
      CHECK(counted.n_forward[1] == block_sizes[1]);
      CHECK(callbacks == iterations);

      // Panels and blocks of gradients of a few columns each (the scenes'
      // 64 MB hold all of this test's): E formed block by block from its
      // lower triangle, the panels entered at a column inside them.
      {
        const DeflationSpace small_blocks(deflation_columns(),
                                          counted.equations,
                                          2048);
        BlockVectorType      x_small = blocks.new_vector();
        SolverControl        small_control(100, 1e-12 * b.l2_norm());
        solve_deflated_cg(counted.equations,
                          small_blocks,
                          jacobi,
                          d,
                          x_small,
                          small_control,
                          [](double) {});
        CHECK(small_control.last_step() == iterations);
        x_small -= x;
        CHECK(x_small.l2_norm() < 1e-12 * x.l2_norm());
      }

      // CG with the balancing preconditioner, from the same start Z E^{-1}
      // Z^T b (Z^T b = -(F Z)^T W d): A Z costs a product with F^T W per
      // column; the iterates are the same in exact arithmetic.
      const ControlCoarseSpace balancing(coarse_columns(),
                                         [&](BlockVectorType       &dst,
                                             const BlockVectorType &src) {
                                           apply(A, dst, src);
                                         });
      BlockVectorType          y = blocks.new_vector();
      Observation              observed_start(n_observations, 0.);
      Vector<double>           start = coarse.solve_product(y, d);
      start *= -1.;
      coarse.add(start, y, observed_start);
      SolverControl             balanced_control(100, 1e-12 * b.l2_norm());
      SolverCG<BlockVectorType> cg(balanced_control);
      cg.solve(DenseOperator{A}, y, b, Balanced{balancing, jacobi});
      INFO("deflated " << iterations << ", balanced "
                       << balanced_control.last_step());
      CHECK(iterations <= balanced_control.last_step() + 1);
      // The same iterates: after five steps both residuals agree (later,
      // round-off parts them; the balanced ones lose more).
      {
        SolverControl   five(5, 0.), balanced_five(5, 0.);
        BlockVectorType x5 = blocks.new_vector(), y5 = blocks.new_vector();
        CHECK_THROWS_AS(
          solve_deflated_cg(
            counted.equations, coarse, jacobi, d, x5, five, [](double) {}),
          SolverControl::NoConvergence);
        coarse.add(start, y5, observed_start);
        SolverCG<BlockVectorType> cg5(balanced_five);
        CHECK_THROWS_AS(
          cg5.solve(DenseOperator{A}, y5, b, Balanced{balancing, jacobi}),
          SolverControl::NoConvergence);
        CHECK(std::abs(five.last_value() - balanced_five.last_value()) <
              1e-8 * five.last_value());
      }
      y -= x;
      CHECK(y.l2_norm() < 1e-10 * x.l2_norm());

      // And the coarse columns matter: Jacobi alone needs more.
      SolverControl             plain_control(200, 1e-12 * b.l2_norm());
      SolverCG<BlockVectorType> plain(plain_control);
      struct Jacobi
      {
        void
        vmult(BlockVectorType &dst, const BlockVectorType &src) const
        {
          smooth(dst, src);
        }
        const ControlCoarseSpace::Operator smooth;
      };
      BlockVectorType w = blocks.new_vector();
      plain.solve(DenseOperator{A}, w, b, Jacobi{jacobi});
      std::cout << "deflated CG test, alpha = " << alpha << ": " << iterations
                << " iterations deflated, " << balanced_control.last_step()
                << " balanced, " << plain_control.last_step() << " Jacobi alone"
                << std::endl;
      CHECK(plain_control.last_step() > iterations + 3);
    }
}



TEST_CASE("the deflated CG's Ritz values reach the ends of the spectrum of "
          "the operator its coarse space and preconditioner leave",
          "[solvers][unit]")
{
  CountedEquations         counted(0.3);
  const FullMatrix<double> A      = counted.matrix();
  const Preconditioner     jacobi = jacobi_of(A);
  // The coarse columns dense: Zd, n x m.
  const std::vector<BlockVectorType> Z = coarse_columns();
  const unsigned int                 m = Z.size();
  FullMatrix<double>                 Zd(n, m);
  for (unsigned int j = 0; j < m; ++j)
    for (unsigned int i = 0; i < n; ++i)
      Zd(i, j) = Z[j](i);

  // Deflated PCG is CG on J^{-1/2} (A - A Z E^{-1} Z^T A) J^{-1/2}, E = Z^T A
  // Z, on the complement of Z's m directions (which it maps to zero).
  FullMatrix<double> AZ(n, m), E(m, m), deflated(n, n);
  A.mmult(AZ, Zd);
  Zd.Tmmult(E, AZ);
  FullMatrix<double> E_inverse(m, m);
  E_inverse.invert(E);
  FullMatrix<double> AZ_E_inverse(n, m);
  AZ.mmult(AZ_E_inverse, E_inverse);
  AZ_E_inverse.mTmult(deflated, AZ);
  LAPACKFullMatrix<double> scaled(n, n);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int l = 0; l < n; ++l)
      scaled(i, l) = (A(i, l) - deflated(i, l)) / std::sqrt(A(i, i) * A(l, l));
  scaled.compute_eigenvalues();
  std::vector<double> spectrum(n);
  for (unsigned int i = 0; i < n; ++i)
    spectrum[i] = scaled.eigenvalue(i).real();
  std::sort(spectrum.begin(), spectrum.end());
  for (unsigned int i = 0; i < m; ++i)
    REQUIRE(std::abs(spectrum[i]) < 1e-10 * spectrum.back());
  const double lowest = spectrum[m], highest = spectrum.back();

  const DeflationSpace coarse(deflation_columns(), counted.equations);
  const Observation    d = CountedEquations::data(
    [](unsigned int q) { return 1 + std::sin(0.9 * q) + 0.01 * q; });
  BlockVectorType x = blocks.new_vector();
  SolverControl   control(100, 1e-12 * counted.rhs(d).l2_norm());
  RitzValues      ritz_values;
  solve_deflated_cg(
    counted.equations,
    coarse,
    jacobi,
    d,
    x,
    control,
    [](double) {},
    nullptr,
    &ritz_values);
  const std::vector<double> ritz = ritz_values.values();
  REQUIRE(ritz.size() == control.last_step());
  std::cout << "deflated CG test: " << ritz.size() << " Ritz values in ["
            << ritz.front() << ", " << ritz.back() << "], the spectrum ["
            << lowest << ", " << highest << "]" << std::endl;
  // Inside the spectrum's ends, and near them once CG has converged (the
  // largest to 1e-9 here, the smallest, whose eigenvector the right-hand
  // side holds less of, to 3e-4).
  CHECK(ritz.front() > lowest * (1 - 1e-8));
  CHECK(ritz.back() < highest * (1 + 1e-8));
  CHECK(ritz.front() < lowest * 1.01);
  CHECK(ritz.back() > highest * 0.99);

  // Without coarse columns the iterates are CG's (for the first steps,
  // before round-off parts them): so are the Ritz values, which deal.II's
  // CG gives from the steps whose next direction it has formed.
  const DeflationSpace none({}, counted.equations);
  BlockVectorType      early = blocks.new_vector();
  SolverControl        four(4, 0.);
  RitzValues           early_ritz;
  CHECK_THROWS_AS(solve_deflated_cg(
                    counted.equations,
                    none,
                    no_preconditioner,
                    d,
                    early,
                    four,
                    [](double) {},
                    nullptr,
                    &early_ritz),
                  SolverControl::NoConvergence);
  std::vector<double>       cg_ritz;
  SolverControl             five(5, 0.);
  SolverCG<BlockVectorType> cg(five);
  cg.connect_eigenvalues_slot(
    [&](const std::vector<double> &values) { cg_ritz = values; });
  BlockVectorType y = blocks.new_vector();
  CHECK_THROWS_AS(
    cg.solve(DenseOperator{A}, y, counted.rhs(d), PreconditionIdentity()),
    SolverControl::NoConvergence);
  const std::vector<double> mine = early_ritz.values();
  REQUIRE(mine.size() == 4);
  REQUIRE(cg_ritz.size() == 4);
  for (unsigned int i = 0; i < 4; ++i)
    CHECK(std::abs(mine[i] - cg_ritz[i]) < 1e-10 * cg_ritz.back());
}



TEST_CASE("the deflated CG without coarse columns is CG", "[solvers][unit]")
{
  CountedEquations         counted(0.);
  const FullMatrix<double> A = counted.matrix();
  const DeflationSpace     none({}, counted.equations);
  const Observation        d = CountedEquations::data(
    [](unsigned int q) { return std::cos(0.4 * q * q); });
  const BlockVectorType b = counted.rhs(d);
  BlockVectorType       x = blocks.new_vector();
  SolverControl         control(200, 1e-10 * b.l2_norm());
  solve_deflated_cg(
    counted.equations, none, no_preconditioner, d, x, control, [](double) {});
  // The start's residual b is one product with F^T W.
  CHECK(counted.n_adjoint == control.last_step() + 1);

  BlockVectorType           y = blocks.new_vector();
  SolverControl             cg_control(200, 1e-10 * b.l2_norm());
  SolverCG<BlockVectorType> cg(cg_control);
  cg.solve(DenseOperator{A}, y, b, PreconditionIdentity());
  y -= x;
  CHECK(y.l2_norm() < 1e-8 * x.l2_norm());

  // The same iterates but for round-off: the direction's observation comes
  // from a recurrence, not from a product. Compared at the first steps, not
  // by the number of steps to the tolerance: this system (alpha = 0) is so
  // ill-conditioned that the two iterates' round-off differences grow by
  // about 1000x per step from the fifth step on (1e-15 at step 4, 1e-7 at
  // step 7, up to 4e-3 before both converge to the same solution), which
  // moved the step count by two on one machine (38 against 40).
  for (unsigned int steps = 1; steps <= 4; ++steps)
    {
      BlockVectorType early = blocks.new_vector();
      SolverControl   stop(steps, 0.);
      CHECK_THROWS_AS(solve_deflated_cg(counted.equations,
                                        none,
                                        no_preconditioner,
                                        d,
                                        early,
                                        stop,
                                        [](double) {}),
                      SolverControl::NoConvergence);
      BlockVectorType           cg_early = blocks.new_vector();
      SolverControl             cg_stop(steps, 0.);
      SolverCG<BlockVectorType> cg_steps(cg_stop);
      CHECK_THROWS_AS(
        cg_steps.solve(DenseOperator{A}, cg_early, b, PreconditionIdentity()),
        SolverControl::NoConvergence);
      cg_early -= early;
      CHECK(cg_early.l2_norm() < 1e-12 * early.l2_norm());
    }

  // Too few iterations allowed: deal.II's exception, as its solvers throw.
  SolverControl too_few(3, 1e-10 * b.l2_norm());
  CHECK_THROWS_AS(
    solve_deflated_cg(
      counted.equations, none, no_preconditioner, d, x, too_few, [](double) {}),
    SolverControl::NoConvergence);
}



TEST_CASE("the deflated CG is the same with block 1's gradients from "
          "observe_alone, many columns at a time, in blocks of any size",
          "[solvers][unit]")
{
  CountedEquations         counted(0.1);
  const FullMatrix<double> A = counted.matrix();
  const Observation        d = CountedEquations::data(
    [](unsigned int q) { return std::sin(0.3 * q) + 0.1 * q / n; });
  const BlockVectorType b      = counted.rhs(d);
  const auto            jacobi = jacobi_of(A);

  // F_1^T W F_1 u for block 1's states alone (alpha is not in it).
  NormalEquations    alone = counted.equations;
  FullMatrix<double> gram(block_sizes[1], block_sizes[1]);
  for (unsigned int i = 0; i < block_sizes[1]; ++i)
    for (unsigned int j = 0; j < block_sizes[1]; ++j)
      gram(i, j) =
        A(block_sizes[0] + i, block_sizes[0] + j) - (i == j ? 0.1 : 0.);
  std::vector<unsigned int> calls;
  alone.observe_alone[1] =
    [&](const unsigned int n_columns, const double *u, double *g) {
      calls.push_back(n_columns);
      for (unsigned int c = 0; c < n_columns; ++c)
        for (unsigned int i = 0; i < block_sizes[1]; ++i)
          {
            double sum = 0;
            for (unsigned int j = 0; j < block_sizes[1]; ++j)
              sum += gram(i, j) * u[c * block_sizes[1] + j];
            g[c * block_sizes[1] + i] = sum;
          }
    };

  const auto solve = [&](const NormalEquations &equations,
                         const std::size_t      block_bytes) {
    const DeflationSpace coarse(deflation_columns(), equations, block_bytes);
    BlockVectorType      x = blocks.new_vector();
    SolverControl        control(100, 1e-12 * b.l2_norm());
    solve_deflated_cg(equations, coarse, jacobi, d, x, control, [](double) {});
    return x;
  };
  const BlockVectorType x = solve(counted.equations, std::size_t(64) << 20);
  // One block; in blocks of 2 KB (panels of 2 states of block 0), whose
  // runs of block 1's columns stop at the panels' ends.
  for (const std::size_t block_bytes :
       {std::size_t(64) << 20, std::size_t(2048)})
    {
      calls.clear();
      BlockVectorType y = solve(alone, block_bytes);
      y -= x;
      CHECK(y.l2_norm() < 1e-12 * x.l2_norm());
      unsigned int columns = 0;
      for (const unsigned int c : calls)
        columns += c;
      CHECK(columns == block_sizes[1]);
      CHECK(calls.size() < block_sizes[1]);
    }
}



TEST_CASE("the coarse matrix's blocks of columns, and so its collective "
          "gradient products, are the same on every rank",
          "[solvers][unit]")
{
  using VectorType           = TrilinosWrappers::MPI::Vector;
  const MPI_Comm     comm    = MPI_COMM_WORLD;
  const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
  const std::array<unsigned int, 2> sizes = {{16, 24}};
  // Rank 0 owns three quarters of each model's unknowns, the other ranks
  // share the rest: their blocks by their own shares would differ.
  const auto owned = [&](const unsigned int k) {
    const unsigned int first_of_others = n_ranks > 1 ? 3 * sizes[k] / 4 : 0;
    const unsigned int others          = std::max(1u, n_ranks - 1);
    const auto         start           = [&](const unsigned int r) {
      return r == 0 ? 0u :
                                        first_of_others +
                        (sizes[k] - first_of_others) * (r - 1) / others;
    };
    IndexSet set(sizes[k]);
    set.add_range(start(rank), rank + 1 < n_ranks ? start(rank + 1) : sizes[k]);
    return set;
  };
  const auto new_state = [&](const unsigned int k) {
    return VectorType(owned(k), comm);
  };
  const auto weight = [](const unsigned int i) { return 1. + 0.1 * i; };
  // V = I and W diagonal: this rank's observations are its entries of
  // both models' states, one after the other.
  const std::size_t size_0 = owned(0).n_elements();
  const std::size_t size_1 = owned(1).n_elements();

  NormalEquations equations{
    [](const unsigned int, const VectorType &x, const VectorType *) {
      return x;
    },
    [&](const NormalEquations::States &u) {
      NormalEquations::Observation y(size_0 + size_1, 0.);
      for (const unsigned int k : {0u, 1u})
        if (u[k].size() > 0)
          std::copy(u[k].begin(),
                    u[k].end(),
                    y.begin() + (k == 0 ? 0 : size_0));
      return y;
    },
    [&](const unsigned int k, const NormalEquations::Observation &y) {
      VectorType g = new_state(k);
      for (std::size_t i = 0; i < g.locally_owned_size(); ++i)
        g.begin()[i] = weight(i) * y[(k == 0 ? 0 : size_0) + i];
      return g;
    },
    {},
    new_state,
    [&](const unsigned int k) {
      VectorType observed = new_state(k);
      observed            = 1.;
      return observed;
    },
    0.};
  std::vector<int> calls;
  equations.observe_alone[1] =
    [&](const unsigned int n_columns, const double *u, double *g) {
      calls.push_back(n_columns);
      for (unsigned int c = 0; c < n_columns; ++c)
        for (std::size_t i = 0; i < size_1; ++i)
          g[c * size_1 + i] = weight(i) * u[c * size_1 + i];
    };

  // Two columns of model 0 (a constant and a ramp), every unit vector of
  // model 1.
  std::vector<DeflationSpace::Column> columns;
  for (const unsigned int j : {0u, 1u})
    {
      VectorType z = new_state(0);
      for (const auto i : owned(0))
        z(i) = j == 0 ? 1. : double(i);
      z.compress(VectorOperation::insert);
      columns.push_back({0, z});
    }
  for (unsigned int i = 0; i < sizes[1]; ++i)
    {
      VectorType z = new_state(1);
      if (z.in_local_range(i))
        z(i) = 1.;
      z.compress(VectorOperation::insert);
      columns.push_back({1, z});
    }
  // Blocks of 320 bytes: panels of two of the largest share's states.
  const DeflationSpace coarse(std::move(columns), equations, 320);

  unsigned int total = 0;
  for (const int c : calls)
    total += c;
  CHECK(total == sizes[1]);
  const std::vector<std::vector<int>> all_calls =
    Utilities::MPI::all_gather(comm, calls);
  for (const auto &other : all_calls)
    CHECK(other == calls);
}

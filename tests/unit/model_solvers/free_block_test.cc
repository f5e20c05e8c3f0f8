// The particle models' free block (the Schur complement of the LPS
// dilatation at the free displacements; doc/discretization.md,
// 'Iterative model solvers')
// is symmetric and positive, for nonlocal diffusion and LPS in 2D and 3D,
// with cracks (an inner one and one across the lattice) and a collar partly
// outside the body, assembled and matrix-free; its products from and at the
// controls and fixed data equal the whole ones; and CG on it solves the
// forward and the transposed equations as the direct solver does, on any
// number of ranks. Where no dilatation is eliminated (nonlocal diffusion),
// the direct solver factorizes that block alone (ModelDirectSolver), and
// solves as the LU of the whole matrix does.

#include <ltn/model_solvers/model_direct_solver.h>
#include <ltn/model_solvers/model_solver.h>
#include <ltn/model_solvers/schur_complement.h>

#include <catch2/catch.hpp>

#include "lu_difference.h"
#include "particle_layout.h"

using namespace ltn;

namespace
{
  /**
   * Over random pairs x, y in the free block: max |x.Sy - y.Sx| / (|x| |Sy|),
   * and CHECKs x.Sx > 0.
   */
  double
  asymmetry(const DiscreteModel &model)
  {
    REQUIRE(model.symmetric_free_block);
    const SchurComplement block(model, false);
    std::mt19937          random(3);
    double                worst = 0;
    auto                  Sx = model.new_vector(), Sy = model.new_vector();
    for (unsigned int trial = 0; trial < 3; ++trial)
      {
        auto x = random_vector(model, random);
        auto y = random_vector(model, random);
        block.restrict_to_free_block(x);
        block.restrict_to_free_block(y);
        block.vmult_free_block(Sx, x);
        block.vmult_free_block(Sy, y);
        CHECK(x * Sx > 0);
        worst =
          std::max(worst,
                   std::abs(x * Sy - y * Sx) / (x.l2_norm() * Sy.l2_norm()));
      }
    return worst;
  }

  /**
   * The products with `S` of a vector outside the free block and `t`, and
   * at those rows, that compute only the rows they need
   * (SchurComplement::vmult_from_outside(), vmult_at_outside()), against
   * the whole product: the largest relative difference, at every row and at
   * those rows respectively, forward and transposed.
   */
  double
  outside_product_difference(const DiscreteModel &model)
  {
    std::mt19937 random(11);
    double       worst      = 0;
    const auto   is_outside = [&](const types::global_dof_index i) {
      return model.role(i) != DofRole::free && !model.eliminated.is_element(i);
    };
    // The adjoint one takes the forward one's rows, as ModelSolver's does.
    const SchurComplement forward(model, false);
    for (const bool transpose : {false, true})
      {
        const SchurComplement S(model, transpose, &forward);
        const auto            x       = random_vector(model, random);
        auto                  outside = x;
        for (const auto i : model.owned)
          if (!is_outside(i))
            outside(i) = 0.;
        outside.compress(VectorOperation::insert);
        auto whole = model.new_vector(), part = model.new_vector();
        // A marker first: a row the product missed would keep it.
        part = 1e300;
        S.vmult(whole, outside);
        S.vmult_from_outside(part, outside);
        worst = std::max(worst, relative_difference(whole, part));

        part = 1e300;
        S.vmult(whole, x);
        S.vmult_at_outside(part, x);
        for (const auto i : model.owned)
          if (!is_outside(i))
            part(i) = whole(i);
        part.compress(VectorOperation::insert);
        worst = std::max(worst, relative_difference(whole, part));
      }
    return worst;
  }

  /**
   * CG on the matrix-free model against the direct solver on the assembled
   * one: forward with data and random controls, adjoint of a random
   * gradient, and M^-T of a random right-hand side (dilatation rows
   * included).
   */
  void
  check_solves(const DiscreteModel &assembled, const DiscreteModel &matrix_free)
  {
    ModelSolverSettings settings;
    settings.kind               = ModelSolverKind::preconditioned_cg;
    settings.relative_tolerance = 1e-12;
    const ModelSolver cg(matrix_free, true, settings);
    const ModelSolver direct(assembled, true);

    std::mt19937                           random(5);
    std::uniform_real_distribution<double> value(-1, 1);
    auto                                   theta = cg.new_control_vector();
    for (const auto i : theta.locally_owned_elements())
      theta(i) = value(random);
    theta.compress(VectorOperation::insert);
    const auto z = random_vector(assembled, random);

    const double forward =
      relative_difference(direct.forward(theta, true), cg.forward(theta, true));
    const double adjoint =
      relative_difference(direct.adjoint(z), cg.adjoint(z));
    const double transposed =
      relative_difference(direct.solve(true, z), cg.solve(true, z));
    INFO("differences to the direct solver: forward "
         << forward << ", adjoint " << adjoint << ", M^-T " << transposed
         << "; " << cg.statistics().iterations << " CG iterations");
    CHECK(forward < 1e-8);
    CHECK(adjoint < 1e-8);
    CHECK(transposed < 1e-8);
  }

  /**
   * The checks of this file on a model assembled and matrix-free
   * (@p name for the messages).
   */
  template <typename Particles>
  void
  check(const std::string &name,
        const Particles   &assembled,
        const Particles   &matrix_free)
  {
    for (const DiscreteModel *model :
         {&assembled.get_model(), &matrix_free.get_model()})
      {
        const double difference = asymmetry(*model);
        INFO(name << ": asymmetry " << difference);
        CHECK(difference < 1e-13);
        const double outside = outside_product_difference(*model);
        INFO(name << ": products outside the free block " << outside);
        CHECK(outside < 1e-13);
      }
    check_solves(assembled.get_model(), matrix_free.get_model());
  }
} // namespace



TEST_CASE("the direct solver factorizes a symmetric free block alone and "
          "solves as the LU of the whole matrix",
          "[solvers][unit]")
{
  const auto diffusion_2d = layout_diffusion<2>(1. / 32, 3, false);
  const auto diffusion_3d = layout_diffusion<3>(1. / 16, 3, false);
  for (const DiscreteModel *model :
       {&diffusion_2d->get_model(), &diffusion_3d->get_model()})
    {
      REQUIRE(ModelDirectSolver(*model).factorizes_free_block());
      const double difference = difference_to_lu(*model);
      INFO("largest relative difference " << difference);
      CHECK(difference < 1e-11);
    }
  // LPS eliminates its dilatation: the whole matrix is factorized.
  const auto lps = cracked_lps<2>(1. / 32, 2, false);
  CHECK_FALSE(ModelDirectSolver(lps->get_model()).factorizes_free_block());
}



TEST_CASE("particle models' free block is symmetric positive definite and CG "
          "solves with it",
          "[solvers][unit]")
{
  check("2D diffusion",
        *layout_diffusion<2>(1. / 32, 3, false),
        *layout_diffusion<2>(1. / 32, 3, true));
  check("3D diffusion",
        *layout_diffusion<3>(1. / 16, 3, false),
        *layout_diffusion<3>(1. / 16, 3, true));
  check("2D LPS",
        *cracked_lps<2>(1. / 32, 2, false),
        *cracked_lps<2>(1. / 32, 2, true));
  check("3D LPS",
        *cracked_lps<3>(1. / 16, 2, false),
        *cracked_lps<3>(1. / 16, 2, true));
}

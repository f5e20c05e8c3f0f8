// CouplingSystem::observation_gram assembles B_k^T W B_k, the mismatch's
// gradient for a field of one model alone. Checked on random vectors
// against the pass over the overlap points it replaces,
// mismatch_gradient(k, mismatch(u_k alone)), for nonlocal diffusion coupled
// to Poisson in 2D and cracked LPS coupled to Navier-Cauchy elasticity
// (FE_Q(2)) in 3D, on one rank and two (the overlap points split between
// them).

#include <deal.II/base/function.h>

#include <ltn/coupling/system/coupling_system.h>
#include <ltn/local/elasticity_problem.h>

#include <catch2/catch.hpp>

#include "coupled_layout.h"

using namespace ltn;

namespace
{
  template <int dim>
  void
  check_observation_gram(const CouplingSystem<dim> &system)
  {
    std::mt19937 random(11);
    for (const unsigned int k : {0u, 1u})
      {
        INFO("model " << k);
        const DiscreteModel                &model = *system.models[k];
        const TrilinosWrappers::MPI::Vector u = random_vector(model, random);
        std::array<TrilinosWrappers::MPI::Vector, 2> alone;
        alone[k] = u;
        const auto expected =
          system.mismatch_gradient(k, system.mismatch(alone[0], alone[1]));

        const TrilinosWrappers::SparseMatrix gram = system.observation_gram(k);
        TrilinosWrappers::MPI::Vector        product = model.new_vector();
        gram.vmult(product, u);
        TrilinosWrappers::MPI::Vector difference = product;
        difference -= expected;
        REQUIRE(expected.l2_norm() > 0);
        CHECK(difference.l2_norm() <= 1e-13 * expected.l2_norm());
      }
  }
} // namespace



TEST_CASE("the observation's Gram matrix is the mismatch gradient of one "
          "model's field, diffusion and Poisson in 2D",
          "[coupling]")
{
  const DiffusionPoissonLayout<2> layout(0.125, 0.125 / 4, 2);
  check_observation_gram(CouplingSystem<2>(layout.particles->get_model(),
                                           layout.local.get_model(),
                                           layout.overlap,
                                           0));
}



TEST_CASE("the observation's Gram matrix is the mismatch gradient of one "
          "model's field, LPS and elasticity in 3D",
          "[coupling][elasticity]")
{
  constexpr int       dim      = 3;
  const Geometry<dim> geometry = particle_layout<dim>();
  const double        h = 0.25, spacing = h / 2, m = 2;

  LocalParameters<dim> parameters;
  parameters.degree          = 2;
  parameters.dirichlet_faces = {0};
  ElasticityProblem<dim> local(
    geometry, parameters, 1.3, 0.7, h, MPI_COMM_WORLD);
  const Functions::ConstantFunction<dim> zero(0., dim), pressure(0.);
  local.assemble(zero, zero, zero, pressure);

  const auto particles = cracked_lps<dim>(spacing, m, true);
  const auto overlap   = create_overlap_quadrature(geometry,
                                                 m * spacing,
                                                 *particles,
                                                 local.get_dof_handler());
  check_observation_gram(
    CouplingSystem<dim>(particles->get_model(), local.get_model(), overlap, 0));
}

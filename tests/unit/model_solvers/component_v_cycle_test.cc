// ComponentVCycle, ML's V-cycle on the lattice surrogate run on all
// components at once: it equals ML's own cycle applied to each component to
// round-off (2D and 3D LPS with cracks, diffusion, on any number of ranks),
// and declines hierarchies whose smoother it does not repeat. Without ML's
// own matrices of the levels it runs, it is the same cycle.

#include <deal.II/lac/trilinos_precondition.h>

#include <ltn/model_solvers/component_v_cycle.h>
#include <ltn/model_solvers/stencil_matrix.h>

#include <Teuchos_ParameterList.hpp>
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "particle_layout.h"

using namespace ltn;

namespace
{
  /**
   * ML on the surrogate, @p sweeps Chebyshev sweeps, ModelPreconditioner's
   * way, but coarsened to 10 rows, not 200: the test's lattices then have
   * three or four levels, so that the cycle runs two of them itself.
   */
  void
  initialize(TrilinosWrappers::PreconditionAMG &amg,
             const Epetra_CrsMatrix            &matrix,
             const int                          sweeps)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.aggregation_threshold = 1e-4;
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> no_modes;
    data.set_parameters(parameters, no_modes, matrix);
    parameters.set("coarse: max size", 10);
    parameters.set("smoother: sweeps", sweeps);
    amg.initialize(matrix, parameters);
  }

  /** max over columns of |cycle - ML| / max |ML| on random columns. */
  double
  cycle_difference(const DiscreteModel &model, const unsigned int components)
  {
    const Epetra_CrsMatrix &matrix =
      model.lattice->surrogate().matrix.trilinos_matrix();
    TrilinosWrappers::PreconditionAMG amg;
    initialize(amg, matrix, 1);
    const StencilMatrix stencil(matrix);
    REQUIRE(stencil.serve_finest_level(amg));
    ComponentVCycle cycle(amg, matrix, stencil, components);
    REQUIRE(cycle.usable());
    CHECK(cycle.memory_consumption() > 0);

    Epetra_MultiVector                     x(matrix.DomainMap(), components);
    std::mt19937                           random(5);
    std::uniform_real_distribution<double> value(-1, 1);
    for (unsigned int c = 0; c < components; ++c)
      for (int i = 0; i < x.MyLength(); ++i)
        x[c][i] = value(random);
    Epetra_MultiVector by_ml(x), together(x);
    amg.trilinos_operator().ApplyInverse(x, by_ml);
    cycle.vmult(together, x);
    // Without ML's matrices of the levels the cycle runs, the same cycle
    // to the last bit: it reads only its copies and ML's coarser levels.
    cycle.release_ml_levels();
    Epetra_MultiVector again(x);
    cycle.vmult(again, x);
    again.Update(-1., together, 1.);
    std::vector<double> changes(components);
    again.NormInf(changes.data());
    CHECK(*std::max_element(changes.begin(), changes.end()) == 0.);
    double worst = 0;
    for (unsigned int c = 0; c < components; ++c)
      {
        double scale = 0, difference = 0;
        by_ml(c)->NormInf(&scale);
        together(c)->Update(-1., *by_ml(c), 1.);
        together(c)->NormInf(&difference);
        worst = std::max(worst, difference / scale);
      }
    return worst;
  }
} // namespace



TEST_CASE("the V-cycle on all components equals ML's cycle per component",
          "[solvers][unit]")
{
  const auto   lps_2d = cracked_lps<2>(1. / 32, 2, true);
  const auto   lps_3d = cracked_lps<3>(1. / 16, 2, true);
  const auto   heat   = layout_diffusion<2>(1. / 32, 3, true);
  const double d2     = cycle_difference(lps_2d->get_model(), 2);
  const double d3     = cycle_difference(lps_3d->get_model(), 3);
  const double d1     = cycle_difference(heat->get_model(), 1);
  INFO("differences " << d2 << " (2D LPS), " << d3 << " (3D LPS), " << d1
                      << " (diffusion)");
  CHECK(d2 < 1e-12);
  CHECK(d3 < 1e-12);
  CHECK(d1 < 1e-12);
}



TEST_CASE("the V-cycle on all components declines Chebyshev of degree 3",
          "[solvers][unit]")
{
  const auto              particles = cracked_lps<3>(1. / 16, 2, true);
  const Epetra_CrsMatrix &matrix =
    particles->get_model().lattice->surrogate().matrix.trilinos_matrix();
  TrilinosWrappers::PreconditionAMG amg;
  initialize(amg, matrix, 3);
  const StencilMatrix stencil(matrix);
  REQUIRE(stencil.serve_finest_level(amg));
  CHECK_FALSE(ComponentVCycle(amg, matrix, stencil, 3).usable());
}

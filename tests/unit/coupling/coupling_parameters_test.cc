// The Collar layer weight `auto`: the LPS weight of doc/discretization.md,
// 'A coarse level for the controls', per level, and only where the Control
// preconditioner weights
// the nonlocal controls' diagonal. The Crack opening coarse fields `auto`:
// in 2D only, and only where there is a coarse level.

#include <ltn/coupling/solvers/coupling_parameters.h>

#include <catch2/catch.hpp>

using namespace ltn;

namespace
{
  /** The Coupling parameters as parsed from @p sets (name, value). */
  CouplingParameters
  parsed(const std::vector<std::pair<std::string, std::string>> &sets)
  {
    ParameterHandler prm;
    CouplingParameters::declare_parameters(prm);
    prm.enter_subsection("Coupling");
    for (const auto &[name, value] : sets)
      prm.set(name, value);
    prm.leave_subsection();
    CouplingParameters parameters;
    parameters.parse_parameters(prm);
    return parameters;
  }
} // namespace

TEST_CASE("the LPS collar layer weight is 1.5 log2(w / (8 eps)) above 8",
          "[solvers][unit]")
{
  CHECK(lps_collar_layer_weight(2) == 0);
  CHECK(lps_collar_layer_weight(8) == 0);
  CHECK(lps_collar_layer_weight(12.5) == Approx(0.966).epsilon(1e-3));
  CHECK(lps_collar_layer_weight(16) == Approx(1.5));
  CHECK(lps_collar_layer_weight(32) == Approx(3));
  CHECK(lps_collar_layer_weight(64) == Approx(4.5));
}

TEST_CASE("`auto` resolves the collar layer weight per LPS level, a number "
          "stays",
          "[solvers][unit]")
{
  const CouplingParameters automatic = parsed({});
  CHECK(automatic.automatic_collar_layer_weight);
  CHECK(automatic.controls.collar_layer_weight == 0);
  CHECK(automatic.at_lps_level(4).controls.collar_layer_weight == 0);
  CHECK(automatic.at_lps_level(32).controls.collar_layer_weight == Approx(3));

  const CouplingParameters fixed = parsed({{"Collar layer weight", "0.5"}});
  CHECK_FALSE(fixed.automatic_collar_layer_weight);
  CHECK(fixed.at_lps_level(4).controls.collar_layer_weight == 0.5);
  CHECK(fixed.at_lps_level(32).controls.collar_layer_weight == 0.5);

  // Nothing to weight: no preconditioner, or the surrogate's block.
  CHECK(parsed({{"Control preconditioner", "none"}})
          .at_lps_level(32)
          .controls.collar_layer_weight == 0);
  CHECK(parsed({{"Nonlocal control block", "surrogate extension"}})
          .at_lps_level(32)
          .controls.collar_layer_weight == 0);
}

TEST_CASE("`auto` adds the crack opening fields in 2D only, `true` and "
          "`false` everywhere, and none without a coarse level",
          "[solvers][unit]")
{
  const std::vector<AffineProductField> fields = {
    {{{0, 1, 0}}, {{{{0, 1, 0}}, -1.}, {{{1, 0, 0}}, -1.}}}};
  const CouplingParameters automatic = parsed({});
  CHECK(automatic.at_lps_level(4, fields, 2)
          .controls.nonlocal_coarse_fields.size() == 1);
  CHECK(automatic.at_lps_level(4, fields, 3)
          .controls.nonlocal_coarse_fields.empty());
  CHECK(parsed({{"Crack opening coarse fields", "true"}})
          .at_lps_level(4, fields, 3)
          .controls.nonlocal_coarse_fields.size() == 1);
  CHECK(parsed({{"Crack opening coarse fields", "false"}})
          .at_lps_level(4, fields, 2)
          .controls.nonlocal_coarse_fields.empty());
  CHECK(parsed({{"Control preconditioner", "block diagonal"}})
          .at_lps_level(4, fields, 2)
          .controls.nonlocal_coarse_fields.empty());
}

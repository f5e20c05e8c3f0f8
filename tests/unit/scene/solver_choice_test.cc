// The `auto` choice of operator and solvers (choose_solvers()): the exact
// path where a factorization fits, the scalable one from many unknowns or
// from many bonds (a wide horizon), and whatever a scene names kept.

#include <ltn/scene/solver_choice.h>

#include <catch2/catch.hpp>

using namespace ltn;

namespace
{
  /** Everything `auto`, as a scene that names nothing. */
  CouplingParameters
  automatic()
  {
    CouplingParameters coupling;
    coupling.method             = CouplingMethod::automatic;
    coupling.model_solvers.kind = ModelSolverKind::automatic;
    return coupling;
  }

  bool
  scalable(const types::global_dof_index unknowns,
           const std::size_t             bonds,
           const unsigned int            dim)
  {
    const SolverChoice choice = choose_solvers(
      automatic(), OperatorStorage::automatic, unknowns, bonds, dim, true);
    CHECK(choice.coupling.method != CouplingMethod::automatic);
    CHECK(choice.coupling.model_solvers.kind != ModelSolverKind::automatic);
    const bool reduced =
      choice.coupling.method == CouplingMethod::reduced_space_cg;
    // The two paths are whole: nothing of the one mixed into the other.
    CHECK(choice.matrix_free == reduced);
    CHECK(choice.coupling.model_solvers.iterative() == reduced);
    return reduced;
  }
} // namespace



TEST_CASE("auto solvers: exact where the factors fit, scalable from many "
          "unknowns or many bonds",
          "[solvers]")
{
  // 3D, 81 bonds (a horizon of two particle spacings): the unknowns
  // decide.
  CHECK_FALSE(scalable(40000, 81, 3));
  CHECK(scalable(60000, 81, 3));
  // A wide horizon (five spacings, 823 bonds in 3D): 40,000 unknowns
  // hold 3.3e7 bonds, beyond what factorizes in memory.
  CHECK(scalable(40000, 823, 3));
  CHECK_FALSE(scalable(20000, 823, 3));
  // 1D is always factorized.
  CHECK_FALSE(scalable(1000000, 0, 1));
}



TEST_CASE("auto solvers keep what the scene names", "[solvers]")
{
  CouplingParameters named = automatic();
  named.method             = CouplingMethod::full_space_direct;
  const SolverChoice choice =
    choose_solvers(named, OperatorStorage::automatic, 40000, 823, 3, true);
  CHECK(choice.coupling.method == CouplingMethod::full_space_direct);
  CHECK_FALSE(choice.matrix_free);
  CHECK(choice.coupling.model_solvers.kind == ModelSolverKind::direct);
  // The scene asked for a factorization past the limit: where to look.
  CHECK(choice.note.find("Large scenes") != std::string::npos);
}

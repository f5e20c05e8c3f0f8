#pragma once

#include <deal.II/base/types.h>

#include <ltn/coupling/solvers/coupling_parameters.h>
#include <ltn/nonlocal/nonlocal_parameters.h>

#include <string>

namespace ltn
{
  /**
   * The particle operator's storage and the solvers of one level, with
   * every `auto` of `Nonlocal model/Operator`, `Coupling/Model solvers` and
   * `Coupling/Method` resolved.
   */
  struct SolverChoice
  {
    bool               matrix_free = false;
    CouplingParameters coupling;
    /**
     * What `auto` chose, for the console; empty when it chose nothing or
     * only the exact path.
     */
    std::string description;
    /**
     * For a particle model from scalable_from_unknowns on that the scene's
     * named choices factorize (direct model solvers, or the full-space
     * direct system): where the settings that scale are. The run goes on as
     * asked. Empty otherwise.
     */
    std::string note;
  };

  /**
   * The particle models from this many unknowns on take the scalable path
   * when the scene leaves the choice to `auto`: their sparse factors grow
   * far faster than the particles (doc/prm_guide.md, 'Large scenes').
   */
  constexpr types::global_dof_index scalable_from_unknowns = 50000;

  /**
   * Nor do fewer unknowns with many bonds each (a wide horizon in particle
   * spacings): from this many unknowns times bonds per particle on, the
   * assembled matrix holds about as many entries and its factors many
   * times more, so the scalable path is taken whatever the unknowns.
   */
  constexpr double scalable_from_bonds = 2.5e7;

  /**
   * Resolve the `auto` choices of @p coupling and @p storage for a level
   * whose particle model has @p n_particle_unknowns unknowns and
   * @p bonds_per_particle bonds per particle in @p dim dimensions (none:
   * 0), coupled to a local model or alone (@p coupled). Below
   * scalable_from_unknowns and scalable_from_bonds, and in 1D, the exact
   * path: the operator
   * assembled, the models factorized, the full-space direct system. From
   * there on the scalable one: matrix-free, preconditioned CG in the
   * particle model with the finite element model factorized, the
   * reduced-space CG. A choice the scene names is kept, and the `auto`
   * ones follow what it needs: a matrix-free operator makes the model
   * solvers iterative and the method the reduced-space CG; direct model
   * solvers or the full-space direct method keep the operator assembled;
   * `Time standalone solves` asks for the reduced-space CG.
   */
  SolverChoice
  choose_solvers(const CouplingParameters     &coupling,
                 const OperatorStorage         storage,
                 const types::global_dof_index n_particle_unknowns,
                 const std::size_t             bonds_per_particle,
                 const unsigned int            dim,
                 const bool                    coupled);
} // namespace ltn

#include <ltn/scene/solver_choice.h>

namespace ltn
{
  SolverChoice
  choose_solvers(const CouplingParameters     &coupling,
                 const OperatorStorage         storage,
                 const types::global_dof_index n_particle_unknowns,
                 const std::size_t             bonds_per_particle,
                 const unsigned int            dim,
                 const bool                    coupled)
  {
    const bool scalable =
      dim > 1 &&
      (n_particle_unknowns >= scalable_from_unknowns ||
       static_cast<double>(n_particle_unknowns) * bonds_per_particle >=
         scalable_from_bonds);
    const ModelSolverKind named_solvers = coupling.model_solvers.kind;
    const CouplingMethod  named_method  = coupling.method;
    // The direct paths a scene can name; auto choices do not leave them.
    // A blending is one factorized system (on the lattice: the particle
    // model's rows blended).
    const bool named_direct =
      named_solvers == ModelSolverKind::direct ||
      (coupled && named_method == CouplingMethod::full_space_direct) ||
      coupling.blending();

    SolverChoice choice;
    choice.coupling = coupling;
    // What auto chose, and whether any of it left the exact path: only
    // that is worth a line on the console.
    std::string auto_choices;
    bool        auto_scaled = false;
    const auto  chose =
      [&](const std::string &what, const std::string &name, const bool scaled) {
        auto_choices += (auto_choices.empty() ? "" : ", ") + what + " " + name;
        auto_scaled = auto_scaled || scaled;
      };

    if (storage == OperatorStorage::automatic)
      {
        choice.matrix_free = scalable && !named_direct;
        chose("operator",
              selection_name(operator_storage_names(),
                             choice.matrix_free ? OperatorStorage::matrix_free :
                                                  OperatorStorage::assembled),
              choice.matrix_free);
      }
    else
      choice.matrix_free = storage == OperatorStorage::matrix_free;

    ModelSolverSettings &solvers = choice.coupling.model_solvers;
    if (named_solvers == ModelSolverKind::automatic)
      {
        const bool iterative =
          (choice.matrix_free || scalable) && !named_direct;
        solvers.kind = iterative ? ModelSolverKind::preconditioned_cg :
                                   ModelSolverKind::direct;
        // The finite element model's mesh is coarse wherever the coupling
        // is used, and the coupled solve needs a local solve per local
        // coarse column: factorized, they are cheap.
        if (iterative)
          solvers.direct_local_model = true;
        chose("model solvers",
              selection_name(model_solver_names(), solvers.kind) +
                (iterative ? " (finite element model direct)" : ""),
              iterative);
      }

    if (named_method == CouplingMethod::automatic)
      {
        const bool reduced = choice.matrix_free ||
                             (scalable && solvers.iterative()) ||
                             coupling.time_standalone_solves;
        choice.coupling.method = reduced ? CouplingMethod::reduced_space_cg :
                                           CouplingMethod::full_space_direct;
        if (coupled)
          chose("method",
                selection_name(coupling_method_names(), choice.coupling.method),
                reduced);
      }

    if (auto_scaled)
      choice.description = "auto for " + std::to_string(n_particle_unknowns) +
                           " particle unknowns: " + auto_choices;
    const bool factorized =
      !solvers.iterative() ||
      (coupled && choice.coupling.method == CouplingMethod::full_space_direct);
    if (scalable && factorized)
      choice.note = "the particle model's " +
                    std::to_string(n_particle_unknowns) + " unknowns (" +
                    std::to_string(bonds_per_particle) +
                    " bonds per particle) are factorized by a direct "
                    "solver; for scenes this large, doc/prm_guide.md "
                    "(\"Large scenes\") gives settings that scale";
    // What the scene named, and what auto made of the rest, must agree.
    choice.coupling.check_operator(choice.matrix_free, coupled);
    return choice;
  }
} // namespace ltn

#include <ltn/model_solvers/model_preconditioner.h>

#include <algorithm>

namespace ltn
{
  ModelPreconditioner::ModelPreconditioner(
    const DiscreteModel              &model,
    const std::vector<unsigned int>  &subset,
    const SurrogateMultigridSettings &settings)
    : on_surrogate(model.lattice != nullptr)
    , node_dofs(on_surrogate ? model.lattice->node_dofs : 1)
    , surrogate_components(
        on_surrogate ? model.lattice->surrogate().components : 1)
    , nodes(on_surrogate ? model.lattice->surrogate().nodes :
                           std::vector<unsigned int>())
    , subset(subset)
  {
    if (on_surrogate)
      {
        std::vector<unsigned int> entry_of_position(
          model.owned.n_elements(), numbers::invalid_unsigned_int);
        for (unsigned int e = 0; e < subset.size(); ++e)
          entry_of_position[subset[e]] = e;
        subset_entry.resize(surrogate_components * nodes.size());
        interleaved = subset.size() == subset_entry.size();
        for (unsigned int c = 0; c < surrogate_components; ++c)
          for (std::size_t i = 0; i < nodes.size(); ++i)
            {
              const unsigned int entry =
                entry_of_position[node_dofs * nodes[i] + c];
              subset_entry[c * nodes.size() + i] = entry;
              interleaved =
                interleaved && entry == surrogate_components * i + c;
            }
        // The free block of a particle model with all its free particles
        // surrogate nodes: no index lists to read, no entry to copy.
        if (interleaved)
          subset_entry = std::vector<unsigned int>();
      }
    // Only the particle models' CG asks for a subset (ModelSolver), and
    // they all have a surrogate.
    AssertThrow(on_surrogate || subset.empty(),
                ExcMessage("a preconditioner on a subset of the entries "
                           "needs the model's lattice surrogate"));

    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    // Three Chebyshev sweeps: two leave FE_Q(2) elasticity at 210 GMRES
    // iterations per solve (lps_plate_2d_asymptotic_compatibility.prm,
    // h = 1/16), three at 48; ILU and Gauss-Seidel smoothers at 48-56 cost
    // more.
    data.smoother_sweeps       = 3;
    data.aggregation_threshold = 1e-4;
    if (!on_surrogate)
      {
        data.constant_modes = model.constant_modes;
        // A constraint row x_i - sum_k c_ik x_k = 0 (a hanging node) makes
        // the matrix nonsymmetric, and ML's Chebyshev smoothing of it
        // diverged: the local GMRES of the cracked plate on a graded mesh
        // stalled at a relative residual of 0.9. The hierarchy is built on
        // the matrix with identity rows there instead: were the V-cycle
        // exact on the other rows, the preconditioned operator would be the
        // identity plus a nilpotent part at those rows (x_i follows its
        // masters), which GMRES resolves in one more iteration.
        if (Utilities::MPI::max(model.constrained.n_elements(),
                                model.communicator) == 0)
          {
            amg.initialize(model.matrix, data);
            return;
          }
        amg_matrix.copy_from(model.matrix);
        const std::vector<types::global_dof_index> rows(
          model.constrained.begin(), model.constrained.end());
        amg_matrix.clear_rows(rows, 1.);
        amg.initialize(amg_matrix, data);
        return;
      }
    // The surrogate is scalar (its near null space the constants, ML's
    // default). One hierarchy on it, applied per component, is a third of
    // the size of one on the vector Laplacian, whose components ML would
    // aggregate apart while still giving each aggregate a coarse unknown
    // per component of the near null space.
    //
    // Coarsened until at most the settings' coarsest rows of the lattice's
    // dimension are left (measurements: benchmarks/scaling/HISTORY.md,
    // "Figures code comments quoted").
    const LatticeSurrogate             &lattice = model.lattice->surrogate();
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> no_modes;
    data.set_parameters(parameters, no_modes, lattice.matrix);
    parameters.set("coarse: max size",
                   static_cast<int>(
                     settings.coarsest_rows.at(lattice.dimension - 2)));
    // One Chebyshev sweep on the surrogate, not the three of the FEM
    // matrices: what the V-cycle misses of the particle model is mostly its
    // difference from the surrogate, not the surrogate's smooth error
    // ('Iterative model solvers'): a few more iterations, each cheaper.
    parameters.set("smoother: sweeps", 1);
    // ML's finest level multiplies by the surrogate's stencil, not by its
    // compressed rows ('Iterative model solvers').
    amg.initialize(lattice.matrix, parameters);
    const Epetra_CrsMatrix &surrogate = lattice.matrix.trilinos_matrix();
    stencil = std::make_unique<StencilMatrix>(surrogate);
    if (!stencil->is_stencil() || !stencil->serve_finest_level(amg))
      stencil.reset();
    // All components through one cycle ('Iterative model solvers'): one
    // pass over the hierarchy for all of them, the same iterations.
    if (stencil)
      cycle = std::make_unique<ComponentVCycle>(amg,
                                                surrogate,
                                                *stencil,
                                                surrogate_components);
    if (cycle && !cycle->usable())
      cycle.reset();
    // ML's own matrices of those levels are released: the cycle keeps
    // copies of its own, and two would only hold memory ('Iterative model
    // solvers').
    if (cycle)
      cycle->release_ml_levels();
    node_in  = std::make_unique<Epetra_MultiVector>(surrogate.DomainMap(),
                                                   surrogate_components);
    node_out = std::make_unique<Epetra_MultiVector>(*node_in);
    // The short-wave term (doc/discretization.md, 'Iterative model
    // solvers').
    const IndexSet &rows = lattice.matrix.locally_owned_range_indices();
    short_wave_scaling.resize(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i)
      short_wave_scaling[i] =
        settings.short_wave_factor * lattice.long_wave_ratio /
        lattice.matrix.diag_element(rows.nth_index_in_set(i));
  }



  void
  ModelPreconditioner::vmult(TrilinosWrappers::MPI::Vector       &dst,
                             const TrilinosWrappers::MPI::Vector &src) const
  {
    if (!on_surrogate)
      {
        amg.vmult(dst, src);
        return;
      }
    // The identity at the eliminated components (a Schur complement's
    // vectors are zero there).
    // So it is at the nodes the surrogate leaves out (their rows of the
    // model are identities).
    // A copy of the owned values: `dst = src` of two vectors made apart
    // imports (deal.II 9.4 compares their communicators' objects).
    AssertDimension(dst.locally_owned_size(), src.locally_owned_size());
    std::copy(src.begin(), src.end(), dst.begin());
    const std::size_t n = nodes.size();
    for (unsigned int c = 0; c < surrogate_components; ++c)
      {
        double *const in = (*node_in)[c];
        for (std::size_t i = 0; i < n; ++i)
          in[i] = src.begin()[node_dofs * nodes[i] + c];
      }
    apply_cycle();
    for (unsigned int c = 0; c < surrogate_components; ++c)
      {
        const double *const in = (*node_in)[c], *const out = (*node_out)[c];
        for (std::size_t i = 0; i < n; ++i)
          dst.begin()[node_dofs * nodes[i] + c] =
            out[i] + short_wave_scaling[i] * in[i];
      }
  }



  void
  ModelPreconditioner::vmult_subset(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    const std::size_t n = nodes.size();
    if (interleaved)
      {
        // One gather of all components and one scatter, without the copy
        // and the index lists below; a gather and a scatter per component
        // passed over the whole vector each.
        const unsigned int    stride = surrogate_components;
        std::vector<double *> in(stride), out(stride);
        for (unsigned int c = 0; c < stride; ++c)
          {
            in[c]  = (*node_in)[c];
            out[c] = (*node_out)[c];
          }
        for (std::size_t i = 0; i < n; ++i)
          for (unsigned int c = 0; c < stride; ++c)
            in[c][i] = src.begin()[stride * i + c];
        apply_cycle();
        for (std::size_t i = 0; i < n; ++i)
          for (unsigned int c = 0; c < stride; ++c)
            dst.begin()[stride * i + c] =
              out[c][i] + short_wave_scaling[i] * in[c][i];
        return;
      }
    // The identity where the surrogate leaves a degree of freedom out, as
    // in vmult().
    std::copy(src.begin(), src.end(), dst.begin());
    for (unsigned int c = 0; c < surrogate_components; ++c)
      {
        const unsigned int *entry = &subset_entry[c * n];
        double *const       in    = (*node_in)[c];
        for (std::size_t i = 0; i < n; ++i)
          in[i] = entry[i] == numbers::invalid_unsigned_int ?
                    0. :
                    src.begin()[entry[i]];
      }
    apply_cycle();
    for (unsigned int c = 0; c < surrogate_components; ++c)
      {
        const unsigned int *entry = &subset_entry[c * n];
        const double *const in = (*node_in)[c], *const out = (*node_out)[c];
        for (std::size_t i = 0; i < n; ++i)
          if (entry[i] != numbers::invalid_unsigned_int)
            dst.begin()[entry[i]] = out[i] + short_wave_scaling[i] * in[i];
      }
  }



  void
  ModelPreconditioner::apply_cycle() const
  {
    if (cycle)
      cycle->vmult(*node_out, *node_in);
    else
      {
        // ML applies its cycle to one column at a time.
        const int error =
          amg.trilinos_operator().ApplyInverse(*node_in, *node_out);
        AssertThrow(error == 0, ExcMessage("ML's V-cycle"));
      }
  }



  std::size_t
  ModelPreconditioner::memory_consumption() const
  {
    const std::size_t node_vectors =
      node_in ? 2 * std::size_t(node_in->MyLength()) * node_in->NumVectors() *
                  sizeof(double) :
                0;
    return amg.memory_consumption() + amg_matrix.memory_consumption() +
           (stencil ? stencil->memory_consumption() : 0) +
           (cycle ? cycle->memory_consumption() : 0) + node_vectors +
           nodes.size() * (sizeof(unsigned int) + sizeof(double)) +
           (subset.size() + subset_entry.size()) * sizeof(unsigned int);
  }
} // namespace ltn

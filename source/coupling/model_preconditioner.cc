#include <ltn/coupling/model_preconditioner.h>

namespace ltn
{
  ModelPreconditioner::ModelPreconditioner(const DiscreteModel &model)
    : on_surrogate(model.surrogate.m() > 0)
    , node_dofs(model.node_dofs)
    , surrogate_components(model.surrogate_components)
  {
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
        amg.initialize(model.matrix, data);
        return;
      }
    // The surrogate is scalar (its near null space the constants, ML's
    // default). One hierarchy on it, applied per component, is a third of
    // the size of one on the vector Laplacian, whose components ML would
    // aggregate apart while still giving each aggregate a coarse unknown
    // per component of the near null space.
    amg.initialize(model.surrogate, data);
    node_src.reinit(model.surrogate.locally_owned_domain_indices(),
                    model.communicator);
    node_dst.reinit(node_src);
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
    dst                     = src;
    const std::size_t nodes = node_src.locally_owned_size();
    for (unsigned int c = 0; c < surrogate_components; ++c)
      {
        for (std::size_t i = 0; i < nodes; ++i)
          node_src.begin()[i] = src.begin()[node_dofs * i + c];
        amg.vmult(node_dst, node_src);
        for (std::size_t i = 0; i < nodes; ++i)
          dst.begin()[node_dofs * i + c] = node_dst.begin()[i];
      }
  }



  std::size_t
  ModelPreconditioner::memory_consumption() const
  {
    return amg.memory_consumption() + node_src.memory_consumption() +
           node_dst.memory_consumption();
  }
} // namespace ltn

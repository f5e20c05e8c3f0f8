#include <ltn/coupling/model_preconditioner.h>

namespace ltn
{
  ModelPreconditioner::ModelPreconditioner(const DiscreteModel &model)
  {
    const TrilinosWrappers::SparseMatrix &matrix =
      model.surrogate.m() > 0 ? model.surrogate : model.matrix;
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    // Three Chebyshev sweeps: two leave FE_Q(2) elasticity at 210 GMRES
    // iterations per solve (lps_plate_2d_asymptotic_compatibility.prm,
    // h = 1/16), three at 48; ILU and Gauss-Seidel smoothers at 48-56 cost
    // more.
    data.smoother_sweeps       = 3;
    data.aggregation_threshold = 1e-4;
    data.constant_modes        = model.constant_modes;
    amg.initialize(matrix, data);
  }



  void
  ModelPreconditioner::vmult(TrilinosWrappers::MPI::Vector       &dst,
                             const TrilinosWrappers::MPI::Vector &src) const
  {
    amg.vmult(dst, src);
  }



  std::size_t
  ModelPreconditioner::memory_consumption() const
  {
    return amg.memory_consumption();
  }
} // namespace ltn

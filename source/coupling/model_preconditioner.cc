#include <ltn/coupling/model_preconditioner.h>

namespace ltn
{
  ModelPreconditioner::ModelPreconditioner(const DiscreteModel &model,
                                           const bool           transpose)
    : model(model)
    , transpose(transpose)
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

    t                = model.new_vector();
    v                = model.new_vector();
    w                = model.new_vector();
    kept             = model.new_vector();
    kept             = 1.;
    inverse_diagonal = model.new_vector();
    eliminates       = Utilities::MPI::sum(model.eliminated.n_elements(),
                                     model.communicator) > 0;
    if (eliminates)
      {
        // The diagonal block D: M applied to the indicator of the
        // eliminated degrees of freedom, read at them.
        for (const auto i : model.eliminated)
          {
            t(i)    = 1.;
            kept(i) = 0.;
          }
        t.compress(VectorOperation::insert);
        kept.compress(VectorOperation::insert);
        model.vmult(w, t);
        for (const auto i : model.eliminated)
          inverse_diagonal(i) = 1. / w(i);
        inverse_diagonal.compress(VectorOperation::insert);
      }
  }



  void
  ModelPreconditioner::apply_model(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    if (transpose)
      model.Tvmult(dst, src);
    else
      model.vmult(dst, src);
  }



  void
  ModelPreconditioner::vmult(TrilinosWrappers::MPI::Vector       &dst,
                             const TrilinosWrappers::MPI::Vector &src) const
  {
    if (!eliminates)
      {
        amg.vmult(dst, src);
        return;
      }
    // t = D^-1 r_t; v = r_u - B t (only at the kept degrees of freedom).
    t = src;
    t.scale(inverse_diagonal);
    apply_model(w, t);
    v = src;
    v -= w;
    v.scale(kept);
    // u = AMG(v), kept degrees of freedom only.
    amg.vmult(dst, v);
    dst.scale(kept);
    // t = D^-1 (r_t - C u).
    apply_model(w, dst);
    v = src;
    v -= w;
    v.scale(inverse_diagonal);
    dst += v;
  }



  std::size_t
  ModelPreconditioner::memory_consumption() const
  {
    return amg.memory_consumption() + 5 * t.memory_consumption();
  }
} // namespace ltn

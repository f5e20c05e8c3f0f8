#include <ltn/coupling/preconditioners/kkt_preconditioner.h>

namespace ltn
{
  template <int dim>
  KktPreconditioner<dim>::KktPreconditioner(
    const KktOperator<dim>                   &kkt,
    const std::array<const ModelSolver *, 2> &solvers,
    const ControlPreconditioner<dim>         &controls)
    : kkt(kkt)
    , solvers(solvers)
    , controls(controls)
  {}



  template <int dim>
  void
  KktPreconditioner<dim>::vmult(BlockVectorType       &dst,
                                const BlockVectorType &src) const
  {
    using VectorType = TrilinosWrappers::MPI::Vector;
    // The unscaled residual of the model rows: g = g_scaled / s.
    std::array<VectorType, 2> g, zg, x, observed;
    for (const unsigned int k : {0u, 1u})
      {
        g[k] = src.block(2 + k);
        g[k] /= kkt.scale;
        zg[k] = g[k];
        kkt.zero_controls(k, zg[k]);
        x[k] = solvers[k]->solve(false, zg[k]);
      }

    // The reduced gradient of the residual, and the controls from it.
    kkt.system.observe(x[0], x[1], observed[0], observed[1]);
    BlockVectorType reduced(2), theta(2);
    for (const unsigned int k : {0u, 1u})
      {
        VectorType y = src.block(k);
        y -= observed[k];
        reduced.block(k) =
          solvers[k]->restrict_to_controls(solvers[k]->solve(true, y));
        theta.block(k) = reduced.block(k);
      }
    reduced.collect_sizes();
    theta.collect_sizes();
    controls.vmult(theta, reduced);

    // The states of these controls, and the multipliers of their residual.
    for (const unsigned int k : {0u, 1u})
      {
        VectorType rhs = solvers[k]->extend_controls(theta.block(k));
        rhs += zg[k];
        x[k] = solvers[k]->solve(false, rhs);
      }
    kkt.system.observe(x[0], x[1], observed[0], observed[1]);
    for (const unsigned int k : {0u, 1u})
      {
        VectorType y = src.block(k);
        y -= observed[k];
        kkt.zero_controls(k, y);
        VectorType &mu = dst.block(2 + k);
        mu             = solvers[k]->solve(true, y);
        kkt.zero_controls(k, mu);
        // (I - Z) g: the control rows' multipliers are their residuals.
        mu += g[k];
        mu -= zg[k];
        mu /= kkt.scale; // mu_scaled = mu / s
        dst.block(k) = x[k];
      }
  }

  template class KktPreconditioner<1>;
  template class KktPreconditioner<2>;
  template class KktPreconditioner<3>;
} // namespace ltn

#include <ltn/coupling/system/reduced_hessian.h>

namespace ltn
{
  template <int dim>
  ReducedHessian<dim>::ReducedHessian(
    const CouplingSystem<dim>                &system,
    const std::array<const ModelSolver *, 2> &solvers)
    : system(system)
    , solvers(solvers)
  {}



  template <int dim>
  typename ReducedHessian<dim>::BlockVectorType
  ReducedHessian<dim>::new_control_vector() const
  {
    BlockVectorType theta(2);
    for (const unsigned int k : {0u, 1u})
      theta.block(k) = solvers[k]->new_control_vector();
    theta.collect_sizes();
    return theta;
  }



  template <int dim>
  typename ReducedHessian<dim>::BlockVectorType
  ReducedHessian<dim>::reduced_gradient(const std::vector<double> &d) const
  {
    std::array<TrilinosWrappers::MPI::Vector, 2> z;
    system.mismatch_gradient(d, z[0], z[1]);
    return adjoint(z);
  }



  template <int dim>
  typename ReducedHessian<dim>::BlockVectorType
  ReducedHessian<dim>::adjoint(
    const std::array<TrilinosWrappers::MPI::Vector, 2> &state_gradients) const
  {
    BlockVectorType g(2);
    for (const unsigned int k : {0u, 1u})
      g.block(k) = solvers[k]->adjoint(state_gradients[k]);
    g.collect_sizes();
    return g;
  }



  template <int dim>
  std::vector<double>
  ReducedHessian<dim>::mismatch(const BlockVectorType &theta,
                                const bool             with_data) const
  {
    return system.mismatch(solvers[0]->forward(theta.block(0), with_data),
                           solvers[1]->forward(theta.block(1), with_data));
  }



  template <int dim>
  void
  ReducedHessian<dim>::vmult(BlockVectorType       &dst,
                             const BlockVectorType &theta) const
  {
    dst = reduced_gradient(mismatch(theta, false));
    dst.add(system.alpha, theta);
  }



  template <int dim>
  NormalEquations
  ReducedHessian<dim>::normal_equations() const
  {
    using VectorType = NormalEquations::VectorType;
    return {
      [this](const unsigned int k,
             const VectorType  &theta_k,
             const VectorType  *initial_state) {
        return solvers[k]->forward(theta_k, false, initial_state);
      },
      [this](const NormalEquations::States &u) {
        return system.mismatch(u[0], u[1]);
      },
      [this](const unsigned int k, const std::vector<double> &d) {
        return system.mismatch_gradient(k, d);
      },
      [this](const NormalEquations::States &gradient) {
        return adjoint(gradient);
      },
      [this](const unsigned int k) { return system.models[k]->new_vector(); },
      // sum_q w_q b_qi^2 with w_q > 0: nonzero exactly where some point
      // reads an unknown with a nonzero coefficient.
      [this](const unsigned int k) { return system.observation_diagonal(k); },
      system.alpha,
      [this](const unsigned int k, const std::vector<VectorType> &controls) {
        return solvers[k]->forward(controls);
      }};
  }



  template class ReducedHessian<1>;
  template class ReducedHessian<2>;
  template class ReducedHessian<3>;
} // namespace ltn

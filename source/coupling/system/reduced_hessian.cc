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
    BlockVectorType g(2);
    for (const unsigned int k : {0u, 1u})
      g.block(k) = solvers[k]->adjoint(z[k]);
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



  template class ReducedHessian<1>;
  template class ReducedHessian<2>;
  template class ReducedHessian<3>;
} // namespace ltn

#include <ltn/coupling/system/kkt_operator.h>

#include <cmath>

namespace ltn
{
  template <int dim>
  KktOperator<dim>::KktOperator(const CouplingSystem<dim> &system)
    : system(system)
  {
    // The size of B^T W B: its largest diagonal entry. The size of M: its
    // gain on a fixed oscillating vector, the same on any number of ranks.
    double observation = 0, model = 0;
    for (const unsigned int k : {0u, 1u})
      {
        observation =
          std::max(observation, system.observation_diagonal(k).linfty_norm());
        TrilinosWrappers::MPI::Vector v = system.models[k]->new_vector();
        TrilinosWrappers::MPI::Vector w = system.models[k]->new_vector();
        for (const auto i : system.models[k]->owned)
          v(i) = std::sin(1.7 * i);
        v.compress(VectorOperation::insert);
        system.models[k]->vmult(w, v);
        model = std::max(model, w.l2_norm() / v.l2_norm());
      }
    scale = (observation > 0 && model > 0) ? observation / model : 1.;
  }



  template <int dim>
  typename KktOperator<dim>::BlockVectorType
  KktOperator<dim>::new_vector() const
  {
    BlockVectorType v(4);
    for (const unsigned int k : {0u, 1u})
      {
        v.block(k)     = system.models[k]->new_vector();
        v.block(2 + k) = system.models[k]->new_vector();
      }
    v.collect_sizes();
    return v;
  }



  template <int dim>
  typename KktOperator<dim>::BlockVectorType
  KktOperator<dim>::rhs() const
  {
    BlockVectorType b = new_vector();
    for (const unsigned int k : {0u, 1u})
      {
        b.block(2 + k) = system.models[k]->rhs;
        b.block(2 + k) *= scale;
      }
    return b;
  }



  template <int dim>
  void
  KktOperator<dim>::zero_controls(const unsigned int             k,
                                  TrilinosWrappers::MPI::Vector &x) const
  {
    for (const auto i : system.models[k]->controls)
      x(i) = 0.;
    x.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  KktOperator<dim>::vmult(BlockVectorType       &dst,
                          const BlockVectorType &src) const
  {
    system.observe(src.block(0), src.block(1), dst.block(0), dst.block(1));
    for (const unsigned int k : {0u, 1u})
      {
        const DiscreteModel                 &model = *system.models[k];
        const TrilinosWrappers::MPI::Vector &x     = src.block(k);
        const TrilinosWrappers::MPI::Vector &mu    = src.block(2 + k);

        // x rows: B^T W B x + alpha R x + s M^T Z mu.
        TrilinosWrappers::MPI::Vector t = mu;
        zero_controls(k, t);
        TrilinosWrappers::MPI::Vector product = model.new_vector();
        model.Tvmult(product, t);
        dst.block(k).add(scale, product);
        if (system.alpha != 0)
          {
            // R x = x - Z x.
            t = x;
            zero_controls(k, t);
            t.sadd(-1., 1., x);
            dst.block(k).add(system.alpha, t);
          }

        // mu rows: s Z M x + s^2 (I - Z) mu.
        model.vmult(product, x);
        zero_controls(k, product);
        t = mu;
        zero_controls(k, t);
        dst.block(2 + k) = mu;
        dst.block(2 + k) -= t;
        dst.block(2 + k).sadd(scale * scale, scale, product);
      }
  }

  template class KktOperator<1>;
  template class KktOperator<2>;
  template class KktOperator<3>;
} // namespace ltn

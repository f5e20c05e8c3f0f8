#include <deal.II/base/mpi.h>

#include <deal.II/lac/vector.h>

#include <ltn/coupling/preconditioners/control_preconditioner.h>

namespace ltn
{
  namespace
  {
    /**
     * Per nonlocal control `i`, `c_i / max_j c_j`: `c_i` the weight of the
     * bonds of its particle into `Omega_n` in the lattice surrogate, the
     * column sum of `C` (LatticeSurrogate::collar), the same for each
     * component of a particle.
     */
    TrilinosWrappers::MPI::Vector
    collar_reach(const DiscreteModel &model, const ModelSolver &solver)
    {
      AssertThrow(model.lattice,
                  ExcMessage("Coupling/Collar layer weight needs a particle "
                             "model's lattice surrogate (2D or 3D)"));
      const TrilinosWrappers::SparseMatrix &collar =
        model.lattice->surrogate().collar;
      const unsigned int            node_dofs = model.lattice->node_dofs;
      TrilinosWrappers::MPI::Vector ones(collar.locally_owned_range_indices(),
                                         model.communicator);
      ones = 1.;
      TrilinosWrappers::MPI::Vector column_sums(
        collar.locally_owned_domain_indices(), model.communicator);
      collar.Tvmult(column_sums, ones);
      // The columns are partitioned like the owned nodes, whose degrees of
      // freedom are node_dofs * node + c.
      TrilinosWrappers::MPI::Vector at_dofs = model.new_vector();
      for (std::size_t node = 0; node < column_sums.locally_owned_size();
           ++node)
        for (unsigned int c = 0; c < node_dofs; ++c)
          at_dofs.begin()[node_dofs * node + c] = column_sums.begin()[node];
      TrilinosWrappers::MPI::Vector reach =
        solver.restrict_to_controls(at_dofs);
      const double largest = reach.linfty_norm();
      if (largest > 0)
        reach /= largest;
      return reach;
    }
  } // namespace



  template <int dim>
  ControlPreconditioner<dim>::ControlPreconditioner(
    const ReducedHessian<dim>        &hessian,
    const std::optional<unsigned int> coarse_degree,
    const bool                        with_local_block,
    const bool                        surrogate_nonlocal_block,
    const double                      collar_layer_weight)
  {
    const ModelSolver &nonlocal = *hessian.solvers[nonlocal_model];
    nonlocal_diagonal           = nonlocal.restrict_to_controls(
      hessian.system.observation_diagonal(nonlocal_model));
    // Every control particle is in the overlap; should a control of another
    // nonlocal discretization be unobserved, it is scaled like the average.
    const double mean_diagonal =
      nonlocal_diagonal.size() > 0 ?
        nonlocal_diagonal.l1_norm() / nonlocal_diagonal.size() :
        0.;
    for (const auto i : nonlocal_diagonal.locally_owned_elements())
      nonlocal_diagonal(i) =
        (nonlocal_diagonal(i) > 0 ? nonlocal_diagonal(i) : mean_diagonal) +
        hessian.system.alpha;
    nonlocal_diagonal.compress(VectorOperation::insert);
    // The top modes of D_n^{-1} H_nn lie mostly on the layer whose bonds
    // reach into Omega_n ('A coarse level for the controls', "The collar
    // layer's weight").
    if (collar_layer_weight > 0)
      {
        const TrilinosWrappers::MPI::Vector reach =
          collar_reach(*hessian.system.models[nonlocal_model], nonlocal);
        for (const auto i : nonlocal_diagonal.locally_owned_elements())
          nonlocal_diagonal(i) *= 1 + collar_layer_weight * reach(i);
        nonlocal_diagonal.compress(VectorOperation::insert);
      }
    if (surrogate_nonlocal_block)
      nonlocal_block = std::make_unique<const SurrogateHessianBlock>(
        *hessian.system.models[nonlocal_model],
        nonlocal,
        nonlocal_diagonal,
        hessian.system.observation_diagonal(nonlocal_model));

    // H_ll = (P V_l)^T W (P V_l) + alpha I: one forward local solve per
    // local control, u_j = V_l e_j, and its observation turned back into a
    // vector of the local model, g_j = P^T W P u_j (the local part of
    // B^T W B [0; u_j]); then H_ll(i, j) = u_i . g_j, summed
    // over the ranks. The observations at the overlap points, kept instead,
    // held one value per point and control: 170 MB of the 700 MB peak of
    // the 1.1e5-particle bar (78 local controls).
    const ModelSolver &local = *hessian.solvers[local_model];
    const unsigned int n =
      with_local_block ? local.new_control_vector().size() : 0;
    const auto zero_nonlocal =
      hessian.system.models[nonlocal_model]->new_vector();
    std::vector<TrilinosWrappers::MPI::Vector> fields(n), observed(n);
    TrilinosWrappers::MPI::Vector              unused;
    for (unsigned int j = 0; j < n; ++j)
      {
        TrilinosWrappers::MPI::Vector unit = local.new_control_vector();
        if (unit.in_local_range(j))
          unit(j) = 1.;
        unit.compress(VectorOperation::insert);
        fields[j] = local.forward(unit, false);
        hessian.system.observe(zero_nonlocal, fields[j], unused, observed[j]);
      }
    std::vector<double> gram(static_cast<std::size_t>(n) * n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j <= i; ++j)
        {
          double sum = 0;
          for (std::size_t k = 0; k < fields[i].locally_owned_size(); ++k)
            sum += fields[i].begin()[k] * observed[j].begin()[k];
          gram[std::size_t(i) * n + j] = sum;
        }
    Utilities::MPI::sum(gram, hessian.system.communicator(), gram);
    local_block.reinit(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j <= i; ++j)
        local_block(i, j) = local_block(j, i) =
          gram[std::size_t(i) * n + j] + (i == j ? hessian.system.alpha : 0.);
    local_block.set_property(LAPACKSupport::symmetric);
    if (n > 0)
      local_block.compute_cholesky_factorization();

    // The coarse products need the model solvers' full tolerance: for the
    // fields both models share, H z is a small difference of two states,
    // and its relative error is that of the states divided by the
    // eigenvalue. With products to 1e-3 the 2D cracked plate took 95 outer
    // iterations instead of 43 (1e-6: 59), worse than one level (59).
    if (coarse_degree)
      {
        std::vector<BlockVectorType> Z;
        for (auto &z : polynomial_control_fields(hessian,
                                                 *coarse_degree,
                                                 {nonlocal_model, local_model}))
          Z.push_back(std::move(z.controls));
        coarse = std::make_unique<const ControlCoarseSpace>(
          std::move(Z), [&](BlockVectorType &dst, const BlockVectorType &src) {
            hessian.vmult(dst, src);
          });
      }
  }



  template <int dim>
  void
  ControlPreconditioner<dim>::vmult(BlockVectorType       &dst,
                                    const BlockVectorType &src) const
  {
    if (coarse)
      coarse->balance(dst,
                      src,
                      [this](BlockVectorType &y, const BlockVectorType &r) {
                        apply_block_diagonal(y, r);
                      });
    else
      apply_block_diagonal(dst, src);
  }



  template <int dim>
  void
  ControlPreconditioner<dim>::apply_block_diagonal(
    BlockVectorType       &dst,
    const BlockVectorType &src) const
  {
    if (nonlocal_block)
      nonlocal_block->solve(dst.block(nonlocal_model),
                            src.block(nonlocal_model));
    else
      {
        for (const auto i : dst.block(nonlocal_model).locally_owned_elements())
          dst.block(nonlocal_model)(i) =
            src.block(nonlocal_model)(i) / nonlocal_diagonal(i);
        dst.block(nonlocal_model).compress(VectorOperation::insert);
      }

    if (local_block.m() == 0)
      {
        dst.block(local_model) = src.block(local_model);
        return;
      }
    // All local controls on every rank (deal.II gathers the vector).
    Vector<double> local(src.block(local_model));
    local_block.solve(local);
    for (const auto i : dst.block(local_model).locally_owned_elements())
      dst.block(local_model)(i) = local(i);
    dst.block(local_model).compress(VectorOperation::insert);
  }



  template <int dim>
  unsigned int
  ControlPreconditioner<dim>::n_explicit_controls() const
  {
    return local_block.m();
  }

  template <int dim>
  unsigned int
  ControlPreconditioner<dim>::n_coarse_modes() const
  {
    return coarse ? coarse->size() : 0;
  }

  template <int dim>
  types::global_dof_index
  ControlPreconditioner<dim>::n_nonlocal_block_unknowns() const
  {
    return nonlocal_block ? nonlocal_block->n_saddle_point_unknowns() : 0;
  }

  template class ControlPreconditioner<1>;
  template class ControlPreconditioner<2>;
  template class ControlPreconditioner<3>;
} // namespace ltn

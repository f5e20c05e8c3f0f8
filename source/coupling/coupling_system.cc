#include <ltn/coupling/coupling_system.h>

namespace ltn
{
  template <int dim>
  CouplingSystem<dim>::CouplingSystem(const DiscreteModel          &nonlocal,
                                      const DiscreteModel          &local,
                                      const OverlapQuadrature<dim> &overlap,
                                      const double tikhonov_parameter)
    : models{{&nonlocal, &local}}
    , overlap(overlap)
    , alpha(tikhonov_parameter)
  {
    for (const unsigned int k : {0u, 1u})
      {
        const auto &rows =
          (k == nonlocal_model) ? overlap.nonlocal_rows : overlap.local_rows;
        std::vector<types::global_dof_index> columns;
        for (const auto &row : rows)
          for (const auto &entry : row)
            columns.push_back(entry.first);
        std::sort(columns.begin(), columns.end());
        columns.erase(std::unique(columns.begin(), columns.end()),
                      columns.end());
        overlap_columns[k] = models[k]->owned;
        overlap_columns[k].add_indices(columns.begin(), columns.end());
      }
  }



  template <int dim>
  std::vector<double>
  CouplingSystem<dim>::mismatch(const VectorType &u_nonlocal,
                                const VectorType &u_local) const
  {
    std::vector<double> d(overlap.weights.size());
    for (const unsigned int k : {0u, 1u})
      {
        const VectorType &field = (k == nonlocal_model) ? u_nonlocal : u_local;
        if (field.size() == 0)
          continue;
        VectorType ghosted(models[k]->owned,
                           overlap_columns[k],
                           models[k]->communicator);
        ghosted           = field;
        const double sign = (k == nonlocal_model) ? 1. : -1.;
        const auto  &rows =
          (k == nonlocal_model) ? overlap.nonlocal_rows : overlap.local_rows;
        for (std::size_t q = 0; q < d.size(); ++q)
          for (const auto &[i, b] : rows[q])
            d[q] += sign * b * ghosted(i);
      }
    return d;
  }



  template <int dim>
  double
  CouplingSystem<dim>::objective(const VectorType &u_nonlocal,
                                 const VectorType &u_local) const
  {
    const std::vector<double> d = mismatch(u_nonlocal, u_local);
    double                    J = 0;
    for (std::size_t q = 0; q < d.size(); ++q)
      J += 0.5 * overlap.weights[q] * d[q] * d[q];
    return Utilities::MPI::sum(J, communicator());
  }



  template <int dim>
  void
  CouplingSystem<dim>::mismatch_gradient(const std::vector<double> &d,
                                         VectorType &gradient_nonlocal,
                                         VectorType &gradient_local) const
  {
    gradient_nonlocal = mismatch_gradient(nonlocal_model, d);
    gradient_local    = mismatch_gradient(local_model, d);
  }



  template <int dim>
  typename CouplingSystem<dim>::VectorType
  CouplingSystem<dim>::mismatch_gradient(const unsigned int         k,
                                         const std::vector<double> &d) const
  {
    // B = [E, -P]: the local rows enter with a minus sign.
    const double sign = (k == nonlocal_model) ? 1. : -1.;
    return sum_over_rows(k, [&](const std::size_t q, const double b) {
      return sign * b * overlap.weights[q] * d[q];
    });
  }



  template <int dim>
  void
  CouplingSystem<dim>::observe(const VectorType &u_nonlocal,
                               const VectorType &u_local,
                               VectorType       &gradient_nonlocal,
                               VectorType       &gradient_local) const
  {
    mismatch_gradient(mismatch(u_nonlocal, u_local),
                      gradient_nonlocal,
                      gradient_local);
  }



  template <int dim>
  typename CouplingSystem<dim>::VectorType
  CouplingSystem<dim>::observation_diagonal(const unsigned int k) const
  {
    return sum_over_rows(k, [&](const std::size_t q, const double b) {
      return overlap.weights[q] * b * b;
    });
  }



  template <int dim>
  typename CouplingSystem<dim>::VectorType
  CouplingSystem<dim>::sum_over_rows(
    const unsigned int                                k,
    const std::function<double(std::size_t, double)> &contribution) const
  {
    // Contributions go to degrees of freedom other ranks own: accumulate in
    // a writable ghosted vector, then add them up where they are owned.
    VectorType sum;
    sum.reinit(models[k]->owned,
               overlap_columns[k],
               models[k]->communicator,
               true);
    const auto &rows =
      (k == nonlocal_model) ? overlap.nonlocal_rows : overlap.local_rows;
    for (std::size_t q = 0; q < rows.size(); ++q)
      for (const auto &[i, b] : rows[q])
        sum(i) += contribution(q, b);
    sum.compress(VectorOperation::add);
    VectorType owned = models[k]->new_vector();
    owned            = sum;
    return owned;
  }



  template <int dim>
  types::global_dof_index
  CouplingSystem<dim>::n_controls() const
  {
    return models[0]->n_controls() + models[1]->n_controls();
  }



  template <int dim>
  MPI_Comm
  CouplingSystem<dim>::communicator() const
  {
    return models[0]->communicator;
  }

  template class CouplingSystem<1>;
  template class CouplingSystem<2>;
  template class CouplingSystem<3>;
} // namespace ltn

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
    std::array<VectorType, 2> u;
    for (const unsigned int k : {0u, 1u})
      {
        u[k].reinit(models[k]->owned,
                    overlap_columns[k],
                    models[k]->communicator);
        u[k] = (k == nonlocal_model) ? u_nonlocal : u_local;
      }
    std::vector<double> d(overlap.weights.size());
    for (std::size_t q = 0; q < d.size(); ++q)
      {
        for (const auto &[i, e] : overlap.nonlocal_rows[q])
          d[q] += e * u[nonlocal_model](i);
        for (const auto &[j, p] : overlap.local_rows[q])
          d[q] -= p * u[local_model](j);
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
    // Contributions go to degrees of freedom other ranks own: accumulate in
    // writable ghosted vectors, then add them up where they are owned.
    std::array<VectorType, 2> gradient;
    for (const unsigned int k : {0u, 1u})
      gradient[k].reinit(models[k]->owned,
                         overlap_columns[k],
                         models[k]->communicator,
                         true);
    for (std::size_t q = 0; q < d.size(); ++q)
      {
        const double wd = overlap.weights[q] * d[q];
        for (const auto &[i, e] : overlap.nonlocal_rows[q])
          gradient[nonlocal_model](i) += e * wd;
        for (const auto &[j, p] : overlap.local_rows[q])
          gradient[local_model](j) -= p * wd;
      }
    for (const unsigned int k : {0u, 1u})
      gradient[k].compress(VectorOperation::add);
    gradient_nonlocal = models[nonlocal_model]->new_vector();
    gradient_local    = models[local_model]->new_vector();
    gradient_nonlocal = gradient[nonlocal_model];
    gradient_local    = gradient[local_model];
  }



  template <int dim>
  typename CouplingSystem<dim>::VectorType
  CouplingSystem<dim>::observation_diagonal(const unsigned int k) const
  {
    VectorType diagonal;
    diagonal.reinit(models[k]->owned,
                    overlap_columns[k],
                    models[k]->communicator,
                    true);
    const auto &rows =
      (k == nonlocal_model) ? overlap.nonlocal_rows : overlap.local_rows;
    for (std::size_t q = 0; q < rows.size(); ++q)
      for (const auto &[i, b] : rows[q])
        diagonal(i) += overlap.weights[q] * b * b;
    diagonal.compress(VectorOperation::add);
    VectorType owned = models[k]->new_vector();
    owned            = diagonal;
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

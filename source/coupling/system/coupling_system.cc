#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ltn/coupling/system/coupling_system.h>

#include <map>

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

    points = Utilities::MPI::create_ascending_partitioning(
      communicator(),
      overlap.weights.size())[Utilities::MPI::this_mpi_process(communicator())];
    const auto first = points.is_empty() ? 0 : *points.begin();
    for (const unsigned int k : {0u, 1u})
      {
        const auto &rows =
          (k == nonlocal_model) ? overlap.nonlocal_rows : overlap.local_rows;
        DynamicSparsityPattern dsp(points.size(),
                                   models[k]->owned.size(),
                                   points);
        for (std::size_t q = 0; q < rows.size(); ++q)
          for (const auto &entry : rows[q])
            dsp.add(first + q, entry.first);
        observation[k].reinit(points, models[k]->owned, dsp, communicator());
        for (std::size_t q = 0; q < rows.size(); ++q)
          for (const auto &[i, b] : rows[q])
            observation[k].add(first + q, i, b);
        observation[k].compress(VectorOperation::add);
      }
  }



  template <int dim>
  std::vector<double>
  CouplingSystem<dim>::mismatch(const VectorType &u_nonlocal,
                                const VectorType &u_local) const
  {
    VectorType observed(points, communicator());
    VectorType d(points, communicator());
    for (const unsigned int k : {0u, 1u})
      {
        const VectorType &field = (k == nonlocal_model) ? u_nonlocal : u_local;
        if (field.size() == 0)
          continue;
        observation[k].vmult(observed, field);
        d.add((k == nonlocal_model) ? 1. : -1., observed);
      }
    return std::vector<double>(d.begin(), d.end());
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
    VectorType   weighted(points, communicator());
    for (std::size_t q = 0; q < d.size(); ++q)
      weighted.begin()[q] = sign * overlap.weights[q] * d[q];
    VectorType gradient = models[k]->new_vector();
    observation[k].Tvmult(gradient, weighted);
    return gradient;
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
  TrilinosWrappers::SparseMatrix
  CouplingSystem<dim>::observation_gram(const unsigned int k) const
  {
    using index = types::global_dof_index;
    // sum_q w_q b_q b_q^T over this rank's points. The rows of the points in
    // one cell share their columns (per component), so each set of columns
    // sums its rank-one terms in a dense block first; the blocks then go to
    // the matrix a row at a time. The signs of B_k cancel.
    const auto &rows =
      (k == nonlocal_model) ? overlap.nonlocal_rows : overlap.local_rows;
    std::map<std::vector<index>, std::vector<double>> blocks;
    std::vector<index>                                columns;
    for (std::size_t q = 0; q < rows.size(); ++q)
      {
        columns.clear();
        for (const auto &entry : rows[q])
          columns.push_back(entry.first);
        const std::size_t    n = columns.size();
        std::vector<double> &block =
          blocks.try_emplace(columns, n * n, 0.).first->second;
        for (std::size_t a = 0; a < n; ++a)
          {
            const double wb = overlap.weights[q] * rows[q][a].second;
            for (std::size_t c = 0; c < n; ++c)
              block[a * n + c] += wb * rows[q][c].second;
          }
      }

    const IndexSet                   &owned = models[k]->owned;
    TrilinosWrappers::SparsityPattern sparsity(owned,
                                               owned,
                                               overlap_columns[k],
                                               communicator());
    for (const auto &[block_columns, block] : blocks)
      for (const index i : block_columns)
        sparsity.add_entries(i, block_columns.begin(), block_columns.end());
    sparsity.compress();
    TrilinosWrappers::SparseMatrix gram(sparsity);
    for (const auto &[block_columns, block] : blocks)
      {
        const std::size_t n = block_columns.size();
        for (std::size_t a = 0; a < n; ++a)
          gram.add(block_columns[a],
                   n,
                   block_columns.data(),
                   block.data() + a * n);
      }
    gram.compress(VectorOperation::add);
    return gram;
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

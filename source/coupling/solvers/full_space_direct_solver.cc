#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ltn/base/direct_solver.h>
#include <ltn/base/matrix_rows.h>
#include <ltn/coupling/solvers/full_space_direct_solver.h>

#include <array>
#include <memory>

namespace ltn
{
  namespace
  {
    /**
     * Visit every entry `(row, column, value)` of the optimality matrix that
     * this rank contributes (some in rows other ranks own), and every entry
     * `(row, value)` of its right-hand side, in the numbering
     * `[u_n | u_l | mu_n | mu_l]`.
     */
    template <int dim, typename MatrixEntry, typename RhsEntry>
    void
    for_each_entry(const CouplingSystem<dim>                    &system,
                   const std::array<types::global_dof_index, 2> &x_offset,
                   const std::array<types::global_dof_index, 2> &mu_offset,
                   const MatrixEntry                            &matrix_entry,
                   const RhsEntry                               &rhs_entry)
    {
      using index         = types::global_dof_index;
      const auto &overlap = system.overlap;

      // B^T W B, one overlap point at a time.
      std::vector<std::pair<index, double>> b_row;
      for (std::size_t q = 0; q < overlap.weights.size(); ++q)
        {
          b_row.clear();
          for (const auto &[i, e] : overlap.nonlocal_rows[q])
            b_row.emplace_back(x_offset[nonlocal_model] + i, e);
          for (const auto &[j, p] : overlap.local_rows[q])
            b_row.emplace_back(x_offset[local_model] + j, -p);
          for (const auto &a : b_row)
            for (const auto &c : b_row)
              matrix_entry(a.first,
                           c.first,
                           overlap.weights[q] * a.second * c.second);
        }

      for (const unsigned int k : {0u, 1u})
        {
          const DiscreteModel &model = *system.models[k];
          for (const index i : model.controls)
            {
              matrix_entry(x_offset[k] + i, x_offset[k] + i, system.alpha);
              matrix_entry(mu_offset[k] + i, mu_offset[k] + i, 1.);
            }
          for (const index i : model.owned)
            if (!model.controls.is_element(i))
              {
                for_each_in_row(
                  model.matrix, i, [&](const index column, const double value) {
                    matrix_entry(mu_offset[k] + i, x_offset[k] + column, value);
                    matrix_entry(x_offset[k] + column, mu_offset[k] + i, value);
                  });
                rhs_entry(mu_offset[k] + i, model.rhs(i));
              }
        }
    }
  } // namespace



  template <int dim>
  void
  assemble_full_space_system(const CouplingSystem<dim>      &system,
                             TrilinosWrappers::SparseMatrix &K,
                             TrilinosWrappers::MPI::Vector  &b)
  {
    using index                    = types::global_dof_index;
    const DiscreteModel       &n_m = *system.models[nonlocal_model];
    const DiscreteModel       &l_m = *system.models[local_model];
    const index                N_n = n_m.owned.size(), N_l = l_m.owned.size();
    const std::array<index, 2> x_offset  = {{0, N_n}};
    const std::array<index, 2> mu_offset = {{N_n + N_l, 2 * N_n + N_l}};
    const index                n         = 2 * (N_n + N_l);
    const MPI_Comm             comm      = system.communicator();

    IndexSet owned(n), writable(n);
    for (const unsigned int k : {0u, 1u})
      {
        const DiscreteModel &model = *system.models[k];
        owned.add_indices(model.owned, x_offset[k]);
        owned.add_indices(model.owned, mu_offset[k]);
        writable.add_indices(model.owned, mu_offset[k]);
        writable.add_indices(system.overlap_columns[k], x_offset[k]);
        // The rows of C^T are the columns of the owned rows of M: with
        // condensed hanging nodes these can reach beyond the ghost layer.
        std::vector<index> columns;
        for (const index i : model.owned)
          for_each_in_row(model.matrix, i, [&](const index column, double) {
            columns.push_back(x_offset[k] + column);
          });
        std::sort(columns.begin(), columns.end());
        columns.erase(std::unique(columns.begin(), columns.end()),
                      columns.end());
        writable.add_indices(columns.begin(), columns.end());
      }

    TrilinosWrappers::SparsityPattern sparsity(owned, owned, writable, comm);
    for_each_entry(
      system,
      x_offset,
      mu_offset,
      [&](const index row, const index column, double) {
        sparsity.add(row, column);
      },
      [](index, double) {});
    sparsity.compress();

    K.reinit(sparsity);
    b.reinit(owned, comm);
    for_each_entry(
      system,
      x_offset,
      mu_offset,
      [&](const index row, const index column, const double value) {
        K.add(row, column, value);
      },
      [&](const index row, const double value) { b(row) = value; });
    K.compress(VectorOperation::add);
    b.compress(VectorOperation::insert);
  }



  template <int dim>
  CouplingSolution
  solve_full_space_direct(const CouplingSystem<dim> &system)
  {
    using index = types::global_dof_index;
    TrilinosWrappers::SparseMatrix K;
    TrilinosWrappers::MPI::Vector  b;
    assemble_full_space_system(system, K, b);
    const IndexSet &owned = b.locally_owned_elements();
    const MPI_Comm  comm  = system.communicator();
    const index     N_n   = system.models[nonlocal_model]->owned.size();
    const std::array<index, 2> x_offset = {{0, N_n}};

    // MUMPS's default pivot threshold 0.01 keeps the factors sparse (the
    // 3D LPS system: 42 s against 120 s at 0.5), but on some saddle-point
    // systems (1D at eps/h = 1.5 and 2) it leaves relative residuals of
    // 1e-3 to 25 that iterative refinement cannot repair; 0.5 solves those
    // to round-off; on others MUMPS finds a pivot below 0.01 too small and
    // stops (1D at eps/h = 1.5 on an AMD EPYC's OpenBLAS). Take the first
    // that reaches 1e-11.
    const double                  b_norm = std::max(b.l2_norm(), 1e-300);
    TrilinosWrappers::MPI::Vector z(owned, comm), residual(owned, comm),
      correction(owned, comm);
    double                      relative_residual = 0;
    unsigned int                refinements       = 0;
    const std::array<double, 2> pivot_thresholds  = {{0.01, 0.5}};
    for (const double pivot_threshold : pivot_thresholds)
      {
        std::unique_ptr<const DirectSolver> factored;
        try
          {
            factored = std::make_unique<const DirectSolver>(K, pivot_threshold);
          }
        catch (const SingularFactorization &)
          {
            if (pivot_threshold == pivot_thresholds.back())
              throw;
            continue;
          }
        const DirectSolver &direct = *factored;
        direct.solve(z, b);
        relative_residual = K.residual(residual, z, b) / b_norm;
        refinements       = 0;
        while (relative_residual > 1e-14 && refinements < 5)
          {
            direct.solve(correction, residual);
            z += correction;
            const double next = K.residual(residual, z, b) / b_norm;
            ++refinements;
            if (next >= relative_residual)
              break;
            relative_residual = next;
          }
        if (relative_residual <= 1e-11)
          break;
      }
    if (!(relative_residual <= 1e-8))
      throw std::runtime_error(
        "the full-space optimality system could not be solved accurately "
        "(relative residual " +
        std::to_string(relative_residual) +
        " after iterative refinement): it is singular or nearly so. Check "
        "that the overlap observes the controls: a wider overlap or a finer "
        "particle lattice helps.");

    CouplingSolution solution;
    solution.iterations = 1 + refinements;
    solution.residual   = relative_residual;
    for (const unsigned int k : {0u, 1u})
      {
        const DiscreteModel &model = *system.models[k];
        solution.fields[k]         = model.new_vector();
        for (const index i : model.owned)
          solution.fields[k](i) = z(x_offset[k] + i);
        solution.fields[k].compress(VectorOperation::insert);
      }
    return solution;
  }

  template void
  assemble_full_space_system(const CouplingSystem<1> &,
                             TrilinosWrappers::SparseMatrix &,
                             TrilinosWrappers::MPI::Vector &);
  template void
  assemble_full_space_system(const CouplingSystem<2> &,
                             TrilinosWrappers::SparseMatrix &,
                             TrilinosWrappers::MPI::Vector &);
  template void
  assemble_full_space_system(const CouplingSystem<3> &,
                             TrilinosWrappers::SparseMatrix &,
                             TrilinosWrappers::MPI::Vector &);
  template CouplingSolution
  solve_full_space_direct(const CouplingSystem<1> &);
  template CouplingSolution
  solve_full_space_direct(const CouplingSystem<2> &);
  template CouplingSolution
  solve_full_space_direct(const CouplingSystem<3> &);
} // namespace ltn

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ltn/nonlocal/lattice_rows.h>

namespace ltn
{
  void
  assemble_rows(
    const IndexSet    &particles,
    const unsigned int n_components,
    const std::function<void(types::global_dof_index, ParticleRows &)> &rows_of,
    const std::function<unsigned int(types::global_dof_index)> &stored_rows_of,
    const std::vector<unsigned int>                            &row_groups,
    const bool                                           only_stored_rows,
    const IndexSet                                      &owned_dofs,
    const MPI_Comm                                       communicator,
    const std::vector<TrilinosWrappers::SparseMatrix *> &matrices,
    IndexSet                                            &relevant)
  {
    AssertDimension(row_groups.size(), matrices.size());
    const auto n_dofs = owned_dofs.size();
    // The group of each component's rows.
    std::vector<unsigned int> group(n_components, 0);
    for (unsigned int g = 0; g < row_groups.size(); ++g)
      for (unsigned int c = 0; c < n_components; ++c)
        if ((row_groups[g] >> c) & 1u)
          group[c] = g;
    // Each matrix's rows: all owned ones, or only those it stores.
    std::vector<IndexSet> row_sets(matrices.size(), owned_dofs);
    if (only_stored_rows)
      {
        for (auto &rows : row_sets)
          rows = IndexSet(n_dofs);
        for (const auto p : particles)
          {
            const unsigned int stored = stored_rows_of(p);
            for (unsigned int c = 0; c < n_components; ++c)
              if ((stored >> c) & 1u)
                row_sets[group[c]].add_index(n_components * p + c);
          }
        for (auto &rows : row_sets)
          rows.compress();
      }
    // One pass for the pattern of the owned rows and the ghosts they reach,
    // one for the values: the rows are cheaper to rebuild than to keep.
    std::vector<DynamicSparsityPattern> dsp(matrices.size());
    for (unsigned int g = 0; g < matrices.size(); ++g)
      dsp[g].reinit(n_dofs, n_dofs, row_sets[g]);
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    ParticleRows                         rows(n_components);
    // Visit each stored row (its matrix, its index, its entries).
    const auto for_each_stored_row = [&](const auto &visit) {
      for (const auto p : particles)
        {
          rows_of(p, rows);
          const unsigned int stored = stored_rows_of(p);
          for (unsigned int c = 0; c < n_components; ++c)
            if ((stored >> c) & 1u)
              visit(group[c], n_components * p + c, rows[c]);
        }
    };
    relevant = owned_dofs;
    for_each_stored_row([&](const unsigned int            g,
                            const types::global_dof_index row,
                            auto                         &entries) {
      columns.clear();
      for (const auto &entry : entries)
        columns.push_back(entry.first);
      std::sort(columns.begin(), columns.end());
      dsp[g].add_entries(row, columns.begin(), columns.end(), true);
      relevant.add_indices(columns.begin(), columns.end());
    });
    relevant.compress();
    for (unsigned int g = 0; g < matrices.size(); ++g)
      matrices[g]->reinit(row_sets[g], owned_dofs, dsp[g], communicator);
    dsp.clear();
    for_each_stored_row([&](const unsigned int            g,
                            const types::global_dof_index row,
                            auto                         &entries) {
      columns.clear();
      values.clear();
      for (const auto &[column, value] : entries)
        {
          columns.push_back(column);
          values.push_back(value);
        }
      matrices[g]->set(row, columns.size(), columns.data(), values.data());
    });
    for (TrilinosWrappers::SparseMatrix *matrix : matrices)
      matrix->compress(VectorOperation::insert);
  }
} // namespace ltn

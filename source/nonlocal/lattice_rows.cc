#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ltn/nonlocal/lattice_rows.h>

namespace ltn
{
  void
  assemble_rows(
    const IndexSet    &owned_particles,
    const unsigned int n_components,
    const std::function<void(types::global_dof_index, ParticleRows &)> &rows_of,
    DiscreteModel                                                      &model)
  {
    const auto n_dofs = model.owned.size();
    // One pass for the pattern of the owned rows and the ghosts they reach,
    // one for the values: the rows are cheaper to rebuild than to keep.
    DynamicSparsityPattern               dsp(n_dofs, n_dofs, model.owned);
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    ParticleRows                         rows(n_components);
    model.relevant = model.owned;
    for (const auto p : owned_particles)
      {
        rows_of(p, rows);
        for (unsigned int c = 0; c < n_components; ++c)
          {
            columns.clear();
            for (const auto &entry : rows[c])
              columns.push_back(entry.first);
            std::sort(columns.begin(), columns.end());
            dsp.add_entries(n_components * p + c,
                            columns.begin(),
                            columns.end(),
                            true);
            model.relevant.add_indices(columns.begin(), columns.end());
          }
      }
    model.relevant.compress();
    model.matrix.reinit(model.owned, model.owned, dsp, model.communicator);
    for (const auto p : owned_particles)
      {
        rows_of(p, rows);
        for (unsigned int c = 0; c < n_components; ++c)
          {
            columns.clear();
            values.clear();
            for (const auto &[column, value] : rows[c])
              {
                columns.push_back(column);
                values.push_back(value);
              }
            model.matrix.set(n_components * p + c,
                             columns.size(),
                             columns.data(),
                             values.data());
          }
      }
    model.matrix.compress(VectorOperation::insert);
  }
} // namespace ltn

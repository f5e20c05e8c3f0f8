#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <ltn/coupling/solvers/blended_system.h>
#include <ltn/coupling/solvers/energy_blending_solver.h>

namespace ltn
{
  template <int dim>
  CouplingSolution
  solve_energy_blending(const CouplingSystem<dim> &system)
  {
    const auto &nodes = system.overlap.blending_nodes;
    AssertThrow(dim == 1 && !nodes.beta.empty() && nodes.energy[0] &&
                  nodes.energy[1],
                ExcMessage("energy blending needs the blending nodes and the "
                           "weighted forms of a 1D coupling"));
    const unsigned int n = nodes.beta.size();

    // The value of each node that a closed model fixes.
    std::vector<bool> fixed(n, false);
    Vector<double>    fixed_value(n);
    for (const unsigned int k : {nonlocal_model, local_model})
      for (const auto i : system.models[k]->fixed)
        {
          const auto node   = nodes.node_of_dof[k][i];
          fixed[node]       = true;
          fixed_value[node] = system.models[k]->rhs(i);
        }

    const auto for_each_free_entry = [&](const auto &action) {
      for (const unsigned int k : {nonlocal_model, local_model})
        {
          const auto &matrix = nodes.energy[k]->matrix;
          for (unsigned int i = 0; i < matrix.m(); ++i)
            if (!fixed[nodes.node_of_dof[k][i]])
              for (auto entry = matrix.begin(i); entry != matrix.end(i);
                   ++entry)
                action(nodes.node_of_dof[k][i],
                       nodes.node_of_dof[k][entry->column()],
                       entry->value());
        }
    };

    DynamicSparsityPattern pattern(n, n);
    for (unsigned int node = 0; node < n; ++node)
      pattern.add(node, node);
    for_each_free_entry(
      [&](const unsigned int row, const unsigned int column, double) {
        if (!fixed[column])
          pattern.add(row, column);
      });
    SparsityPattern sparsity;
    sparsity.copy_from(pattern);
    SparseMatrix<double> blended(sparsity);
    Vector<double>       load(n);
    // A fixed column's entries move to the load: the matrix stays symmetric.
    for_each_free_entry([&](const unsigned int row,
                            const unsigned int column,
                            const double       value) {
      if (fixed[column])
        load(row) -= value * fixed_value[column];
      else
        blended.add(row, column, value);
    });
    for (const unsigned int k : {nonlocal_model, local_model})
      for (unsigned int i = 0; i < nodes.energy[k]->load.size(); ++i)
        if (!fixed[nodes.node_of_dof[k][i]])
          load(nodes.node_of_dof[k][i]) += nodes.energy[k]->load(i);
    for (unsigned int node = 0; node < n; ++node)
      if (fixed[node])
        {
          blended.set(node, node, 1.);
          load(node) = fixed_value[node];
        }
    return solve_blended_system(system, blended, load);
  }

#define LTN_INSTANTIATE(dim) \
  template CouplingSolution solve_energy_blending(const CouplingSystem<dim> &);
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

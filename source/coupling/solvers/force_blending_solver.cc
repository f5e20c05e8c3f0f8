#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <ltn/coupling/solvers/blended_system.h>
#include <ltn/coupling/solvers/force_blending_solver.h>

namespace ltn
{
  template <int dim>
  CouplingSolution
  solve_force_blending(const CouplingSystem<dim> &system)
  {
    const auto &nodes = system.overlap.blending_nodes;
    AssertThrow(dim == 1 && !nodes.beta.empty(),
                ExcMessage("force blending needs the blending nodes of a 1D "
                           "coupling (add_blending_nodes())"));
    const unsigned int n = nodes.beta.size();
    // The weight of model k's rows at a node: beta for the nonlocal model,
    // 1 - beta for the local one.
    const auto weight = [&](const unsigned int k, const unsigned int node) {
      return k == nonlocal_model ? nodes.beta[node] : 1. - nodes.beta[node];
    };
    const auto for_each_weighted_row = [&](const auto &action) {
      for (const unsigned int k : {nonlocal_model, local_model})
        {
          const auto &matrix = system.models[k]->matrix;
          for (unsigned int i = 0; i < matrix.m(); ++i)
            {
              const unsigned int node = nodes.node_of_dof[k][i];
              const double       w    = weight(k, node);
              if (w != 0)
                action(k, i, node, w, matrix);
            }
        }
    };

    DynamicSparsityPattern pattern(n, n);
    for_each_weighted_row([&](const unsigned int k,
                              const unsigned int i,
                              const unsigned int node,
                              double,
                              const TrilinosWrappers::SparseMatrix &matrix) {
      for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
        pattern.add(node, nodes.node_of_dof[k][entry->column()]);
    });
    SparsityPattern sparsity;
    sparsity.copy_from(pattern);
    SparseMatrix<double> blended(sparsity);
    Vector<double>       load(n);
    for_each_weighted_row([&](const unsigned int                    k,
                              const unsigned int                    i,
                              const unsigned int                    node,
                              const double                          w,
                              const TrilinosWrappers::SparseMatrix &matrix) {
      for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
        blended.add(node,
                    nodes.node_of_dof[k][entry->column()],
                    w * entry->value());
      load(node) += w * system.models[k]->rhs(i);
    });

    return solve_blended_system(system, blended, load);
  }

#define LTN_INSTANTIATE(dim) \
  template CouplingSolution solve_force_blending(const CouplingSystem<dim> &);
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

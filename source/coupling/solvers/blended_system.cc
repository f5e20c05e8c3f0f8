#include <deal.II/lac/sparse_direct.h>

#include <ltn/coupling/solvers/blended_system.h>

#include <cmath>

namespace ltn
{
  template <int dim>
  CouplingSolution
  solve_blended_system(const CouplingSystem<dim>  &system,
                       const SparseMatrix<double> &matrix,
                       const Vector<double>       &load)
  {
    const auto         &nodes = system.overlap.blending_nodes;
    const unsigned int  n     = load.size();
    CouplingSolution    solution;
    SparseDirectUMFPACK lu;
    lu.initialize(matrix);
    Vector<double> field(load);
    lu.solve(field);
    Vector<double> residual(n);
    matrix.vmult(residual, field);
    residual -= load;
    solution.iterations = 1;
    solution.residual   = residual.l2_norm() / load.l2_norm();

    double squared = 0, asymmetric = 0;
    for (unsigned int i = 0; i < n; ++i)
      for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
        {
          const double transposed = matrix.el(entry->column(), i);
          squared += entry->value() * entry->value();
          asymmetric +=
            (entry->value() - transposed) * (entry->value() - transposed);
        }
    solution.asymmetry = std::sqrt(asymmetric / squared);

    for (const unsigned int k : {nonlocal_model, local_model})
      {
        solution.fields[k] = system.models[k]->new_vector();
        for (unsigned int i = 0; i < solution.fields[k].size(); ++i)
          solution.fields[k](i) = field(nodes.node_of_dof[k][i]);
        solution.fields[k].compress(VectorOperation::insert);
      }
    return solution;
  }

#define LTN_INSTANTIATE(dim)                                                   \
  template CouplingSolution solve_blended_system(const CouplingSystem<dim> &,  \
                                                 const SparseMatrix<double> &, \
                                                 const Vector<double> &);
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ltn/base/matrix_rows.h>
#include <ltn/coupling/model_direct_solver.h>

namespace ltn
{
  namespace
  {
    using index = types::global_dof_index;

    /** `v` with its entries outside @p kept (owned ones) set to zero. */
    TrilinosWrappers::MPI::Vector
    restricted_to(const TrilinosWrappers::MPI::Vector &v, const IndexSet &kept)
    {
      TrilinosWrappers::MPI::Vector restricted(v.locally_owned_elements(),
                                               v.get_mpi_communicator());
      for (const index i : kept)
        restricted(i) = static_cast<double>(v(i));
      restricted.compress(VectorOperation::insert);
      return restricted;
    }

    /**
     * `blockdiag(M_FF, I)`: the free rows of @p model's matrix without their
     * entries in the columns of @p outside, and identity rows there.
     */
    TrilinosWrappers::SparseMatrix
    free_block_matrix(const DiscreteModel &model, const IndexSet &outside)
    {
      // Which columns the owned rows reach are free, ghosts included.
      TrilinosWrappers::MPI::Vector owned_flags(model.owned,
                                                model.communicator);
      for (const index i : model.owned)
        owned_flags(i) = outside.is_element(i) ? 0. : 1.;
      owned_flags.compress(VectorOperation::insert);
      TrilinosWrappers::MPI::Vector free(model.owned,
                                         model.relevant,
                                         model.communicator);
      free = owned_flags;

      std::vector<index>  columns;
      std::vector<double> values;
      const auto          row = [&](const index i) {
        columns.clear();
        values.clear();
        if (outside.is_element(i))
          {
            columns.push_back(i);
            values.push_back(1.);
            return;
          }
        for_each_in_row(model.matrix, i, [&](const index j, const double a) {
          if (free(j) != 0.)
            {
              columns.push_back(j);
              values.push_back(a);
            }
        });
      };

      TrilinosWrappers::SparsityPattern pattern(model.owned,
                                                model.owned,
                                                model.communicator);
      for (const index i : model.owned)
        {
          row(i);
          pattern.add_entries(i, columns.begin(), columns.end());
        }
      pattern.compress();
      TrilinosWrappers::SparseMatrix matrix;
      matrix.reinit(pattern);
      for (const index i : model.owned)
        {
          row(i);
          matrix.set(i, columns, values);
        }
      matrix.compress(VectorOperation::insert);
      return matrix;
    }
  } // namespace



  ModelDirectSolver::ModelDirectSolver(const DiscreteModel &model)
    : model(model)
    , outside(model.controls)
    // The same choice on every rank: one MUMPS instance factorizes for all.
    , free_block_only(model.symmetric_free_block &&
                      Utilities::MPI::max(model.eliminated.n_elements() +
                                            model.constrained.n_elements(),
                                          model.communicator) == 0)
  {
    AssertThrow(!model.matrix_free,
                ExcMessage("a direct solver needs the assembled matrix"));
    outside.add_indices(model.fixed);
    const DirectSolver::Ordering ordering =
      model.mesh_couplings ? DirectSolver::Ordering::nested_dissection :
                             DirectSolver::Ordering::minimum_degree;
    // The free block's matrix goes once it is factorized.
    direct = free_block_only ?
               std::make_unique<DirectSolver>(
                 free_block_matrix(model, outside),
                 0.5,
                 DirectSolver::Symmetry::positive_definite,
                 ordering) :
               std::make_unique<DirectSolver>(model.matrix,
                                              0.5,
                                              DirectSolver::Symmetry::general,
                                              ordering);
  }



  bool
  ModelDirectSolver::factorizes_free_block() const
  {
    return free_block_only;
  }



  TrilinosWrappers::MPI::Vector
  ModelDirectSolver::free_block_rhs(
    const TrilinosWrappers::MPI::Vector &b) const
  {
    const TrilinosWrappers::MPI::Vector t = restricted_to(b, outside);
    TrilinosWrappers::MPI::Vector       rhs(b), product(b);
    model.matrix.vmult(product, t);
    rhs -= product;
    rhs += t;
    return rhs;
  }



  void
  ModelDirectSolver::complete_transposed(TrilinosWrappers::MPI::Vector &y) const
  {
    TrilinosWrappers::MPI::Vector y_free(y);
    y_free -= restricted_to(y, outside);
    TrilinosWrappers::MPI::Vector product(y);
    model.matrix.Tvmult(product, y_free);
    for (const index i : outside)
      {
        const double value = y(i);
        y(i)               = value - product(i);
      }
    y.compress(VectorOperation::insert);
  }



  void
  ModelDirectSolver::solve(TrilinosWrappers::MPI::Vector       &x,
                           const TrilinosWrappers::MPI::Vector &b,
                           const bool                           transpose) const
  {
    if (!free_block_only)
      {
        if (transpose)
          direct->solve_transposed(x, b);
        else
          direct->solve(x, b);
        return;
      }
    if (transpose)
      {
        direct->solve(x, b);
        complete_transposed(x);
      }
    else
      direct->solve(x, free_block_rhs(b));
  }



  void
  ModelDirectSolver::solve(std::vector<TrilinosWrappers::MPI::Vector>       &x,
                           const std::vector<TrilinosWrappers::MPI::Vector> &b,
                           const bool transpose) const
  {
    if (!free_block_only)
      {
        direct->solve(x, b, transpose);
        return;
      }
    if (transpose)
      {
        direct->solve(x, b, false);
        for (auto &y : x)
          complete_transposed(y);
        return;
      }
    std::vector<TrilinosWrappers::MPI::Vector> rhs;
    rhs.reserve(b.size());
    for (const auto &column : b)
      rhs.push_back(free_block_rhs(column));
    direct->solve(x, rhs, false);
  }
} // namespace ltn

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <ltn/model_solvers/model_direct_solver.h>

#include <Epetra_Import.h>
#include <Epetra_MultiVector.h>
#include <Epetra_Vector.h>

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

    /** What a degree of freedom is to the free block's solves. */
    enum Role : unsigned char
    {
      free_role        = 1,
      constrained_role = 2,
      outside_role     = 4
    };

    /**
     * The role of each column of @p model's matrix (its Epetra column map,
     * local numbers), owned by this rank or another: imported once, as
     * Epetra's products import their vectors' entries.
     */
    std::vector<unsigned char>
    column_roles(const DiscreteModel &model, const IndexSet &outside)
    {
      const Epetra_CrsMatrix &matrix = model.matrix.trilinos_matrix();
      Epetra_Vector           owned(matrix.RowMap());
      for (const index i : model.owned)
        owned[matrix.RowMap().LID(
          static_cast<TrilinosWrappers::types::int_type>(i))] =
          outside.is_element(i)           ? outside_role :
          model.constrained.is_element(i) ? constrained_role :
                                            free_role;
      Epetra_Vector       columns(matrix.ColMap());
      const Epetra_Import import(matrix.ColMap(), matrix.RowMap());
      AssertThrow(columns.Import(owned, import, Insert) == 0,
                  ExcMessage("importing the columns' roles failed"));
      std::vector<unsigned char> roles(columns.MyLength());
      for (int c = 0; c < columns.MyLength(); ++c)
        roles[c] = static_cast<unsigned char>(columns[c]);
      return roles;
    }

    /**
     * The entries of @p model's matrix in the owned rows of @p rows and the
     * columns whose role (column_roles()) is in the bits of @p kept_columns
     * into @p matrix; with @p identity_elsewhere the other rows are
     * identity rows, else empty.
     */
    void
    entries_of(const DiscreteModel              &model,
               const IndexSet                   &rows,
               const std::vector<unsigned char> &roles,
               const unsigned int                kept_columns,
               const bool                        identity_elsewhere,
               TrilinosWrappers::SparseMatrix   &matrix)
    {
      const Epetra_CrsMatrix &epetra = model.matrix.trilinos_matrix();
      std::vector<index>      columns;
      std::vector<double>     values;
      const auto              row = [&](const index i) {
        columns.clear();
        values.clear();
        if (!rows.is_element(i))
          {
            if (identity_elsewhere)
              {
                columns.push_back(i);
                values.push_back(1.);
              }
            return;
          }
        int     n            = 0;
        double *row_values   = nullptr;
        int    *local_column = nullptr;
        epetra.ExtractMyRowView(
          epetra.RowMap().LID(
            static_cast<TrilinosWrappers::types::int_type>(i)),
          n,
          row_values,
          local_column);
        for (int k = 0; k < n; ++k)
          if (roles[local_column[k]] & kept_columns)
            {
              columns.push_back(epetra.ColMap().GID(local_column[k]));
              values.push_back(row_values[k]);
            }
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
      matrix.reinit(pattern);
      for (const index i : model.owned)
        {
          row(i);
          if (!columns.empty())
            matrix.set(i, columns, values);
        }
      matrix.compress(VectorOperation::insert);
    }
  } // namespace



  ModelDirectSolver::ModelDirectSolver(const DiscreteModel &model)
    : model(model)
    , outside(model.controls)
    // The same choice on every rank: one MUMPS instance factorizes for all.
    , free_block_only(model.symmetric_free_block &&
                      Utilities::MPI::max(model.eliminated.n_elements(),
                                          model.communicator) == 0)
    , any_constrained(Utilities::MPI::max(model.constrained.n_elements(),
                                          model.communicator) > 0)
  {
    AssertThrow(!model.matrix_free,
                ExcMessage("a direct solver needs the assembled matrix"));
    outside.add_indices(model.fixed);
    const DirectSolver::Ordering ordering =
      model.mesh_couplings ? DirectSolver::Ordering::nested_dissection :
                             DirectSolver::Ordering::minimum_degree;
    if (!free_block_only)
      {
        direct = std::make_unique<DirectSolver>(model.matrix,
                                                0.5,
                                                DirectSolver::Symmetry::general,
                                                ordering);
        return;
      }

    const std::vector<unsigned char> roles = column_roles(model, outside);
    // The solves rely on the condensed columns: entries in the columns C
    // only on their diagonal, 1.
    const Epetra_CrsMatrix &epetra = model.matrix.trilinos_matrix();
    for (int i = 0; any_constrained && i < epetra.NumMyRows(); ++i)
      {
        int     n       = 0;
        double *values  = nullptr;
        int    *columns = nullptr;
        epetra.ExtractMyRowView(i, n, values, columns);
        for (int k = 0; k < n; ++k)
          if (roles[columns[k]] == constrained_role)
            {
              const bool diagonal =
                epetra.ColMap().GID(columns[k]) == epetra.RowMap().GID(i);
              AssertThrow(values[k] == (diagonal ? 1. : 0.),
                          ExcMessage(
                            "a hanging node's column holds entries off its "
                            "diagonal: the assembly did not condense it, and "
                            "its free block cannot be factorized alone"));
            }
      }

    // F: the owned rows that are neither outside nor constrained.
    free = model.owned;
    free.subtract_set(outside);
    free.subtract_set(model.constrained);
    IndexSet not_outside = model.owned;
    not_outside.subtract_set(outside);
    entries_of(model, not_outside, roles, outside_role, false, to_outside);
    entries_of(model,
               model.constrained,
               roles,
               free_role | outside_role,
               false,
               constraints);
    // The free block's matrix goes once it is factorized.
    TrilinosWrappers::SparseMatrix free_block;
    entries_of(model, free, roles, free_role, true, free_block);
    direct = std::make_unique<DirectSolver>(
      free_block, 0.5, DirectSolver::Symmetry::positive_definite, ordering);
  }



  bool
  ModelDirectSolver::factorizes_free_block() const
  {
    return free_block_only;
  }



  TrilinosWrappers::MPI::Vector
  ModelDirectSolver::free_block_transposed_rhs(
    const TrilinosWrappers::MPI::Vector &g) const
  {
    if (!any_constrained)
      return g;
    // constraints' rows are C: g_C alone enters.
    TrilinosWrappers::MPI::Vector product(g);
    constraints.Tvmult(product, g);
    TrilinosWrappers::MPI::Vector rhs(g);
    rhs -= restricted_to(product, free);
    return rhs;
  }



  void
  ModelDirectSolver::complete_transposed(TrilinosWrappers::MPI::Vector &y) const
  {
    // to_outside has no rows O: y_O does not enter.
    TrilinosWrappers::MPI::Vector product(y);
    to_outside.Tvmult(product, y);
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
        direct->solve(x, free_block_transposed_rhs(b));
        complete_transposed(x);
      }
    else
      {
        // One column of the many-column solve, which forms the free
        // block's right-hand side and completes the constrained rows.
        std::vector<TrilinosWrappers::MPI::Vector> solution;
        solve(solution, {b}, false);
        x = solution.front();
      }
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
        std::vector<TrilinosWrappers::MPI::Vector> rhs;
        rhs.reserve(b.size());
        for (const auto &column : b)
          rhs.push_back(free_block_transposed_rhs(column));
        direct->solve(x, rhs, false);
        for (auto &column : x)
          complete_transposed(column);
        return;
      }

    x.resize(b.size());
    if (b.empty())
      return;
    // The products before and after the solve, M_{.O} b_O and M_C. x, as
    // one sparse product of each matrix with all columns: column by column
    // each passed over all rows of its matrix and allocated, imported and
    // copied vectors, which on the 3D bar of benchmarks/speed_accuracy
    // (1,158 local coarse columns) took as long as the solve itself.
    const Epetra_BlockMap &map = b.front().trilinos_vector().Map();
    const int              n   = static_cast<int>(b.size());
    Epetra_MultiVector     given(map, n), columns(map, n);
    for (int j = 0; j < n; ++j)
      std::copy(b[j].begin(), b[j].end(), given[j]);
    AssertThrow(to_outside.trilinos_matrix().Multiply(false, given, columns) ==
                    0 &&
                  columns.Update(1., given, -1.) == 0,
                ExcMessage("the free block's right-hand sides"));
    direct->solve(columns, false);
    if (any_constrained)
      {
        Epetra_MultiVector product(map, n);
        AssertThrow(constraints.trilinos_matrix().Multiply(false,
                                                           columns,
                                                           product) == 0,
                    ExcMessage("the constrained rows' products"));
        for (const index h : model.constrained)
          {
            const int row =
              map.LID(static_cast<TrilinosWrappers::types::int_type>(h));
            for (int j = 0; j < n; ++j)
              columns[j][row] = given[j][row] - product[j][row];
          }
      }
    for (int j = 0; j < n; ++j)
      {
        x[j].reinit(b[j], true);
        std::copy(columns[j],
                  columns[j] + b[j].locally_owned_size(),
                  x[j].begin());
      }
  }
} // namespace ltn

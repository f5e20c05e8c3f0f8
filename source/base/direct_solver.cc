#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <ltn/base/direct_solver.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Map.h>
#include <Epetra_MultiVector.h>
#include <dmumps_c.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ltn
{
  namespace
  {
    /** MUMPS's arrays are numbered from 1 as in its manual: ICNTL(i). */
    MUMPS_INT &
    icntl(DMUMPS_STRUC_C &id, const unsigned int i)
    {
      return id.icntl[i - 1];
    }

    MUMPS_INT
    infog(const DMUMPS_STRUC_C &id, const unsigned int i)
    {
      return id.infog[i - 1];
    }

    std::string
    mumps_error(const DMUMPS_STRUC_C &id)
    {
      return "MUMPS reports INFOG(1) = " + std::to_string(infog(id, 1)) +
             ", INFOG(2) = " + std::to_string(infog(id, 2));
    }
    /**
     * Throw a failure a user can act on where MUMPS could not allocate its
     * memory in @p phase (INFOG(1) = -13): the system is too large to be
     * factorized on this machine, and the iterative solvers are the way on.
     */
    void
    check_memory(const DMUMPS_STRUC_C &id, const std::string &phase)
    {
      if (infog(id, 1) == -13)
        throw std::runtime_error(
          "the sparse direct solver (MUMPS) ran out of memory in the " + phase +
          " of a system of " + std::to_string(id.n) + " unknowns (" +
          mumps_error(id) +
          "); for systems this large, doc/prm_guide.md (\"Large scenes\") "
          "gives iterative settings that scale");
    }

    /**
     * Replace @p entries on the host by all ranks' entries, in rank order,
     * and empty them elsewhere.
     */
    template <typename T>
    void
    gather_on_host(std::vector<T> &entries, const MPI_Comm communicator)
    {
      const unsigned int n_ranks =
        Utilities::MPI::n_mpi_processes(communicator);
      if (n_ranks == 1)
        return;
      const bool host = Utilities::MPI::this_mpi_process(communicator) == 0;
      AssertThrow(entries.size() < (std::size_t(1) << 31),
                  ExcMessage("too many matrix entries on one rank for MUMPS"));
      const int        count = static_cast<int>(entries.size());
      std::vector<int> counts(host ? n_ranks : 0), offsets;
      MPI_Gather(
        &count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, communicator);
      std::vector<T> all;
      if (host)
        {
          offsets.resize(n_ranks, 0);
          std::size_t total = 0;
          for (unsigned int r = 0; r < n_ranks; ++r)
            {
              AssertThrow(total < (std::size_t(1) << 31),
                          ExcMessage("too many matrix entries for MUMPS's "
                                     "32-bit counts"));
              offsets[r] = static_cast<int>(total);
              total += counts[r];
            }
          all.resize(total);
        }
      const MPI_Datatype type = Utilities::MPI::mpi_type_id_for_type<T>;
      MPI_Gatherv(entries.data(),
                  count,
                  type,
                  all.data(),
                  counts.data(),
                  offsets.data(),
                  type,
                  0,
                  communicator);
      entries = std::move(all);
    }
  } // namespace



  /**
   * One MUMPS instance on the matrix's communicator, rank 0 the host: the
   * matrix given distributed (each rank its own rows), right-hand sides and
   * solutions gathered on the host, where MUMPS wants them dense.
   */
  struct DirectSolver::Mumps
  {
    Mumps(const TrilinosWrappers::SparseMatrix &matrix,
          const double                          pivot_threshold,
          const Symmetry                        symmetry,
          const Ordering                        ordering)
      : communicator(matrix.get_mpi_communicator())
      , row_map(matrix.trilinos_matrix().RowMap())
    {
      const bool host = Utilities::MPI::this_mpi_process(communicator) == 0;
      const types::global_dof_index n = matrix.m();
      AssertThrow(n < (types::global_dof_index(1) << 31),
                  ExcMessage("MUMPS's 32-bit indices cannot number " +
                             std::to_string(n) + " rows"));

      // The host's map holds every row, the others none: a vector imported
      // into it is the dense centralized vector MUMPS reads and writes.
      const auto n_host =
        static_cast<TrilinosWrappers::types::int_type>(host ? n : 0);
      host_map = std::make_unique<Epetra_Map>(
        static_cast<TrilinosWrappers::types::int_type>(n),
        n_host,
        static_cast<TrilinosWrappers::types::int_type>(0),
        row_map.Comm());
      to_host = std::make_unique<Epetra_Import>(*host_map, row_map);

      // This rank's rows as triplets, numbered from 1 (read from Epetra:
      // deal.II's iterators copy each row they visit, most of the setup).
      std::vector<MUMPS_INT>  rows, columns;
      std::vector<double>     values;
      const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
      rows.reserve(epetra.NumMyNonzeros());
      columns.reserve(epetra.NumMyNonzeros());
      values.reserve(epetra.NumMyNonzeros());
      for (int i = 0; i < epetra.NumMyRows(); ++i)
        {
          int     length;
          double *row_values;
          int    *row_columns;
          epetra.ExtractMyRowView(i, length, row_values, row_columns);
          const auto row = static_cast<MUMPS_INT>(epetra.GRID64(i) + 1);
          for (int k = 0; k < length; ++k)
            {
              const auto column =
                static_cast<MUMPS_INT>(epetra.GCID64(row_columns[k]) + 1);
              if (symmetry != Symmetry::general && column > row)
                continue;
              rows.push_back(row);
              columns.push_back(column);
              values.push_back(row_values[k]);
            }
        }
      // The whole matrix on the host, whatever the number of ranks: MUMPS
      // computes its maximum-weight matching (below) on a centralized matrix
      // only, and the factors then do not depend on how the rows were
      // distributed (the analysis runs on the host either way). MUMPS reads
      // the triplets in the factorization only (no iterative refinement or
      // error analysis asked): they go when it is done.
      gather_on_host(rows, communicator);
      gather_on_host(columns, communicator);
      gather_on_host(values, communicator);

      instance.start(communicator, symmetry);
      DMUMPS_STRUC_C &id = instance.id;
      // Errors go into our exceptions, not onto the terminal.
      icntl(id, 1) = -1;
      icntl(id, 2) = -1;
      icntl(id, 3) = -1;
      icntl(id, 4) = 0;
      // A column permutation that maximizes the product of the diagonal
      // entries (MC64). The full-space optimality system (doc 'The
      // full-space KKT system') has
      // zero diagonals at every state not observed on the overlap and every
      // multiplier; without it the factorization delayed 92 % of the pivots
      // (diffusion_3d_convergence: 4.4e11 flops, 1.2e8 factor entries; with
      // it 9.8e10 and 5.3e7, 0.07 % delayed). The models' own matrices keep
      // their diagonal.
      icntl(id, 6) = 5;
      // Approximate minimum degree with detection of quasi-dense rows (the
      // rows of wide nonlocal stencils): faster than MUMPS's automatic
      // choice on the 2D convergence scene (5.8 s against 7.6 s in all).
      // Nested dissection by PORD, which MUMPS always carries (Debian's
      // build runs PORD whether METIS, SCOTCH or its automatic choice is
      // asked for), on a mesh's matrix: the 3D cracked bar's FE_Q(2)
      // model of 83,682 unknowns factorized with 1.4e8 entries and
      // 2.7e11 flops against 2.0e8 and 6.1e11 ('The reduced space').
      icntl(id, 7) = ordering == Ordering::nested_dissection ? 4 : 6;
      // Simultaneous row and column iterative scaling, as Amesos set it.
      icntl(id, 8)  = 7;
      icntl(id, 18) = 0; // the matrix centralized on the host
      icntl(id, 20) = 0; // dense right-hand sides on the host
      icntl(id, 21) = 0; // the solution on the host, in place
      id.cntl[0]    = pivot_threshold;
      id.n          = static_cast<MUMPS_INT>(n);
      if (host)
        {
          id.nnz = static_cast<MUMPS_INT8>(values.size());
          id.nz  = static_cast<MUMPS_INT>(values.size());
          id.irn = rows.data();
          id.jcn = columns.data();
          id.a   = values.data();
        }

      id.job = 1;
      dmumps_c(&id);
      check_memory(id, "analysis");
      AssertThrow(infog(id, 1) >= 0,
                  ExcMessage("the symbolic factorization failed: " +
                             mumps_error(id)));
      // Pivoting on indefinite (saddle point) matrices needs more workspace
      // than MUMPS's estimate: when it runs out (INFOG(1) = -9, seen in 3D
      // on 2 ranks even with 100 % extra), start over with twice as much.
      for (int extra_workspace = 100;; extra_workspace *= 2)
        {
          icntl(id, 14) = extra_workspace;
          id.job        = 2;
          dmumps_c(&id);
          if (infog(id, 1) >= 0)
            {
              id.irn = id.jcn = nullptr;
              id.a            = nullptr;
              return;
            }
          check_memory(id, "factorization");
          if (infog(id, 1) == -10)
            throw SingularFactorization(
              "the matrix is singular: the numeric factorization failed: " +
              mumps_error(id));
          AssertThrow(infog(id, 1) == -9 && extra_workspace < 1600,
                      ExcMessage("the numeric factorization failed: " +
                                 mumps_error(id)));
        }
    }

    /** Solve for the columns of @p b (overwritten by the solutions). */
    void
    solve(Epetra_MultiVector &b, const bool transpose)
    {
      DMUMPS_STRUC_C    &id = instance.id;
      Epetra_MultiVector on_host(*host_map, b.NumVectors());
      AssertThrow(on_host.Import(b, *to_host, Insert) == 0,
                  ExcMessage("gathering the right-hand sides failed"));
      double *values_on_host = nullptr;
      int     stride         = 0;
      on_host.ExtractView(&values_on_host, &stride);
      id.rhs       = values_on_host;
      id.nrhs      = b.NumVectors();
      id.lrhs      = std::max(stride, 1);
      icntl(id, 9) = transpose ? 0 : 1;
      // All the columns in one block: the factors are read once per call,
      // not once per 32 columns (MUMPS's default blocking).
      icntl(id, 27) = std::max(id.nrhs, 1);
      // Many sparse right-hand sides (at most a tenth of their entries
      // nonzero, as the local coarse columns: a control's unit vector moved
      // to the free rows it couples to) are given as sparse columns: MUMPS
      // then runs the forward elimination only along the paths of the
      // elimination tree they touch. The solutions stay dense, in `rhs`.
      std::vector<MUMPS_INT> column_start, entry_row;
      std::vector<double>    entry_value;
      int                    sparse = 0;
      if (on_host.MyLength() > 0 && id.nrhs > 1)
        {
          std::size_t nonzeros = 0;
          for (int j = 0; j < id.nrhs; ++j)
            nonzeros += std::count_if(values_on_host + std::size_t(j) * stride,
                                      values_on_host + std::size_t(j) * stride +
                                        on_host.MyLength(),
                                      [](const double v) { return v != 0.; });
          sparse =
            10 * nonzeros <= std::size_t(on_host.MyLength()) * id.nrhs ? 1 : 0;
          if (sparse)
            {
              for (int j = 0; j < id.nrhs; ++j)
                {
                  column_start.push_back(entry_row.size() + 1);
                  const double *column =
                    values_on_host + std::size_t(j) * stride;
                  for (int i = 0; i < on_host.MyLength(); ++i)
                    if (column[i] != 0.)
                      {
                        entry_row.push_back(i + 1);
                        entry_value.push_back(column[i]);
                      }
                }
              column_start.push_back(entry_row.size() + 1);
            }
        }
      MPI_Bcast(&sparse, 1, MPI_INT, 0, communicator);
      icntl(id, 20)  = sparse;
      id.nz_rhs      = static_cast<MUMPS_INT>(entry_row.size());
      id.irhs_ptr    = column_start.data();
      id.irhs_sparse = entry_row.data();
      id.rhs_sparse  = entry_value.data();
      id.job         = 3;
      dmumps_c(&id);
      icntl(id, 20) = 0;
      id.irhs_ptr = id.irhs_sparse = nullptr;
      id.rhs_sparse                = nullptr;
      check_memory(id, "solve");
      AssertThrow(infog(id, 1) >= 0,
                  ExcMessage("the direct solve failed: " + mumps_error(id)));
      AssertThrow(b.Export(on_host, *to_host, Insert) == 0,
                  ExcMessage("scattering the solutions failed"));
    }

    /**
     * The MUMPS instance, freed also when a factorization throws (the
     * full-space solver then retries with another pivot threshold).
     */
    struct Instance
    {
      DMUMPS_STRUC_C id      = {};
      bool           started = false;

      void
      start(const MPI_Comm communicator, const Symmetry symmetry)
      {
        id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(communicator));
        id.par          = 1; // the host works too
        // MUMPS's SYM: 0 general (LU), 1 symmetric positive definite (LDL^T
        // without pivoting), 2 symmetric (LDL^T with 1x1 and 2x2 pivots).
        id.sym = symmetry == Symmetry::general   ? 0 :
                 symmetry == Symmetry::symmetric ? 2 :
                                                   1;
        id.job = -1;
        dmumps_c(&id);
        started = true;
        AssertThrow(infog(id, 1) >= 0, ExcMessage(mumps_error(id)));
      }

      ~Instance()
      {
        if (started)
          {
            id.job = -2;
            dmumps_c(&id);
          }
      }
    };

    Instance       instance;
    const MPI_Comm communicator;
    /** A copy (Epetra's maps share their data): the matrix may go. */
    const Epetra_BlockMap          row_map;
    std::unique_ptr<Epetra_Map>    host_map;
    std::unique_ptr<Epetra_Import> to_host;
  };



  DirectSolver::DirectSolver(const TrilinosWrappers::SparseMatrix &matrix,
                             const double   pivot_threshold,
                             const Symmetry symmetry,
                             const Ordering ordering)
    : mumps(
        std::make_unique<Mumps>(matrix, pivot_threshold, symmetry, ordering))
  {}



  DirectSolver::~DirectSolver() = default;



  double
  DirectSolver::factor_entries() const
  {
    // INFOG(29) on every rank; negative, it counts millions.
    const MUMPS_INT entries = infog(mumps->instance.id, 29);
    return entries >= 0 ? entries : -1e6 * entries;
  }



  void
  DirectSolver::solve(TrilinosWrappers::MPI::Vector       &x,
                      const TrilinosWrappers::MPI::Vector &b) const
  {
    x = b;
    mumps->solve(x.trilinos_vector(), false);
  }



  void
  DirectSolver::solve_transposed(TrilinosWrappers::MPI::Vector       &x,
                                 const TrilinosWrappers::MPI::Vector &b) const
  {
    x = b;
    mumps->solve(x.trilinos_vector(), true);
  }



  void
  DirectSolver::solve(std::vector<TrilinosWrappers::MPI::Vector>       &x,
                      const std::vector<TrilinosWrappers::MPI::Vector> &b,
                      const bool transpose) const
  {
    x.resize(b.size());
    if (b.empty())
      return;
    const Epetra_BlockMap &map = b.front().trilinos_vector().Map();
    Epetra_MultiVector     columns(map, b.size());
    for (std::size_t j = 0; j < b.size(); ++j)
      std::copy(b[j].begin(), b[j].end(), columns[j]);
    solve(columns, transpose);
    for (std::size_t j = 0; j < b.size(); ++j)
      {
        x[j].reinit(b[j], true);
        std::copy(columns[j],
                  columns[j] + b[j].locally_owned_size(),
                  x[j].begin());
      }
  }



  void
  DirectSolver::solve(Epetra_MultiVector &columns, const bool transpose) const
  {
    mumps->solve(columns, transpose);
  }
} // namespace ltn

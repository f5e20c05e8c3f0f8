#pragma once

#include <deal.II/lac/trilinos_precondition.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Vector.h>
#include <mpi.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The product of a sparse matrix whose rows are a few-point stencil
   * (doc/discretization.md, 'Iterative model solvers'): over rows
   * numbered contiguously on
   * each rank, every off-diagonal entry of row `g` lies in column `g + o`
   * for `o` from one set of at most eight offsets and has one value `c`,
   *
   *   (A x)_g = a_g x_g + c sum_{o present in row g} x_{g + o}.
   *
   * The lattice surrogate is one (the offsets are the axis neighbours'
   * numbers, `c = -diagonal / (2 dim)`). Its product reads per row a byte
   * (which offsets are present) and the diagonal, where the compressed rows
   * read seven values and seven column numbers, and reads the owned values
   * directly where the whole stencil stays in the rank's range, importing
   * only the values within the offsets' reach of its two ends.
   *
   * It describes a matrix it does not copy: ML builds its hierarchy on the
   * matrix itself, and serve_finest_level() then gives ML's finest level
   * this product in place of the compressed rows' one (a copy that ML
   * built on kept a second set of the rows: 13 MiB per rank on the 1e5
   * bar).
   */
  class StencilMatrix
  {
  public:
    /**
     * The stencil of @p matrix, which must outlive this object;
     * is_stencil() says whether it has the form.
     */
    explicit StencilMatrix(const Epetra_CrsMatrix &matrix);

    /** ML's finest level, where this serves it, no longer calls it. */
    ~StencilMatrix();

    StencilMatrix(const StencilMatrix &) = delete;
    StencilMatrix &
    operator=(const StencilMatrix &) = delete;

    /** Are the rows a stencil (on every rank)? */
    bool
    is_stencil() const;

    /**
     * `y = A x` over this rank's rows, @p x and @p y their values. Only
     * where is_stencil(); collective (it imports the edges' values).
     */
    void
    apply(const double *x, double *y) const;

    /**
     * Make the finest level of @p amg, built on the matrix, multiply by
     * apply(). Returns whether it did: not where the rows are no stencil,
     * or where ML's finest operator is not the matrix.
     */
    bool
    serve_finest_level(const TrilinosWrappers::PreconditionAMG &amg) const;

    /** Bytes of the stencil's description and of its edges. */
    std::size_t
    memory_consumption() const;

  private:
    const Epetra_CrsMatrix   &matrix;
    MPI_Comm                  communicator;
    bool                      stencil = false;
    std::int64_t              first   = 0;
    std::vector<std::int64_t> offsets;
    double                    off_diagonal = 0;
    /** Bit k of row i: is offset k present? */
    std::vector<std::uint8_t> present;
    std::vector<double>       diagonal;
    /** The rows whose every offset stays in the owned range. */
    std::size_t inner_begin = 0, inner_end = 0;
    /** The imported ranges [below, first) and [end, above). */
    std::int64_t                   below = 0, above = 0;
    std::unique_ptr<Epetra_Vector> edges;
    std::unique_ptr<Epetra_Import> importer;
  };
} // namespace ltn

#include <ltn/base/discrete_model.h>

namespace ltn
{
  DofRole
  DiscreteModel::role(const types::global_dof_index i) const
  {
    return controls.is_element(i) ? DofRole::control :
           fixed.is_element(i)    ? DofRole::fixed :
                                    DofRole::free;
  }



  TrilinosWrappers::MPI::Vector
  DiscreteModel::new_vector() const
  {
    return TrilinosWrappers::MPI::Vector(owned, communicator);
  }



  TrilinosWrappers::MPI::Vector
  DiscreteModel::ghosted(const TrilinosWrappers::MPI::Vector &field) const
  {
    TrilinosWrappers::MPI::Vector result(owned, relevant, communicator);
    result = field;
    return result;
  }



  void
  DiscreteModel::vmult(TrilinosWrappers::MPI::Vector       &dst,
                       const TrilinosWrappers::MPI::Vector &src) const
  {
    if (matrix_free)
      matrix_free->vmult_rows(dst, src, false, RowSubset::all, nullptr);
    else
      matrix.vmult(dst, src);
  }



  void
  DiscreteModel::Tvmult(TrilinosWrappers::MPI::Vector       &dst,
                        const TrilinosWrappers::MPI::Vector &src) const
  {
    if (matrix_free)
      matrix_free->vmult_rows(dst, src, true, RowSubset::all, nullptr);
    else
      matrix.Tvmult(dst, src);
  }



  void
  DiscreteModel::vmult_rows(TrilinosWrappers::MPI::Vector       &dst,
                            const TrilinosWrappers::MPI::Vector &src,
                            const bool                           transpose,
                            const RowSubset                      rows,
                            const RowRanges                     *within) const
  {
    if (matrix_free)
      matrix_free->vmult_rows(dst, src, transpose, rows, within);
    else if (transpose)
      matrix.Tvmult(dst, src);
    else
      matrix.vmult(dst, src);
  }



  std::vector<RowRanges>
  DiscreteModel::rows_near(const TrilinosWrappers::MPI::Vector &marked,
                           const unsigned int                   layers) const
  {
    if (matrix_free)
      return matrix_free->rows_near(marked, layers);
    const auto all = static_cast<unsigned int>(owned.n_elements());
    return std::vector<RowRanges>(layers + 1, RowRanges{{0u, all}});
  }



  std::size_t
  DiscreteModel::memory_consumption() const
  {
    const auto bytes = [](const TrilinosWrappers::SparseMatrix &m) {
      return m.m() == 0 ? std::size_t(0) : m.memory_consumption();
    };
    return bytes(matrix) + (lattice ? lattice->memory_consumption() : 0) +
           (matrix_free ? matrix_free->memory_consumption() : 0) +
           rhs.memory_consumption();
  }



  types::global_dof_index
  DiscreteModel::n_controls() const
  {
    return Utilities::MPI::sum<types::global_dof_index>(controls.n_elements(),
                                                        communicator);
  }
} // namespace ltn

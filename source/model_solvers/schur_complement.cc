#include <ltn/base/partition.h>
#include <ltn/model_solvers/schur_complement.h>

#include <algorithm>
#include <cmath>

namespace ltn
{
  SchurComplement::SchurComplement(const DiscreteModel   &model,
                                   const bool             transpose,
                                   const SchurComplement *same_model)
    : model(model)
    , transpose(transpose)
  {
    eliminates = Utilities::MPI::sum(model.eliminated.n_elements(),
                                     model.communicator) > 0;
    v          = model.new_vector();
    w          = model.new_vector();
    free       = model.new_vector();
    // The kept degrees of freedom, free or outside (controls and fixed
    // data), by their owned positions.
    TrilinosWrappers::MPI::Vector outside  = model.new_vector();
    unsigned int                  position = 0;
    for (const auto i : model.owned)
      {
        if (!model.eliminated.is_element(i))
          {
            if (model.role(i) == DofRole::free)
              {
                free.begin()[position] = 1.;
                free_list.push_back(position);
              }
            else
              outside.begin()[position] = 1.;
          }
        ++position;
      }
    free_partition = contiguous_partition(free_list.size(), model.communicator);
    // The same rows for M and M^T (the bonds are symmetric).
    near_outside =
      same_model ? same_model->near_outside : model.rows_near(outside, 2);
    if (!eliminates)
      return;
    kept             = model.new_vector();
    kept             = 1.;
    inverse_diagonal = model.new_vector();
    // D: M applied to the indicator of the eliminated degrees of freedom,
    // read at them (the same for M^T: D is diagonal).
    for (const auto i : model.eliminated)
      {
        v(i)    = 1.;
        kept(i) = 0.;
      }
    v.compress(VectorOperation::insert);
    kept.compress(VectorOperation::insert);
    model.vmult(w, v);
    for (const auto i : model.eliminated)
      {
        inverse_diagonal(i) = 1. / w(i);
        eliminated_positions.push_back(model.owned.index_within_set(i));
      }
    inverse_diagonal.compress(VectorOperation::insert);
  }



  void
  SchurComplement::vmult(TrilinosWrappers::MPI::Vector       &dst,
                         const TrilinosWrappers::MPI::Vector &src) const
  {
    if (!eliminates)
      model.vmult_rows(dst, src, transpose, RowSubset::all);
    else
      masked_product(dst, src, kept);
  }



  void
  SchurComplement::vmult_from_outside(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    // S = A - B D^-1 C: C src is zero beyond one bond of src's entries, and
    // the product with it beyond two.
    if (!eliminates)
      model.vmult_rows(dst, src, transpose, RowSubset::all, &near_outside[1]);
    else
      masked_product(dst, src, kept, {{&near_outside[1], &near_outside[2]}});
  }



  void
  SchurComplement::vmult_at_outside(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    // The rows u there read D^-1 C src within one bond of them.
    if (!eliminates)
      model.vmult_rows(dst, src, transpose, RowSubset::all, &near_outside[0]);
    else
      masked_product(dst, src, kept, {{&near_outside[1], &near_outside[0]}});
  }



  void
  SchurComplement::vmult_free_block(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    masked_product(dst, src, free);
  }



  void
  SchurComplement::restrict_to_free_block(
    TrilinosWrappers::MPI::Vector &v) const
  {
    v.scale(free);
  }



  TrilinosWrappers::MPI::Vector
  SchurComplement::new_free_vector() const
  {
    return TrilinosWrappers::MPI::Vector(free_partition, model.communicator);
  }



  const std::vector<unsigned int> &
  SchurComplement::free_positions() const
  {
    return free_list;
  }



  void
  SchurComplement::extract_free(TrilinosWrappers::MPI::Vector       &free_part,
                                const TrilinosWrappers::MPI::Vector &v) const
  {
    for (std::size_t i = 0; i < free_list.size(); ++i)
      free_part.begin()[i] = v.begin()[free_list[i]];
  }



  void
  SchurComplement::insert_free(
    TrilinosWrappers::MPI::Vector       &v,
    const TrilinosWrappers::MPI::Vector &free_part) const
  {
    std::fill(v.begin(), v.end(), 0.);
    for (std::size_t i = 0; i < free_list.size(); ++i)
      v.begin()[free_list[i]] = free_part.begin()[i];
  }



  void
  SchurComplement::vmult_free_vector(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    insert_free(v, src);
    product_of_work_vector(w);
    extract_free(dst, w);
  }



  void
  SchurComplement::masked_product(
    TrilinosWrappers::MPI::Vector          &dst,
    const TrilinosWrappers::MPI::Vector    &src,
    const TrilinosWrappers::MPI::Vector    &mask,
    const std::array<const RowRanges *, 2> &near_rows) const
  {
    // Loops over the owned values, not vector operations: `v = src` of
    // two vectors made apart imports (deal.II 9.4 compares their
    // communicators' objects, not the communicators), and the fused loops
    // pass over the vectors once.
    AssertDimension(v.locally_owned_size(), src.locally_owned_size());
    const std::size_t n = v.locally_owned_size();
    for (std::size_t i = 0; i < n; ++i)
      v.begin()[i] = src.begin()[i] * mask.begin()[i];
    product_of_work_vector(dst, near_rows);
    dst.scale(mask);
  }



  void
  SchurComplement::product_of_work_vector(
    TrilinosWrappers::MPI::Vector          &dst,
    const std::array<const RowRanges *, 2> &near_rows) const
  {
    if (!eliminates)
      {
        model.vmult_rows(dst, v, transpose, RowSubset::all, near_rows[1]);
        return;
      }
    // The t-rows of M [u; 0]: C u; v = [u; -D^-1 C u].
    model.vmult_rows(w, v, transpose, RowSubset::eliminated, near_rows[0]);
    // Over the t alone: a pass over all entries took 3 % of a run of the
    // 3e5 bar of benchmarks/scaling (two ranks, `perf`).
    for (const unsigned int i : eliminated_positions)
      v.begin()[i] -= inverse_diagonal.begin()[i] * w.begin()[i];
    // The u-rows of M v: A u - B D^-1 C u (into w too, if dst is w: its
    // t-rows are used by then).
    model.vmult_rows(dst, v, transpose, RowSubset::kept, near_rows[1]);
  }



  TrilinosWrappers::MPI::Vector
  SchurComplement::reduce(const TrilinosWrappers::MPI::Vector &b) const
  {
    if (!eliminates)
      return b;
    // The u-rows of M [0; D^-1 b_t]: B D^-1 b_t. Loops over the owned
    // values, as in masked_product().
    const std::size_t n       = v.locally_owned_size();
    double            largest = 0;
    for (std::size_t i = 0; i < n; ++i)
      {
        v.begin()[i] = b.begin()[i] * inverse_diagonal.begin()[i];
        largest      = std::max(largest, std::abs(v.begin()[i]));
      }
    // The coupled solves' right-hand sides, loads and the mismatch's
    // gradient, are zero at the eliminated rows (the dilatations' equations
    // have no source): the product, a pass over all kept rows, is then
    // zero, and skipped.
    const bool with_product =
      Utilities::MPI::max(largest, model.communicator) > 0;
    if (with_product)
      model.vmult_rows(w, v, transpose, RowSubset::kept);
    TrilinosWrappers::MPI::Vector g = b;
    for (std::size_t i = 0; i < n; ++i)
      g.begin()[i] =
        (with_product ? b.begin()[i] - w.begin()[i] : b.begin()[i]) *
        kept.begin()[i];
    return g;
  }



  void
  SchurComplement::recover(TrilinosWrappers::MPI::Vector       &x,
                           const TrilinosWrappers::MPI::Vector &b) const
  {
    if (!eliminates)
      return;
    // The t-rows of M [u; 0]: C u.
    x.scale(kept);
    model.vmult_rows(w, x, transpose, RowSubset::eliminated);
    const std::size_t n = x.locally_owned_size();
    for (std::size_t i = 0; i < n; ++i)
      x.begin()[i] +=
        inverse_diagonal.begin()[i] * (b.begin()[i] - w.begin()[i]);
  }



  std::size_t
  SchurComplement::memory_consumption() const
  {
    std::size_t ranges = 0;
    for (const RowRanges &rows : near_outside)
      ranges += rows.size();
    return (eliminates ? 5 : 3) * free.memory_consumption() +
           free_list.size() * sizeof(unsigned int) +
           eliminated_positions.size() * sizeof(unsigned int) +
           ranges * sizeof(RowRanges::value_type);
  }
} // namespace ltn

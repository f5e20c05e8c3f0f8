// Control vectors of two blocks on one process, and dense matrices acting
// on them: the small exactly known operators the control solvers' unit
// tests run on.
#pragma once

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <array>
#include <functional>

namespace dense_controls
{
  using BlockVectorType = dealii::TrilinosWrappers::MPI::BlockVector;
  using Sizes           = std::array<unsigned int, 2>;

  /** Control vectors of two blocks of the sizes `sizes`. */
  struct Blocks
  {
    /** A zero vector. */
    BlockVectorType
    new_vector() const
    {
      BlockVectorType v(2);
      for (const unsigned int k : {0u, 1u})
        v.block(k).reinit(dealii::complete_index_set(sizes[k]), MPI_COMM_SELF);
      v.collect_sizes();
      return v;
    }

    /** The vector with entries `f(i)`. */
    BlockVectorType
    from_function(const std::function<double(unsigned int)> &f) const
    {
      BlockVectorType v = new_vector();
      for (unsigned int i = 0; i < v.size(); ++i)
        v(i) = f(i);
      v.compress(dealii::VectorOperation::insert);
      return v;
    }

    const Sizes sizes;
  };

  /** `dst = A src`. */
  inline void
  apply(const dealii::FullMatrix<double> &A,
        BlockVectorType                  &dst,
        const BlockVectorType            &src)
  {
    for (unsigned int i = 0; i < A.m(); ++i)
      {
        double sum = 0;
        for (unsigned int l = 0; l < A.n(); ++l)
          sum += A(i, l) * src(l);
        dst(i) = sum;
      }
    dst.compress(dealii::VectorOperation::insert);
  }

  /** A dense matrix as an operator for deal.II's solvers. */
  struct DenseOperator
  {
    void
    vmult(BlockVectorType &dst, const BlockVectorType &src) const
    {
      apply(A, dst, src);
    }
    const dealii::FullMatrix<double> &A;
  };
} // namespace dense_controls

#pragma once

#include <deal.II/base/types.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace ltn
{
  using namespace dealii;

  /** What a degree of freedom of a model is to the coupling. */
  enum class DofRole : unsigned char
  {
    /** An unknown of the model's own equations (a row of `A`). */
    free,
    /** A virtual control: `theta_n` on the control collar, `theta_l` on
       `Gamma_c`. A column of `A`, but no row. */
    control,
    /** Fixed by physical data (volume constraint or Dirichlet condition). */
    fixed
  };

  /**
   * The narrow interface through which the coupling sees a model: its matrix
   * `A` and load vector `F` over all its degrees of freedom (without any
   * constraint applied), the role of every degree of freedom, and the values
   * of the fixed ones. The model's equations are the rows of the free degrees
   * of freedom: `sum_j A_ij x_j = F_i` for free `i`, with `x_j` the control
   * or fixed value where `j` is not free.
   *
   * Not copyable: the matrix points to the sparsity pattern it holds.
   */
  struct DiscreteModel
  {
    DiscreteModel()                      = default;
    DiscreteModel(const DiscreteModel &) = delete;
    DiscreteModel &
    operator=(const DiscreteModel &) = delete;

    SparsityPattern      sparsity;
    SparseMatrix<double> matrix;
    Vector<double>       rhs;
    Vector<double>       fixed_values;
    std::vector<DofRole> roles;
  };
} // namespace ltn

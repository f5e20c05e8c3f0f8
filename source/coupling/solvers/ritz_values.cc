#include <deal.II/base/exceptions.h>

#include <deal.II/lac/tridiagonal_matrix.h>

#include <ltn/coupling/solvers/ritz_values.h>

#include <algorithm>
#include <cmath>

namespace ltn
{
  using namespace dealii;

  void
  RitzValues::add_step_length(const double a)
  {
    Assert(step_lengths.size() == direction_coefficients.size(),
           ExcMessage("a step length follows a direction's coefficient"));
    step_lengths.push_back(a);
  }



  void
  RitzValues::add_direction_coefficient(const double b)
  {
    Assert(step_lengths.size() == direction_coefficients.size() + 1,
           ExcMessage("a direction's coefficient follows a step length"));
    direction_coefficients.push_back(b);
  }



  std::vector<double>
  RitzValues::values() const
  {
    const std::size_t n = step_lengths.size();
    if (n == 0)
      return {};
    TridiagonalMatrix<double> T(n, true);
    for (std::size_t j = 0; j < n; ++j)
      {
        T(j, j) = 1. / step_lengths[j];
        if (j > 0)
          T(j, j) += direction_coefficients[j - 1] / step_lengths[j - 1];
        if (j + 1 < n)
          T(j, j + 1) = std::sqrt(direction_coefficients[j]) / step_lengths[j];
      }
    T.compute_eigenvalues();
    std::vector<double> values(n);
    for (std::size_t j = 0; j < n; ++j)
      values[j] = T.eigenvalue(j);
    std::sort(values.begin(), values.end());
    return values;
  }
} // namespace ltn

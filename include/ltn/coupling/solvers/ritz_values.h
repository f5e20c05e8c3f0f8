#pragma once

#include <vector>

namespace ltn
{
  /**
   * The Ritz values of a preconditioned CG (doc/discretization.md,
   * 'A coarse level for the controls', "What bounds the outer
   * iterations"): from its step lengths
   * `a_j` and direction coefficients `b_j` (`p_{j+1} = z_{j+1} + b_j p_j`),
   * the eigenvalues of Lanczos's tridiagonal matrix
   *
   *   T_jj = 1/a_j + b_{j-1}/a_{j-1},   T_{j,j+1} = sqrt(b_j)/a_j,
   *
   * as deal.II's SolverCG computes them for its own iterations. The extreme
   * ones converge first, to the extreme eigenvalues of the preconditioned
   * operator (for a deflated CG, on the complement of its coarse space),
   * so their ratio estimates the condition number the iterations see.
   */
  class RitzValues
  {
  public:
    /** Record the step length of the next step. */
    void
    add_step_length(const double a);

    /** Record the coefficient of the next direction. */
    void
    add_direction_coefficient(const double b);

    /** The Ritz values, in ascending order; none before a step. */
    std::vector<double>
    values() const;

  private:
    std::vector<double> step_lengths, direction_coefficients;
  };
} // namespace ltn

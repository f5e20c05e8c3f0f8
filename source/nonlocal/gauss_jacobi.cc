#include <ltn/nonlocal/gauss_jacobi.h>

#include <cmath>

#include <Eigen/Eigenvalues>

namespace ltn
{
  Quadrature<1>
  gauss_jacobi_unit_interval(const unsigned int n_points, const double alpha)
  {
    AssertThrow(alpha > -1, ExcMessage("Gauss-Jacobi needs alpha > -1."));
    AssertThrow(n_points > 0, ExcMessage("Gauss-Jacobi needs n > 0 points."));

    // Jacobi matrix for the weight (1+s)^b on (-1,1), b = alpha (a = 0).
    const double    b = alpha;
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n_points, n_points);
    for (unsigned int k = 0; k < n_points; ++k)
      {
        const double two_k_b = 2. * k + b;
        J(k, k) = (k == 0) ? b / (b + 2) : b * b / (two_k_b * (two_k_b + 2));
        if (k + 1 < n_points)
          {
            const double m  = k + 1;
            const double tm = 2. * m + b;
            const double beta_m =
              4. * m * m * (m + b) * (m + b) / (tm * tm * (tm + 1) * (tm - 1));
            J(k, k + 1) = J(k + 1, k) = std::sqrt(beta_m);
          }
      }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(J);
    AssertThrow(eigen.info() == Eigen::Success,
                ExcMessage("Gauss-Jacobi eigenproblem failed."));

    // mu_0 = int_{-1}^{1} (1+s)^b ds; mapping s -> t = (1+s)/2 scales the
    // weights by 2^-(b+1).
    const double mu_0  = std::pow(2., b + 1) / (b + 1);
    const double scale = std::pow(2., -(b + 1));

    std::vector<Point<1>> points(n_points);
    std::vector<double>   weights(n_points);
    for (unsigned int q = 0; q < n_points; ++q)
      {
        const double v0 = eigen.eigenvectors()(0, q);
        points[q]       = Point<1>(0.5 * (1 + eigen.eigenvalues()(q)));
        weights[q]      = mu_0 * v0 * v0 * scale;
      }
    return Quadrature<1>(points, weights);
  }
} // namespace ltn

#include <deal.II/base/quadrature_lib.h>

#include <ltn/nonlocal/lattice_stencil.h>

#include <cmath>

#include <Eigen/Dense>

namespace ltn
{
  namespace
  {
    /** All multi-indices alpha with 1 <= |alpha| <= max_degree. */
    template <int dim>
    std::vector<std::array<unsigned int, dim>>
    multi_indices(const unsigned int max_degree)
    {
      std::vector<std::array<unsigned int, dim>> result;
      std::array<unsigned int, dim>              alpha{};
      const auto                                 recurse = [&](const auto        &self,
                               const unsigned int d,
                               const unsigned int remaining) -> void {
        if (d == dim)
          {
            unsigned int total = 0;
            for (const unsigned int a : alpha)
              total += a;
            if (total >= 1)
              result.push_back(alpha);
            return;
          }
        for (unsigned int a = 0; a <= remaining; ++a)
          {
            alpha[d] = a;
            self(self, d + 1, remaining - a);
          }
      };
      recurse(recurse, 0, max_degree);
      return result;
    }

    /**
     * int over the box [lower, upper] ∩ B_eps(0) of gamma(|y|), by recursive
     * subdivision of boxes the sphere cuts, to depth max_depth; cut leaves
     * use the Gauss points that fall inside the ball.
     */
    template <int dim>
    double
    cut_cell_integral(const Kernel          &kernel,
                      const Point<dim>      &lower,
                      const Point<dim>      &upper,
                      const unsigned int     depth,
                      const unsigned int     max_depth,
                      const Quadrature<dim> &rule)
    {
      const double eps   = kernel.horizon();
      double       near2 = 0, far2 = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double lo = lower[d], hi = upper[d];
          const double n = (lo > 0) ? lo : (hi < 0 ? -hi : 0.);
          near2 += n * n;
          far2 += std::max(lo * lo, hi * hi);
        }
      if (near2 >= eps * eps)
        return 0;
      const bool inside = far2 <= eps * eps;
      if (inside || depth == max_depth)
        {
          double volume = 1;
          for (unsigned int d = 0; d < dim; ++d)
            volume *= upper[d] - lower[d];
          double sum = 0;
          for (unsigned int q = 0; q < rule.size(); ++q)
            {
              Point<dim> y;
              for (unsigned int d = 0; d < dim; ++d)
                y[d] = lower[d] + (upper[d] - lower[d]) * rule.point(q)[d];
              const double r = y.norm();
              if (r <= eps)
                sum += rule.weight(q) * kernel.value(r);
            }
          return sum * volume;
        }
      double sum = 0;
      for (unsigned int child = 0; child < (1u << dim); ++child)
        {
          Point<dim> child_lower, child_upper;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double middle     = 0.5 * (lower[d] + upper[d]);
              const bool   upper_half = (child >> d) & 1;
              child_lower[d]          = upper_half ? middle : lower[d];
              child_upper[d]          = upper_half ? upper[d] : middle;
            }
          sum += cut_cell_integral(
            kernel, child_lower, child_upper, depth + 1, max_depth, rule);
        }
      return sum;
    }
  } // namespace



  template <int dim>
  double
  LatticeStencil<dim>::exact_moment(const Kernel                        &kernel,
                                    const std::array<unsigned int, dim> &alpha)
  {
    // Spherical part: int over S^{dim-1} of w^alpha, zero unless every
    // alpha_d is even; radial part: int_0^eps c r^-beta (r/eps)^|alpha|
    // r^(dim-1) dr.
    unsigned int order     = 0;
    double       spherical = 2;
    for (const unsigned int a : alpha)
      {
        if (a % 2 == 1)
          return 0;
        order += a;
        spherical *= std::tgamma((a + 1) / 2.);
      }
    spherical /= std::tgamma((order + dim) / 2.);
    const double beta = kernel.exponent();
    return spherical * kernel.scale() * std::pow(kernel.horizon(), dim - beta) /
           (order + dim - beta);
  }



  template <int dim>
  void
  kernel_weighted_cell_volumes(const Kernel                      &kernel,
                               const double                       spacing,
                               std::vector<std::array<int, dim>> &offsets,
                               std::vector<double>               &volumes)
  {
    const double eps = kernel.horizon();
    const double h   = spacing;
    // Cells that the ball reaches: |o_d| <= eps / h + 1/2.
    const int          radius = static_cast<int>(std::floor(eps / h + 0.5));
    const QGauss<dim>  rule(3);
    const unsigned int max_depth = (dim == 1) ? 30 : (dim == 2 ? 9 : 5);

    offsets.clear();
    volumes.clear();
    std::array<int, dim> o{};
    const int            n       = 2 * radius + 1;
    const unsigned int   n_cells = std::pow(n, dim);
    for (unsigned int index = 0; index < n_cells; ++index)
      {
        unsigned int rest = index;
        bool         zero = true;
        Point<dim>   lower, upper;
        for (unsigned int d = 0; d < dim; ++d)
          {
            o[d] = static_cast<int>(rest % n) - radius;
            rest /= n;
            zero &= (o[d] == 0);
            lower[d] = (o[d] - 0.5) * h;
            upper[d] = (o[d] + 0.5) * h;
          }
        // The particle's own cell has no bond; quadratures built on these
        // volumes account for its integral through their moments.
        if (zero)
          continue;
        const double a =
          cut_cell_integral(kernel, lower, upper, 0, max_depth, rule);
        if (a > 0)
          {
            offsets.push_back(o);
            volumes.push_back(a);
          }
      }
  }



  template <int dim>
  LatticeStencil<dim>::LatticeStencil(const Kernel &kernel,
                                      const double  spacing)
  {
    const double eps = kernel.horizon();
    const double h   = spacing;
    stencil_radius   = static_cast<int>(std::floor(eps / h + 0.5));
    std::vector<double> base;
    kernel_weighted_cell_volumes<dim>(kernel, spacing, stencil_offsets, base);

    // Correct the moments, degree 4 if the stencil allows, else degree 2.
    const unsigned int n_points = base.size();
    for (const unsigned int try_degree : {4u, 2u})
      {
        const auto      alphas = multi_indices<dim>(try_degree);
        Eigen::MatrixXd G(alphas.size(), n_points);
        Eigen::VectorXd target(alphas.size()), a0(n_points);
        for (unsigned int j = 0; j < n_points; ++j)
          a0[j] = base[j];
        for (unsigned int k = 0; k < alphas.size(); ++k)
          {
            target[k] = exact_moment(kernel, alphas[k]);
            for (unsigned int j = 0; j < n_points; ++j)
              {
                double monomial = 1;
                for (unsigned int d = 0; d < dim; ++d)
                  monomial *=
                    std::pow(stencil_offsets[j][d] * h / eps, alphas[k][d]);
                G(k, j) = monomial;
              }
          }
        // a = a0 + D G^T lambda, (G D G^T) lambda = target - G a0.
        const Eigen::MatrixXd GD = G * a0.asDiagonal();
        const Eigen::MatrixXd S  = GD * G.transpose();
        const Eigen::VectorXd lambda =
          S.completeOrthogonalDecomposition().solve(target - G * a0);
        const Eigen::VectorXd a = a0 + GD.transpose() * lambda;
        const double defect     = (G * a - target).lpNorm<Eigen::Infinity>();
        if (defect <= 1e-12 * target.lpNorm<Eigen::Infinity>())
          {
            stencil_coefficients.assign(a.data(), a.data() + n_points);
            degree = try_degree;
            return;
          }
      }
    AssertThrow(false,
                ExcMessage("The lattice stencil cannot be made exact on "
                           "quadratics: the horizon is too small for the "
                           "particle spacing."));
  }



  template <int dim>
  const std::vector<std::array<int, dim>> &
  LatticeStencil<dim>::offsets() const
  {
    return stencil_offsets;
  }



  template <int dim>
  const std::vector<double> &
  LatticeStencil<dim>::coefficients() const
  {
    return stencil_coefficients;
  }



  template <int dim>
  int
  LatticeStencil<dim>::radius() const
  {
    return stencil_radius;
  }



  template <int dim>
  unsigned int
  LatticeStencil<dim>::exact_degree() const
  {
    return degree;
  }

  template void
  kernel_weighted_cell_volumes<1>(const Kernel &,
                                  double,
                                  std::vector<std::array<int, 1>> &,
                                  std::vector<double> &);
  template void
  kernel_weighted_cell_volumes<2>(const Kernel &,
                                  double,
                                  std::vector<std::array<int, 2>> &,
                                  std::vector<double> &);
  template void
  kernel_weighted_cell_volumes<3>(const Kernel &,
                                  double,
                                  std::vector<std::array<int, 3>> &,
                                  std::vector<double> &);
  template class LatticeStencil<1>;
  template class LatticeStencil<2>;
  template class LatticeStencil<3>;
} // namespace ltn

// Kernel normalization and the plane-wave symbol, checked against
// independent quadrature and closed forms.

#include <deal.II/base/quadrature_lib.h>

#include <ltn/nonlocal/gauss_jacobi.h>
#include <ltn/nonlocal/kernel.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace ltn;

namespace
{
  // int over B_eps of gamma(|xi|) xi_1^2, by a radial Gauss-Jacobi rule for
  // the weight r^(dim+1-beta) and a trapezoidal rule (exact for cos^2) over
  // angles.
  double
  second_moment(const Kernel &kernel, const unsigned int dim)
  {
    const double eps  = kernel.horizon();
    const double beta = kernel.exponent();
    const auto   radial =
      gauss_jacobi_unit_interval(4, static_cast<double>(dim) + 1 - beta);
    double radial_integral = 0;
    for (unsigned int q = 0; q < radial.size(); ++q)
      radial_integral += radial.weight(q);
    radial_integral *= kernel.scale() * std::pow(eps, dim + 2 - beta);

    // Mean of w_1^2 over the unit sphere, times its area.
    double angular = 0;
    if (dim == 1)
      angular = 2;
    else
      {
        const unsigned int n = 64;
        for (unsigned int i = 0; i < n; ++i)
          {
            const double phi = 2 * M_PI * (i + 0.5) / n;
            if (dim == 2)
              angular += std::pow(std::cos(phi), 2) * 2 * M_PI / n;
            else
              {
                // w_1 = sin(theta) cos(phi): integrate (1 - t^2) in
                // t = cos(theta) by Gauss-Legendre, exactly.
                const dealii::QGauss<1> gauss(2);
                for (unsigned int j = 0; j < gauss.size(); ++j)
                  {
                    const double t = -1 + 2 * gauss.point(j)[0];
                    angular += (1 - t * t) * std::pow(std::cos(phi), 2) *
                               (2 * M_PI / n) * 2 * gauss.weight(j);
                  }
              }
          }
      }
    return radial_integral * angular;
  }
} // namespace



TEST_CASE("kernel second moments are one", "[kernel]")
{
  for (const unsigned int dim : {1u, 2u, 3u})
    for (const std::string name :
         {"constant", "inverse distance", "fractional"})
      for (const double eps : {0.05, 0.3, 2.})
        {
          const Kernel kernel(parse_selection(kernel_names(), name),
                              0.4,
                              dim,
                              eps);
          INFO(name << " dim " << dim << " eps " << eps);
          CHECK(second_moment(kernel, dim) == Approx(1.).epsilon(1e-12));
        }
}



TEST_CASE("kernel constants match the design's table", "[kernel]")
{
  const double eps = 0.7;
  CHECK(Kernel(KernelKind::constant, 0.5, 1, eps).scale() ==
        Approx(3. / (2 * std::pow(eps, 3))).epsilon(1e-14));
  CHECK(Kernel(KernelKind::constant, 0.5, 2, eps).scale() ==
        Approx(4. / (M_PI * std::pow(eps, 4))).epsilon(1e-14));
  CHECK(Kernel(KernelKind::constant, 0.5, 3, eps).scale() ==
        Approx(15. / (4 * M_PI * std::pow(eps, 5))).epsilon(1e-14));
  CHECK(Kernel(KernelKind::inverse_distance, 0.5, 3, eps).scale() ==
        Approx(3. / (M_PI * std::pow(eps, 4))).epsilon(1e-14));
  CHECK(Kernel(KernelKind::inverse_distance, 0.5, 2, eps).scale() ==
        Approx(3. / (M_PI * std::pow(eps, 3))).epsilon(1e-14));
  CHECK(Kernel(KernelKind::fractional, 0.25, 1, eps).scale() ==
        Approx(0.75 / std::pow(eps, 1.5)).epsilon(1e-14));
}



TEST_CASE("plane-wave symbol matches closed forms", "[kernel]")
{
  // The closed forms cancel catastrophically for small k eps (the series
  // does not): compare where they keep their digits, k eps >= 0.375.
  for (const double eps : {0.125, 0.5})
    for (const double k : {3., 8., 20.})
      {
        INFO("eps " << eps << " k " << k);
        // 1D constant: 4 c (sin(k eps) / k - eps).
        const Kernel k1(KernelKind::constant, 0.5, 1, eps);
        CHECK(k1.plane_wave_symbol(k) ==
              Approx(4 * k1.scale() * (std::sin(k * eps) / k - eps))
                .epsilon(1e-11));
        // 3D constant: 8 pi c ((sin(k eps) - k eps cos(k eps)) / k^3
        //                      - eps^3 / 3).
        const Kernel k3(KernelKind::constant, 0.5, 3, eps);
        const double closed_3d =
          8 * M_PI * k3.scale() *
          ((std::sin(k * eps) - k * eps * std::cos(k * eps)) / std::pow(k, 3) -
           std::pow(eps, 3) / 3);
        CHECK(k3.plane_wave_symbol(k) == Approx(closed_3d).epsilon(1e-10));
        // 2D constant: 4 pi c (eps J1(k eps) / k - eps^2 / 2).
        const Kernel k2(KernelKind::constant, 0.5, 2, eps);
        const double closed_2d =
          4 * M_PI * k2.scale() *
          (eps * std::cyl_bessel_j(1., k * eps) / k - eps * eps / 2);
        CHECK(k2.plane_wave_symbol(k) == Approx(closed_2d).epsilon(1e-10));
      }
}



TEST_CASE("plane-wave symbol of singular kernels by quadrature", "[kernel]")
{
  // sigma = 4 c int_0^eps (cos(k r) - 1) r^-beta dr in 1D; (cos(kr) - 1)/r^2
  // is smooth, so Gauss-Jacobi for r^(2-beta) converges exponentially.
  for (const std::string name : {"inverse distance", "fractional"})
    for (const double s : {0.1, 0.5, 0.9})
      {
        const double eps = 0.2, k = 7;
        const Kernel kernel(parse_selection(kernel_names(), name), s, 1, eps);
        const auto rule = gauss_jacobi_unit_interval(20, 2 - kernel.exponent());
        double     integral = 0;
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const double r = eps * rule.point(q)[0];
            // cos(kr) - 1 = -2 sin^2(kr/2), without cancellation at small r.
            integral +=
              rule.weight(q) * -2 * std::pow(std::sin(k * r / 2), 2) / (r * r);
          }
        integral *= 4 * kernel.scale() * std::pow(eps, 3 - kernel.exponent());
        INFO(name << " s " << s);
        CHECK(kernel.plane_wave_symbol(k) == Approx(integral).epsilon(1e-12));
      }
}



TEST_CASE("plane-wave symbol tends to -k^2 as eps -> 0", "[kernel]")
{
  for (const unsigned int dim : {1u, 2u, 3u})
    {
      const Kernel kernel(KernelKind::inverse_distance, 0.5, dim, 1e-4);
      CHECK(kernel.plane_wave_symbol(5.) == Approx(-25.).epsilon(1e-6));
    }
}

// Gauss-Jacobi rules integrate t^m t^alpha exactly up to degree 2n - 1.

#include <ltn/nonlocal/gauss_jacobi.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace ltn;

TEST_CASE("Gauss-Jacobi is exact on monomials", "[quadrature]")
{
  for (const double alpha : {-0.9, -0.5, 0., 0.2, 1., 2.})
    for (unsigned int n = 1; n <= 8; ++n)
      {
        const auto rule = gauss_jacobi_unit_interval(n, alpha);
        for (unsigned int m = 0; m <= 2 * n - 1; ++m)
          {
            double sum = 0;
            for (unsigned int q = 0; q < rule.size(); ++q)
              sum += rule.weight(q) * std::pow(rule.point(q)[0], m);
            INFO("alpha " << alpha << " n " << n << " m " << m);
            CHECK(sum == Approx(1. / (m + alpha + 1)).epsilon(1e-13));
          }
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            CHECK(rule.point(q)[0] > 0);
            CHECK(rule.point(q)[0] < 1);
          }
      }
}

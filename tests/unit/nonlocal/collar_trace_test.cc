// The collar's trace weights (doc/discretization.md, 'A surrogate model of
// the nonlocal control block'): how much
// each collar layer contributes to the smooth field a particle stencil
// drives into Omega_n, against the closed form of the two-layer chain.

#include <ltn/nonlocal/collar_trace.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>

using namespace ltn;

TEST_CASE("a nearest-neighbour stencil sees only the first collar layer",
          "[particles]")
{
  const std::vector<double> a = collar_trace_weights({2.5});
  REQUIRE(a.size() == 1);
  CHECK(a[0] == Approx(1).epsilon(1e-13));
}

TEST_CASE("collar trace weights of a two-layer stencil: the closed form",
          "[particles]")
{
  // On the half-line the bounded solutions are A + c r^j, with r the root
  // in (-1, 0) of r + 1/r = -(2 + w1 / w2); from v_0 = y_1, v_{-1} = y_2,
  // A = (y_1 - r y_2) / (1 - r).
  for (const double ratio : {0.5, 1., 4.})
    {
      const double              s = -(2 + ratio);
      const double              r = (s + std::sqrt(s * s - 4)) / 2;
      const std::vector<double> a = collar_trace_weights({ratio, 1.});
      INFO("w1 / w2 = " << ratio << ", r = " << r);
      REQUIRE(a.size() == 2);
      CHECK(a[0] == Approx(1 / (1 - r)).epsilon(1e-12));
      CHECK(a[1] == Approx(-r / (1 - r)).epsilon(1e-12));
    }
}

TEST_CASE("collar trace weights reproduce constants and fall off with depth",
          "[particles]")
{
  const std::vector<double> a = collar_trace_weights({5., 4., 1.});
  REQUIRE(a.size() == 3);
  CHECK(std::accumulate(a.begin(), a.end(), 0.) == Approx(1).epsilon(1e-12));
  CHECK(a[0] > a[1]);
  CHECK(a[1] > a[2]);
  CHECK(a[2] > 0);
}

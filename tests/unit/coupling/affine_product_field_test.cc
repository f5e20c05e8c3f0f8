// The crack opening fields' expansion into the coarse level's monomials
// (doc/discretization.md, 'A coarse level for the controls', "Crack
// opening fields"): the sum of
// the terms equals the product it expands, in 2D and 3D.

#include <ltn/coupling/preconditioners/affine_product_field.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace ltn;

namespace
{
  /** Component @p c of the sum of @p terms at @p xi. */
  double
  sum_of_terms(const std::vector<MonomialTerm> &terms,
               const std::array<double, 3>     &xi,
               const unsigned int               c)
  {
    double sum = 0;
    for (const MonomialTerm &term : terms)
      if (term.component == c)
        {
          double value = term.coefficient;
          for (unsigned int d = 0; d < 3; ++d)
            value *= std::pow(xi[d], term.exponents[d]);
          sum += value;
        }
    return sum;
  }

  /** Component @p c of @p field at @p x, the product itself. */
  double
  product_at(const AffineProductField    &field,
             const std::array<double, 3> &x,
             const unsigned int           c,
             const unsigned int           dim)
  {
    double product = field.direction[c];
    for (const auto &[g, h] : field.factors)
      {
        double affine = h;
        for (unsigned int d = 0; d < dim; ++d)
          affine += g[d] * x[d];
        product *= affine;
      }
    return product;
  }
} // namespace

TEST_CASE("an axis-aligned opening field about the frame's centre is one "
          "monomial",
          "[solvers][unit]")
{
  // e_y (y - 1) (x - 1)^2 in the frame centred at (1, 1), scaled by 2:
  // 8 xi_x^2 xi_y in the y component.
  const AffineProductField field = {
    {{0, 1, 0}}, {{{{0, 1, 0}}, -1.}, {{{1, 0, 0}}, -1.}, {{{1, 0, 0}}, -1.}}};
  const std::vector<MonomialTerm> terms =
    expand_in_frame(field, {{1, 1, 0}}, 2., 2);
  REQUIRE(terms.size() == 1);
  CHECK(terms[0].component == 1);
  CHECK(terms[0].exponents == std::array<unsigned int, 3>{{2, 1, 0}});
  CHECK(terms[0].coefficient == Approx(8).epsilon(1e-14));
}

TEST_CASE("the expansion of an oblique opening field in a shifted, scaled "
          "frame equals the product, in 2D and 3D",
          "[solvers][unit]")
{
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (const unsigned int dim : {2u, 3u})
    {
      // The normal n, a direction t along the crack and the crack's centre
      // c: the field n (n.(x - c)) (t.(x - c))^2.
      const double          a = 0.3, b = 0.2;
      std::array<double, 3> n = {{std::cos(a), std::sin(a), 0}};
      std::array<double, 3> t = {{-std::sin(a), std::cos(a), 0}};
      if (dim == 3)
        {
          n = {{std::cos(a) * std::cos(b), std::sin(a), std::sin(b)}};
          t = {{0, -std::sin(b), std::sin(a)}};
        }
      const std::array<double, 3> c = {{0.9, 1.1, dim == 3 ? 0.7 : 0}};
      const auto                  about_centre = [&](const auto &g) {
        double h = 0;
        for (unsigned int d = 0; d < dim; ++d)
          h -= g[d] * c[d];
        return std::make_pair(g, h);
      };
      const AffineProductField field = {
        n, {about_centre(n), about_centre(t), about_centre(t)}};
      const std::array<double, 3>     centre = {{1, 1, dim == 3 ? 0.5 : 0}};
      const double                    scale  = 0.4;
      const std::vector<MonomialTerm> terms =
        expand_in_frame(field, centre, scale, dim);
      for (const MonomialTerm &term : terms)
        CHECK(term.exponents[0] + term.exponents[1] + term.exponents[2] <= 3);
      for (unsigned int sample = 0; sample < 20; ++sample)
        {
          std::array<double, 3> xi = {{0, 0, 0}}, x = {{0, 0, 0}};
          for (unsigned int d = 0; d < dim; ++d)
            {
              xi[d] = uniform(random);
              x[d]  = centre[d] + scale * xi[d];
            }
          for (unsigned int component = 0; component < dim; ++component)
            CHECK(sum_of_terms(terms, xi, component) ==
                  Approx(product_at(field, x, component, dim)).margin(1e-15));
        }
    }
}

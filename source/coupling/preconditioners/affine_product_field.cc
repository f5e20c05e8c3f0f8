#include <ltn/coupling/preconditioners/affine_product_field.h>

#include <map>

namespace ltn
{
  std::vector<MonomialTerm>
  expand_in_frame(const AffineProductField    &field,
                  const std::array<double, 3> &centre,
                  const double                 scale,
                  const unsigned int           dim)
  {
    // The product's coefficients by the exponents of their monomials in xi.
    std::map<std::array<unsigned int, 3>, double> product = {{{{0, 0, 0}}, 1.}};
    for (const auto &[g, h] : field.factors)
      {
        double constant = h;
        for (unsigned int d = 0; d < dim; ++d)
          constant += g[d] * centre[d];
        std::map<std::array<unsigned int, 3>, double> next;
        for (const auto &[exponents, coefficient] : product)
          {
            next[exponents] += coefficient * constant;
            for (unsigned int d = 0; d < dim; ++d)
              {
                std::array<unsigned int, 3> raised = exponents;
                ++raised[d];
                next[raised] += coefficient * scale * g[d];
              }
          }
        product = std::move(next);
      }
    std::vector<MonomialTerm> terms;
    for (unsigned int c = 0; c < dim; ++c)
      if (field.direction[c] != 0)
        for (const auto &[exponents, coefficient] : product)
          if (coefficient != 0)
            terms.push_back({c, exponents, coefficient * field.direction[c]});
    return terms;
  }
} // namespace ltn

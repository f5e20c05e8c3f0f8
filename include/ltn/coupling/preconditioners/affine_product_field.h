#pragma once

#include <array>
#include <utility>
#include <vector>

namespace ltn
{
  /**
   * A vector field `d prod_i (g_i . x + h_i)`: a direction `d` times a
   * product of affine functions of the position `x` (dim-agnostic: the
   * entries beyond dim are ignored). The reduced-space CG adds such fields
   * to its coarse level beside the monomials (doc/discretization.md,
   * 'A coarse level for the controls', "Crack opening fields").
   */
  struct AffineProductField
  {
    std::array<double, 3>                                 direction;
    std::vector<std::pair<std::array<double, 3>, double>> factors;
  };

  /** A multiple of a monomial in one component of a vector field. */
  struct MonomialTerm
  {
    unsigned int                component;
    std::array<unsigned int, 3> exponents;
    double                      coefficient;
  };

  /**
   * @p field as a sum of monomials in the coordinates
   * `xi = (x - centre) / scale` of @p dim dimensions, one term per component
   * and monomial with a nonzero coefficient: each factor is
   * `scale (g . xi) + (g . centre + h)`, multiplied out.
   */
  std::vector<MonomialTerm>
  expand_in_frame(const AffineProductField    &field,
                  const std::array<double, 3> &centre,
                  const double                 scale,
                  const unsigned int           dim);
} // namespace ltn

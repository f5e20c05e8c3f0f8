#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace ltn
{
  /**
   * How much each layer of a particle model's collar contributes to the
   * smooth field it drives into `Omega_n` (doc/discretization.md,
   * 'A surrogate model of the nonlocal control block'). Along an axis
   * normal to a flat collar, a field constant
   * along the collar sees the model's stencil projected onto that axis:
   * weights `w_m` (@p projected_weights, `m = 1 .. M`) of the bonds that
   * reach `m` lattice layers along it. On the half-line of free particles
   * `j = 1, 2, ...` with the collar's values `y_l` at `j = 1 - l`
   * (`l = 1 .. M`, layer 1 next to `Omega_n`),
   *
   *   sum_m w_m (2 v_j - v_{j+m} - v_{j-m}) = 0,
   *
   * the bounded solution tends to a constant `sum_l a_l y_l`: the layers'
   * trace weights `a_l`, returned. A nearest-neighbour Laplacian whose
   * boundary values sit on layer 1 with the values `sum_l a_l y_l` extends
   * them alike. They sum to 1 (constants are reproduced); the nearest-
   * neighbour stencil itself (`M = 1`) gives `a_1 = 1`.
   *
   * The half-line is cut at `60 M` particles, where the flat continuation
   * `v_j = v_N` (`j > N`) closes it: the other solutions decay
   * geometrically away from the collar, to round-off well before.
   */
  std::vector<double>
  collar_trace_weights(const std::vector<double> &projected_weights);

  /**
   * A stencil's bonds projected on axis 0, the argument of
   * collar_trace_weights(): bond `k`, whose offset @p offsets[k] reaches
   * `m = offsets[k][0] > 0` layers along it, adds @p weight(k) to `w_m`.
   * As many layers as the bonds reach, which is the collar's depth (a
   * stencil's radius rounds eps/h: at eps = 2.5h it is 3 where the bonds
   * reach 2 layers).
   */
  template <typename Offsets, typename Weight>
  std::vector<double>
  axis_projection(const Offsets &offsets, const Weight &weight)
  {
    std::vector<double> projected;
    for (std::size_t k = 0; k < offsets.size(); ++k)
      if (const int m = offsets[k][0]; m > 0)
        {
          projected.resize(std::max<std::size_t>(projected.size(), m), 0.);
          projected[m - 1] += weight(k);
        }
    return projected;
  }
} // namespace ltn

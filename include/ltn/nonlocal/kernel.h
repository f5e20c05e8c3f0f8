#pragma once

#include <deal.II/base/point.h>

#include <ltn/base/selection.h>

#include <string>

namespace ltn
{
  using namespace dealii;

  /** The kernels of `Nonlocal model/Kernel` (Kernel lists their `beta`). */
  enum class KernelKind
  {
    constant,
    inverse_distance,
    fractional
  };

  /** The names of the kernels in `Nonlocal model/Kernel`. */
  inline const SelectionNames<KernelKind> &
  kernel_names()
  {
    static const SelectionNames<KernelKind> names = {
      {KernelKind::constant, "constant"},
      {KernelKind::inverse_distance, "inverse distance"},
      {KernelKind::fractional, "fractional"}};
    return names;
  }

  /**
   * A radial kernel of nonlocal diffusion, `gamma(|xi|) = c |xi|^-beta` for
   * `|xi| <= eps` and zero outside. All kernels of LtN are of this power-law
   * family, picked by name:
   *
   * | name               | beta        |
   * |--------------------|-------------|
   * | `constant`         | 0           |
   * | `inverse distance` | 1           |
   * | `fractional`       | dim + 2 s   |
   *
   * The scale `c` is fixed by the normalization of the design,
   * `integral over B_eps(0) of gamma(|xi|) xi_1^2 dxi = 1`, i.e.
   * `c = dim (dim + 2 - beta) / (|S^{dim-1}| eps^{dim + 2 - beta})`, so that
   * `L u = 2 int (u(y) - u(x)) gamma dy` equals the Laplacian on every
   * polynomial of degree <= 3 and tends to it as `eps -> 0`.
   */
  class Kernel
  {
  public:
    Kernel(const KernelKind   kind,
           const double       fractional_order,
           const unsigned int dim,
           const double       horizon);

    /** `gamma(r)` for `0 < r <= eps`, zero beyond the horizon. */
    double
    value(const double r) const;

    /** The exponent `beta` of `gamma = c r^-beta`. */
    double
    exponent() const;

    /** The scale `c` of `gamma = c r^-beta`. */
    double
    scale() const;

    /** The horizon `eps`. */
    double
    horizon() const;

    /**
     * The symbol of `L` on plane waves: `L e^{i k.x} = sigma(k) e^{i k.x}`
     * with `sigma(k) = 2 int_{B_eps} gamma(|xi|) (cos(k.xi) - 1) dxi`, for a
     * wave number `k = |k|`. Summed from its power series, which converges
     * for every `k eps`; cancellation between its alternating terms keeps
     * the relative error below 1e-13 only for `k eps <= 20` (measured
     * against the closed forms), which the input check enforces.
     */
    double
    plane_wave_symbol(const double wave_number) const;

    /** The surface area of the unit sphere in @p dim dimensions. */
    static double
    unit_sphere_area(const unsigned int dim);

  private:
    unsigned int dim;
    double       eps;
    double       beta;
    double       c;
  };
} // namespace ltn

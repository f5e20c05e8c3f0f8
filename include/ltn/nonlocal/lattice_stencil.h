#pragma once

#include <ltn/nonlocal/kernel.h>

#include <array>
#include <vector>

namespace ltn
{
  /**
   * The cells of a square (cubic) lattice of spacing @p spacing, centred at
   * `h o` for integer offsets `o != 0`, that the ball `B_eps(0)` of the
   * kernel's horizon reaches, and the kernel integrated over each cell's
   * part inside the ball, `int_{B_eps ∩ cell} gamma(|y|) dy` (positive):
   * kernel-weighted partial volumes, by recursive subdivision of the cells
   * the sphere cuts. The base of every lattice quadrature of LtN.
   */
  template <int dim>
  void
  kernel_weighted_cell_volumes(const Kernel                      &kernel,
                               const double                       spacing,
                               std::vector<std::array<int, dim>> &offsets,
                               std::vector<double>               &volumes);

  /**
   * The stencil of nonlocal diffusion on a square (cubic) lattice of spacing
   * `h`: offsets `xi_j = h o_j` (integer vectors `o_j != 0`) and coefficients
   * `a_j`, so that at a particle `x_i` whose whole neighbourhood is present
   *
   *   L_h u(x_i) = 2 sum_j a_j (u(x_i + xi_j) - u(x_i)).
   *
   * The base coefficients are the kernel integrated over the part of each
   * lattice cell inside the ball, `a_j^0 = int_{B_eps ∩ cell_j} gamma(|y|) dy`
   * (kernel-weighted partial volumes), computed by recursive subdivision of
   * the cells the sphere cuts. They are then corrected, with the smallest
   * change in the norm `sum (a_j - a_j^0)^2 / a_j^0`, so that the discrete
   * moments `sum_j a_j xi_j^alpha` equal the exact ones
   * `int_{B_eps} gamma(|xi|) xi^alpha dxi` for all `1 <= |alpha| <= 4` (or,
   * when the stencil is too small for that, for `|alpha| <= 2`). Exactness
   * up to degree 2 makes `L_h p = Laplace p` for every quadratic `p`
   * (the patch test); up to degree 4 it leaves the quadrature error to
   * sixth-order terms. See doc/discretization.md.
   *
   * Every particle of a lattice with a complete collar shares this stencil.
   */
  template <int dim>
  class LatticeStencil
  {
  public:
    LatticeStencil(const Kernel &kernel, const double spacing);

    /** The integer offsets `o_j` (never zero). */
    const std::vector<std::array<int, dim>> &
    offsets() const;

    /** The coefficients `a_j`. */
    const std::vector<double> &
    coefficients() const;

    /** The largest `|o_j|` in any coordinate. */
    int
    radius() const;

    /** 4 or 2: the degree up to which the moments are exact. */
    unsigned int
    exact_degree() const;

    /**
     * The exact moment `int_{B_eps} gamma(|xi|) prod_d (xi_d / eps)^alpha_d`
     * of @p kernel.
     */
    static double
    exact_moment(const Kernel                        &kernel,
                 const std::array<unsigned int, dim> &alpha);

  private:
    std::vector<std::array<int, dim>> stencil_offsets;
    std::vector<double>               stencil_coefficients;
    int                               stencil_radius = 0;
    unsigned int                      degree         = 0;
  };
} // namespace ltn

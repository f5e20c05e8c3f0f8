#pragma once

#include <deal.II/base/tensor.h>

#include <ltn/nonlocal/kernel.h>

#include <array>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The bonds of a particle of a square (cubic) lattice of spacing `h` in
   * linearized state-based peridynamics (LPS): bond vectors `xi_j = h o_j`
   * and quadrature weights `c_j`, standing for `omega(|xi|) dV` in every
   * integral of the model:
   *
   *   m = sum_j c_j |xi_j|^2,   theta = dim/m sum_j c_j xi_j . (u_j - u_i).
   *
   * The weights start as the influence function integrated over the part
   * of each lattice cell inside the horizon (kernel_weighted_cell_volumes);
   * then the smallest relative change makes the fourth moment isotropic,
   *
   *   sum_j c_j (xi_j)_a^4 / |xi_j|^2 = 3 sum_j c_j (xi_j)_a^2 (xi_j)_b^2 /
   * |xi_j|^2,
   *
   * which, with the symmetries of the lattice and `m` summed with the same
   * weights, is exactly what makes the discrete operator equal Navier–Cauchy
   * on every quadratic displacement (doc/discretization.md, 'Linearized
   * peridynamics (LPS) on particles').
   * Every particle with a complete neighbourhood shares these bonds.
   */
  template <int dim>
  class PeridynamicStencil
  {
  public:
    /**
     * @param influence the influence function `omega` (its horizon is the
     *   model's; its scale cancels out).
     * @param spacing the lattice spacing `h`.
     */
    PeridynamicStencil(const Kernel &influence, const double spacing);

    /** The integer offsets `o_j` of the bonds. */
    const std::vector<std::array<int, dim>> &
    offsets() const;

    /** The bond vectors `xi_j = h o_j`. */
    const std::vector<Tensor<1, dim>> &
    bonds() const;

    /** The weights `c_j`. */
    const std::vector<double> &
    weights() const;

    /** The weighted volume `m` of a complete neighbourhood. */
    double
    weighted_volume() const;

    /**
     * Every offset `o_j + o_k` of two bonds (and of one): the particles whose
     * displacement the operator at a particle reads through the dilatations
     * of its neighbours. The collar of an LPS lattice.
     */
    std::vector<std::array<int, dim>>
    two_bond_reach() const;

  private:
    std::vector<std::array<int, dim>> bond_offsets;
    std::vector<Tensor<1, dim>>       bond_vectors;
    std::vector<double>               bond_weights;
    double                            m = 0;
  };
} // namespace ltn

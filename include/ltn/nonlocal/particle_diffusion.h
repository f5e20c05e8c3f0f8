#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <ltn/nonlocal/kernel.h>
#include <ltn/nonlocal/lattice_rows.h>
#include <ltn/nonlocal/lattice_stencil.h>
#include <ltn/nonlocal/particle_lattice.h>
#include <ltn/nonlocal/particle_model.h>
#include <ltn/problem/blending_function.h>
#include <ltn/problem/geometry.h>

#include <optional>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * Nonlocal diffusion in 2D and 3D in strong form on particles: the centres
   * of a lattice of spacing `h` that fills `Omega_n`, plus the particles of
   * its collar that some particle of `Omega_n` reaches (ParticleLattice).
   * Each particle of `Omega_n` satisfies
   *
   *   -L_h u(x_i) = 2 sum_j a_j (u(x_i) - u(x_i + xi_j)) = f(x_i)
   *
   * with the LatticeStencil `(xi_j, a_j)`, which every particle shares
   * because the collar makes every neighbourhood complete. Collar particles
   * outside the body carry the volume constraint `u = g` (fixed); those
   * inside carry the control `theta_n`.
   *
   * Each rank owns a contiguous range of particle numbers (a slab of the
   * lattice) and reads its ghosts: the particles its rows reach, out to the
   * full horizon.
   */
  /** The blending baselines on the lattice (ParticleDiffusion::blend()). */
  enum class LatticeBlending
  {
    force,
    energy
  };

  template <int dim>
  class ParticleDiffusion : public ParticleModel<dim, LatticeStencil<dim>, 1, 1>
  {
  public:
    using Base = ParticleModel<dim, LatticeStencil<dim>, 1, 1>;
    using typename Base::LatticeIndex;

    ParticleDiffusion(const Geometry<dim> &geometry,
                      const Kernel        &kernel,
                      const double         spacing,
                      const MPI_Comm       communicator);

    /**
     * Assemble `-L_h` (its matrix, or with @p matrix_free a
     * LatticeOperator, and the surrogate for AMG), the load @p rhs and the
     * volume constraint.
     */
    void
    assemble(const Function<dim> &rhs,
             const Function<dim> &volume_data,
             const bool           matrix_free = false);

    /**
     * For the blending baselines on a lattice that fills the body
     * (doc/baseline_couplings.md, 'Blending'): assemble, in place of
     * `-L_h`, one field's rows that blend it with the classical Laplacian
     * `Lambda u(x_i) = sum_{k in N(i)} (u_i - u_k) / h^2` on the nearest
     * neighbours by the weight @p beta, as @p kind says:
     *
     * - force: `beta_i (-L_h u)_i + (1 - beta_i) (Lambda u)_i` (not
     *   symmetric where beta changes);
     * - energy: `sum_j a_j (beta_i + beta_j') (u_i - u_j') + sum_{k in
     *   N(i)} (1 - (beta_i + beta_k) / 2) (u_i - u_k) / h^2`, the gradient
     *   of the blended energy over `h^dim` (symmetric),
     *
     * with the load `beta f_n + (1 - beta) f_l` of @p nonlocal_rhs and
     * @p local_rhs and the volume constraint @p volume_data. Assembled (a
     * matrix-free operator holds the shared stencil only).
     */
    void
    assemble_blended(const LatticeBlending        kind,
                     const BlendingFunction<dim> &beta,
                     const Function<dim>         &nonlocal_rhs,
                     const Function<dim>         &local_rhs,
                     const Function<dim>         &volume_data);

    /** The row of particle @p i of the closed model. */
    void
    particle_rows(const types::global_dof_index i, ParticleRows &rows) const;

  private:
    /** What assemble_blended() blends the rows with; none: nothing. */
    struct Blending
    {
      LatticeBlending       kind;
      BlendingFunction<dim> beta;
    };
    std::optional<Blending> blending;

    using Base::lattice;
    using Base::model;
    using Base::spacing;
    using Base::stencil;
  };
} // namespace ltn

#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>

#include <ltn/base/discrete_model.h>
#include <ltn/base/field_errors.h>
#include <ltn/nonlocal/kernel.h>
#include <ltn/nonlocal/lattice_operator.h>
#include <ltn/nonlocal/lattice_rows.h>
#include <ltn/nonlocal/particle_lattice.h>
#include <ltn/nonlocal/particle_model.h>
#include <ltn/nonlocal/peridynamic_stencil.h>
#include <ltn/problem/crack.h>
#include <ltn/problem/geometry.h>

#include <map>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * Linearized state-based peridynamics (LPS) in 2D and 3D in strong form on
   * particles: the centres of a lattice of spacing `h` filling `Omega_n`,
   * plus a collar two horizons deep (the operator at a particle reads the
   * dilatations of its neighbours, each of which needs its own complete
   * neighbourhood). With the bonds `(xi_j, c_j)` of the PeridynamicStencil,
   * bonds that cross a crack removed, and per particle the weighted volume
   * `m_i = sum_{j intact} c_j |xi_j|^2`, a particle `x_i` of `Omega_n`
   * satisfies
   *
   *   -sum_{j intact} c_j [ A (theta_i/m_i + theta_j/m_j) xi
   *       + B (1/m_i + 1/m_j) (xi (x) xi)/|xi|^2 (u_j - u_i) ] = b(x_i),
   *   theta_i = dim/m_i sum_{j intact} c_j xi . (u_j - u_i),
   *
   * with `A = dim (lambda - mu)`, `B = dim (dim + 2) mu` from the Lamé
   * constants of the dimension (doc/discretization.md, 'Linearized
   * peridynamics (LPS) on particles').
   *
   * The dilatation is an unknown of its own: each particle carries `dim`
   * displacement components and `theta` (degree of freedom
   * `(dim + 1) n + c`). This keeps the matrix to one horizon of neighbours
   * per row instead of two. The dilatation's equation holds at every
   * particle with a complete neighbourhood (`Omega_n` and the inner collar);
   * elsewhere `theta` is fixed to zero, unused. Displacements of collar
   * particles outside the body carry the volume constraint `u = g`, those
   * inside the control `theta_n`.
   *
   * Each rank owns a contiguous range of particles (a slab of the lattice)
   * with all their degrees of freedom.
   */
  template <int dim>
  class ParticleElasticity
    : public ParticleModel<dim, PeridynamicStencil<dim>, dim + 1, dim>
  {
  public:
    /**
     * Per particle the displacement and `theta`, `dim + 1` degrees of
     * freedom; the field the coupling compares is the displacement.
     */
    using Base = ParticleModel<dim, PeridynamicStencil<dim>, dim + 1, dim>;
    using Base::dof;
    using Base::n_components;
    using typename Base::LatticeIndex;

    ParticleElasticity(const Geometry<dim>           &geometry,
                       const Kernel                  &influence,
                       const double                   spacing,
                       const double                   lambda,
                       const double                   mu,
                       const std::vector<Crack<dim>> &cracks,
                       const MPI_Comm                 communicator);

    using Rows = ParticleRows;

    /**
     * Assemble the model with the body force @p body_force and the volume
     * constraint @p volume_data (both `dim` components): its matrix, or
     * with @p matrix_free a LatticeOperator; and the surrogate, the
     * eliminated dilatations and the rigid translations its iterative
     * solver needs.
     */
    void
    assemble(const Function<dim> &body_force,
             const Function<dim> &volume_data,
             const bool           matrix_free = false);

    /** The row of particle @p n of the closed model, per component. */
    void
    particle_rows(const types::global_dof_index n, Rows &rows) const;

    /**
     * Which rows of the particle at @p index (bit `c` for component `c`)
     * are the rows every particle far from cracks and the collar shares
     * (LatticeOperator): none if one of its bonds is cut; the dilatation's
     * if its neighbourhood is complete; the displacement's in `Omega_n`
     * unless a neighbour has a cut bond (its weighted volume differs).
     */
    unsigned int
    shared_rows(const LatticeIndex &index) const;

    /**
     * The form of the other rows of particles with a complete
     * neighbourhood, cut bonds or not: the shared ones scaled by the
     * weighted volumes of the particle and its partners
     * (LatticeOperator computes them, not stores them).
     */
    ScaledBondRows<dim>
    scaled_bond_rows() const;

    /** The horizon `eps`. */
    double
    horizon() const;

    /**
     * Which bonds of the particle at @p index are intact (not cut by a
     * crack, and reaching a particle of the lattice); return the particle's
     * weighted volume over them.
     */
    double
    intact_bonds(const LatticeIndex &index, std::vector<bool> &intact) const;

    /** Per particle of this rank: the fraction of its bonds cracks cut. */
    std::vector<double>
    owned_broken_bond_fractions() const;

    /** The opening of a crack, sampled at pairs of particles. */
    struct CrackOpening
    {
      /** The points of the crack between the two particles of a pair. */
      std::vector<Point<dim>> points;
      /** `n . (u_+ - u_-)`: the normal jump of the displacement. */
      std::vector<double> opening;
    };

    /**
     * The opening of crack @p k in @p field (ghosted or not; each rank reads
     * its own particles) at the pairs of particles that face each other
     * across it half a spacing away, on all ranks, ordered along the crack.
     * Empty when the crack does not lie halfway between lattice planes.
     */
    CrackOpening
    crack_opening(const TrilinosWrappers::MPI::Vector &field,
                  const unsigned int                   k) const;

  private:
    using Base::geometry;
    using Base::lattice;
    using Base::model;
    using Base::owned_particles;
    using Base::spacing;
    using Base::stencil;

    /** Does the particle at @p index have all its bonds' neighbours? */
    bool
    complete(const LatticeIndex &index) const;

    /** Is @p x close enough to a crack for one of its bonds to cross it? */
    bool
    near_crack(const Point<dim> &x) const;

    /** Is the bond from @p x to @p y cut by a crack? */
    bool
    is_cut(const Point<dim> &x, const Point<dim> &y) const;

    const double                  eps;
    const double                  coefficient_A;
    const double                  coefficient_B;
    const std::vector<Crack<dim>> cracks;
    /** The cracks' boxes widened by the horizon: where bonds can be cut. */
    std::vector<Box<dim>> crack_neighbourhoods;
    /** Per particle of the lattice: is one of its bonds cut? */
    std::vector<bool> has_cut_bond;
    /**
     * The weighted volume of each particle with a cut bond, found with its
     * bonds once: a row reads those of all its partners, and finding them
     * anew took the square of the bonds per row near a crack.
     */
    std::map<types::global_dof_index, double> cut_weighted_volume;
  };
} // namespace ltn

#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/base/field_errors.h>
#include <ltn/nonlocal/kernel.h>
#include <ltn/nonlocal/particle_lattice.h>
#include <ltn/problem/geometry.h>

#include <functional>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * What the particle models (ParticleDiffusion, ParticleElasticity) share:
   * the particles of a lattice of spacing `h` that fills `Omega_n` and
   * reaches out of it as far as the `Stencil`'s rows read (ParticleLattice),
   * each rank owning a contiguous range of them (a slab of the lattice) with
   * all their `n_dofs` degrees of freedom (`n_dofs n + c`), the first
   * `n_field` of which are the field the coupling compares; their roles
   * (free in `Omega_n`, the control `theta_n` in the collar inside the body,
   * the volume constraint outside), the load, the errors, and what the
   * output reads. The physics assembles the operator.
   */
  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  class ParticleModel
  {
  public:
    using LatticeIndex = typename ParticleLattice<dim>::LatticeIndex;

    /** Degrees of freedom per particle. */
    static constexpr unsigned int n_components = n_dofs;

    /** The field components the coupling compares: the first ones. */
    static constexpr unsigned int n_field_components = n_field;

    /** The degree of freedom of component @p c of particle @p number. */
    static types::global_dof_index
    dof(const types::global_dof_index number, const unsigned int c)
    {
      return n_components * number + c;
    }

    const DiscreteModel &
    get_model() const;

    const ParticleLattice<dim> &
    get_lattice() const;

    /** The bonds of a particle with a complete neighbourhood. */
    std::size_t
    bonds_per_particle() const;

    /** The role of the field components of the particle at @p index. */
    DofRole
    role(const LatticeIndex &index) const;

    /** The volume `h^dim` of every particle. */
    double
    particle_volume() const;

    /** The positions of this rank's particles, in their order. */
    std::vector<Point<dim>>
    owned_positions() const;

    /** The region tags of this rank's particles. */
    std::vector<Region>
    owned_regions() const;

    /**
     * Errors of the field components of @p field against @p exact (with as
     * many components) over the particles of `Omega_n` on all ranks:
     * `l2^2 = sum_i h^dim |e_i|^2`, `linf = max_{i,c} |e_ic|`.
     */
    ErrorNorms
    errors(const TrilinosWrappers::MPI::Vector &field,
           const Function<dim>                 &exact) const;

  protected:
    /** Not deleted through this base. */
    ~ParticleModel() = default;

    /**
     * The particles of @p geometry's `Omega_n` at @p spacing with the
     * stencil `Stencil(kernel, spacing)`, out to the offsets
     * @p reach returns of it, distributed over @p communicator; the roles of
     * their field components. @p collar_depth is how far out of `Omega_n`
     * the rows read (the region tags' collar).
     */
    ParticleModel(const Geometry<dim> &geometry,
                  const Kernel        &kernel,
                  const double         spacing,
                  const double         collar_depth,
                  std::vector<LatticeIndex> (*reach)(const Stencil &),
                  const MPI_Comm communicator);

    /**
     * `model.rhs`: @p load at the free field components, @p volume_data at
     * the fixed ones, zero elsewhere.
     */
    void
    assemble_load(const Function<dim> &load, const Function<dim> &volume_data);

    /**
     * `model.lattice`: this rank's particles as nodes, and their lattice
     * surrogate (assemble_lattice_surrogate()) with the physics' @p diagonal,
     * @p long_wave_modulus, @p collar_trace and @p is_cut, built when a
     * solver first asks for it.
     */
    void
    offer_lattice(
      const double               diagonal,
      const double               long_wave_modulus,
      const std::vector<double> &collar_trace,
      std::function<bool(const Point<dim> &, const Point<dim> &)> is_cut);

    const Geometry<dim>       &geometry;
    const double               spacing;
    const double               collar_depth;
    const Stencil              stencil;
    const ParticleLattice<dim> lattice;
    IndexSet                   owned_particles;
    DiscreteModel              model;
  };
} // namespace ltn

#include <ltn/base/partition.h>
#include <ltn/nonlocal/lattice_stencil.h>
#include <ltn/nonlocal/lattice_surrogate.h>
#include <ltn/nonlocal/particle_model.h>
#include <ltn/nonlocal/peridynamic_stencil.h>

#include <cmath>

namespace ltn
{
  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  ParticleModel<dim, Stencil, n_dofs, n_field>::ParticleModel(
    const Geometry<dim> &geometry,
    const Kernel        &kernel,
    const double         spacing,
    const double         collar_depth,
    std::vector<LatticeIndex> (*reach)(const Stencil &),
    const MPI_Comm communicator)
    : geometry(geometry)
    , spacing(spacing)
    , collar_depth(collar_depth)
    , stencil(kernel, spacing)
    , lattice(geometry.nonlocal_region(), spacing, reach(stencil))
  {
    owned_particles = even_partition(lattice.n_particles(), communicator);
    const types::global_dof_index n_dofs_all =
      n_components * lattice.n_particles();
    model.communicator = communicator;
    model.owned        = IndexSet(n_dofs_all);
    if (owned_particles.n_elements() > 0)
      model.owned.add_range(dof(*owned_particles.begin(), 0),
                            dof(owned_particles.nth_index_in_set(
                                  owned_particles.n_elements() - 1),
                                n_components));
    model.controls = IndexSet(n_dofs_all);
    model.fixed    = IndexSet(n_dofs_all);
    for (const auto n : owned_particles)
      {
        const DofRole r = role(lattice.index(n));
        for (unsigned int c = 0; c < n_field_components; ++c)
          if (r == DofRole::control)
            model.controls.add_index(dof(n, c));
          else if (r == DofRole::fixed)
            model.fixed.add_index(dof(n, c));
      }
    model.controls.compress();
    model.fixed.compress();
    model.locate_controls<dim>(
      [&](const types::global_dof_index i) {
        return lattice.position(lattice.index(i / n_components));
      },
      [](const types::global_dof_index i) {
        return static_cast<unsigned int>(i % n_components);
      });
  }



  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  void
  ParticleModel<dim, Stencil, n_dofs, n_field>::assemble_load(
    const Function<dim> &load,
    const Function<dim> &volume_data)
  {
    model.rhs = model.new_vector();
    for (const auto n : owned_particles)
      {
        const Point<dim> x = lattice.position(lattice.index(n));
        for (unsigned int c = 0; c < n_field_components; ++c)
          switch (model.role(dof(n, c)))
            {
              case DofRole::free:
                model.rhs(dof(n, c)) = load.value(x, c);
                break;
              case DofRole::fixed:
                model.rhs(dof(n, c)) = volume_data.value(x, c);
                break;
              case DofRole::control:
                break;
            }
      }
    model.rhs.compress(VectorOperation::insert);
  }



  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  void
  ParticleModel<dim, Stencil, n_dofs, n_field>::offer_lattice(
    const double               diagonal,
    const double               long_wave_modulus,
    const std::vector<double> &collar_trace,
    std::function<bool(const Point<dim> &, const Point<dim> &)> is_cut)
  {
    std::vector<std::array<double, 3>> node_positions;
    for (const auto n : owned_particles)
      node_positions.push_back(
        DiscreteModel::padded<dim>(lattice.position(lattice.index(n))));
    model.lattice = std::make_shared<const ModelLattice>(
      n_components,
      std::move(node_positions),
      [this, diagonal, long_wave_modulus, collar_trace, is_cut](
        LatticeSurrogate &surrogate) {
        assemble_lattice_surrogate<dim>(lattice,
                                        owned_particles,
                                        n_field_components,
                                        diagonal,
                                        long_wave_modulus,
                                        collar_trace,
                                        spacing,
                                        is_cut,
                                        model.communicator,
                                        surrogate);
      });
  }



  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  const DiscreteModel &
  ParticleModel<dim, Stencil, n_dofs, n_field>::get_model() const
  {
    return model;
  }



  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  const ParticleLattice<dim> &
  ParticleModel<dim, Stencil, n_dofs, n_field>::get_lattice() const
  {
    return lattice;
  }



  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  std::size_t
  ParticleModel<dim, Stencil, n_dofs, n_field>::bonds_per_particle() const
  {
    return stencil.offsets().size();
  }



  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  DofRole
  ParticleModel<dim, Stencil, n_dofs, n_field>::role(
    const LatticeIndex &index) const
  {
    return lattice.role(index, geometry);
  }



  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  double
  ParticleModel<dim, Stencil, n_dofs, n_field>::particle_volume() const
  {
    return std::pow(spacing, dim);
  }



  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  std::vector<Point<dim>>
  ParticleModel<dim, Stencil, n_dofs, n_field>::owned_positions() const
  {
    std::vector<Point<dim>> result;
    for (const auto n : owned_particles)
      result.push_back(lattice.position(lattice.index(n)));
    return result;
  }



  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  std::vector<Region>
  ParticleModel<dim, Stencil, n_dofs, n_field>::owned_regions() const
  {
    std::vector<Region> result;
    for (const auto &x : owned_positions())
      result.push_back(geometry.nonlocal_region_of(x, collar_depth));
    return result;
  }



  template <int dim,
            typename Stencil,
            unsigned int n_dofs,
            unsigned int n_field>
  ErrorNorms
  ParticleModel<dim, Stencil, n_dofs, n_field>::errors(
    const TrilinosWrappers::MPI::Vector &field,
    const Function<dim>                 &exact) const
  {
    ErrorNorms errors;
    for (const auto n : owned_particles)
      {
        const LatticeIndex index = lattice.index(n);
        if (!lattice.inside(index))
          continue;
        const Point<dim> x = lattice.position(index);
        for (unsigned int c = 0; c < n_field_components; ++c)
          {
            const double e = field(dof(n, c)) - exact.value(x, c);
            errors.l2_squared += particle_volume() * e * e;
            errors.add_pointwise(e);
          }
      }
    return errors.over_all_ranks(model.communicator);
  }

  template class ParticleModel<2, LatticeStencil<2>, 1, 1>;
  template class ParticleModel<3, LatticeStencil<3>, 1, 1>;
  template class ParticleModel<2, PeridynamicStencil<2>, 3, 2>;
  template class ParticleModel<3, PeridynamicStencil<3>, 4, 3>;
} // namespace ltn

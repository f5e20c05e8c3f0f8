#include <ltn/base/partition.h>
#include <ltn/nonlocal/collar_trace.h>
#include <ltn/nonlocal/lattice_operator.h>
#include <ltn/nonlocal/lattice_surrogate.h>
#include <ltn/nonlocal/particle_diffusion.h>

#include <cmath>

namespace ltn
{
  template <int dim>
  ParticleDiffusion<dim>::ParticleDiffusion(const Geometry<dim> &geometry,
                                            const Kernel        &kernel,
                                            const double         spacing,
                                            const MPI_Comm       communicator)
    : geometry(geometry)
    , kernel(kernel)
    , spacing(spacing)
    , stencil(kernel, spacing)
    , lattice(geometry.nonlocal_region, spacing, stencil.offsets())
  {
    model.communicator = communicator;
    model.owned        = even_partition(lattice.n_particles(), communicator);
    model.controls     = IndexSet(lattice.n_particles());
    model.fixed        = IndexSet(lattice.n_particles());
    for (const auto i : model.owned)
      {
        const DofRole r = role(lattice.index(i));
        if (r == DofRole::control)
          model.controls.add_index(i);
        else if (r == DofRole::fixed)
          model.fixed.add_index(i);
      }
    model.controls.compress();
    model.fixed.compress();
    model.locate_controls<dim>(
      [&](const types::global_dof_index i) {
        return lattice.position(lattice.index(i));
      },
      [](const types::global_dof_index) { return 0u; });
    model.locate_nodes<dim>(model.owned, [&](const types::global_dof_index n) {
      return lattice.position(lattice.index(n));
    });
  }



  template <int dim>
  void
  ParticleDiffusion<dim>::particle_rows(const types::global_dof_index i,
                                        ParticleRows &rows) const
  {
    const auto &offsets      = stencil.offsets();
    const auto &coefficients = stencil.coefficients();
    rows.resize(1);
    auto &row = rows[0];
    row.assign(1, {i, 1.});
    const LatticeIndex index = lattice.index(i);
    if (!lattice.inside(index))
      return;
    row[0].second = 0;
    for (std::size_t k = 0; k < offsets.size(); ++k)
      {
        LatticeIndex neighbour = index;
        for (unsigned int d = 0; d < dim; ++d)
          neighbour[d] += offsets[k][d];
        const auto j = lattice.number(neighbour);
        Assert(j != ParticleLattice<dim>::invalid, ExcInternalError());
        row.emplace_back(j, -2 * coefficients[k]);
        row[0].second += 2 * coefficients[k];
      }
  }



  template <int dim>
  void
  ParticleDiffusion<dim>::assemble(const Function<dim> &rhs,
                                   const Function<dim> &volume_data,
                                   const bool           matrix_free)
  {
    // Every particle of Omega_n has the stencil's row.
    store_particle_operator<dim>(
      lattice,
      stencil.offsets(),
      1,
      0,
      model.owned,
      [this](const LatticeIndex &index) {
        return lattice.inside(index) ? 1u : 0u;
      },
      [this](const types::global_dof_index i, ParticleRows &rows) {
        particle_rows(i, rows);
      },
      matrix_free,
      model);

    double diagonal = 0;
    for (const double a : stencil.coefficients())
      diagonal += 2 * a;
    // The stencil projected on an axis: the weight of the bonds that reach
    // m layers along it.
    const std::vector<double> projected =
      axis_projection(stencil.offsets(), [&](const std::size_t k) {
        return stencil.coefficients()[k];
      });
    assemble_lattice_surrogate<dim>(
      lattice,
      model.owned,
      1,
      1,
      diagonal,
      1., // the moment conditions make the long-wave limit the Laplacian
      collar_trace_weights(projected),
      spacing,
      [](const Point<dim> &, const Point<dim> &) { return false; },
      model);
    model.eliminated = IndexSet(model.owned.size());
    // a_j = a_{-j}: the free block is symmetric, and positive definite
    // (doc/discretization.md, section 11).
    model.symmetric_free_block = true;

    model.rhs = model.new_vector();
    for (const auto i : model.owned)
      {
        const Point<dim> x = lattice.position(lattice.index(i));
        switch (model.role(i))
          {
            case DofRole::free:
              model.rhs(i) = rhs.value(x);
              break;
            case DofRole::fixed:
              model.rhs(i) = volume_data.value(x);
              break;
            case DofRole::control:
              break;
          }
      }
    model.rhs.compress(VectorOperation::insert);
  }



  template <int dim>
  const DiscreteModel &
  ParticleDiffusion<dim>::get_model() const
  {
    return model;
  }



  template <int dim>
  const ParticleLattice<dim> &
  ParticleDiffusion<dim>::get_lattice() const
  {
    return lattice;
  }



  template <int dim>
  DofRole
  ParticleDiffusion<dim>::role(const LatticeIndex &index) const
  {
    return lattice.role(index, geometry);
  }



  template <int dim>
  double
  ParticleDiffusion<dim>::particle_volume() const
  {
    return std::pow(spacing, dim);
  }



  template <int dim>
  std::vector<Point<dim>>
  ParticleDiffusion<dim>::owned_positions() const
  {
    std::vector<Point<dim>> result;
    for (const auto i : model.owned)
      result.push_back(lattice.position(lattice.index(i)));
    return result;
  }



  template <int dim>
  std::vector<Region>
  ParticleDiffusion<dim>::owned_regions() const
  {
    std::vector<Region> result;
    for (const auto &x : owned_positions())
      result.push_back(geometry.nonlocal_region_of(x, kernel.horizon()));
    return result;
  }



  template <int dim>
  ErrorNorms
  ParticleDiffusion<dim>::errors(const TrilinosWrappers::MPI::Vector &field,
                                 const Function<dim> &exact) const
  {
    ErrorNorms errors;
    for (const auto i : model.owned)
      if (model.role(i) == DofRole::free)
        {
          const double e =
            field(i) - exact.value(lattice.position(lattice.index(i)));
          errors.l2_squared += particle_volume() * e * e;
          errors.add_pointwise(e);
        }
    return errors.over_all_ranks(model.communicator);
  }



  template class ParticleDiffusion<2>;
  template class ParticleDiffusion<3>;
} // namespace ltn

#include <ltn/nonlocal/collar_trace.h>
#include <ltn/nonlocal/lattice_operator.h>
#include <ltn/nonlocal/particle_diffusion.h>

namespace ltn
{
  template <int dim>
  ParticleDiffusion<dim>::ParticleDiffusion(const Geometry<dim> &geometry,
                                            const Kernel        &kernel,
                                            const double         spacing,
                                            const MPI_Comm       communicator)
    : Base(
        geometry,
        kernel,
        spacing,
        kernel.horizon(),
        [](const LatticeStencil<dim> &stencil) { return stencil.offsets(); },
        communicator)
  {}



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
    this->offer_lattice(
      diagonal,
      1., // the moment conditions make the long-wave limit the Laplacian
      collar_trace_weights(projected),
      [](const Point<dim> &, const Point<dim> &) { return false; });
    model.eliminated = IndexSet(model.owned.size());
    // a_j = a_{-j}: the free block is symmetric, and positive definite
    // (doc/discretization.md, 'Why the system is nonsingular').
    model.symmetric_free_block = true;

    this->assemble_load(rhs, volume_data);
  }



  template class ParticleDiffusion<2>;
  template class ParticleDiffusion<3>;
} // namespace ltn

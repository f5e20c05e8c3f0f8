#include <deal.II/base/function.h>

#include <ltn/nonlocal/collar_trace.h>
#include <ltn/nonlocal/lattice_operator.h>
#include <ltn/nonlocal/particle_diffusion.h>

#include <algorithm>

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
    row[0].second   = 0;
    const auto beta = [&](const LatticeIndex &at) {
      return blending->beta.value(lattice.position(at));
    };
    const double beta_i = blending ? beta(index) : 1.;
    // The bond to the particle at @p at, with @p weight; the stencil's
    // bonds are distinct, a later bond (@p repeated) may be one of them.
    const auto add =
      [&](const LatticeIndex &at, const double weight, const bool repeated) {
        const auto j = lattice.number(at);
        Assert(j != ParticleLattice<dim>::invalid, ExcInternalError());
        const auto entry =
          repeated ? std::find_if(row.begin() + 1,
                                  row.end(),
                                  [j](const auto &e) { return e.first == j; }) :
                     row.end();
        if (entry == row.end())
          row.emplace_back(j, -weight);
        else
          entry->second -= weight;
        row[0].second += weight;
      };
    // Bond j's coefficient in the row: 2 a_j unblended and blended by
    // force, a_j (beta_i + beta_j) blended by energy.
    for (std::size_t k = 0; k < offsets.size(); ++k)
      {
        LatticeIndex neighbour = index;
        for (unsigned int d = 0; d < dim; ++d)
          neighbour[d] += offsets[k][d];
        add(neighbour,
            !blending ? 2 * coefficients[k] :
            blending->kind == LatticeBlending::force ?
                        beta_i * 2 * coefficients[k] :
                        coefficients[k] * (beta_i + beta(neighbour)),
            false);
      }
    if (!blending)
      return;
    // The classical Laplacian on the nearest neighbours, weighted by
    // 1 - beta_i (force) or by the bond's 1 - (beta_i + beta_k) / 2.
    for (unsigned int d = 0; d < dim; ++d)
      for (const int step : {-1, 1})
        {
          LatticeIndex neighbour = index;
          neighbour[d] += step;
          const double local_weight = blending->kind == LatticeBlending::force ?
                                        1 - beta_i :
                                        1 - 0.5 * (beta_i + beta(neighbour));
          // The nearest neighbours are bonds of the stencil too: their
          // weights add.
          add(neighbour, local_weight / (spacing * spacing), true);
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



  template <int dim>
  void
  ParticleDiffusion<dim>::assemble_blended(const LatticeBlending        kind,
                                           const BlendingFunction<dim> &beta,
                                           const Function<dim> &nonlocal_rhs,
                                           const Function<dim> &local_rhs,
                                           const Function<dim> &volume_data)
  {
    blending.emplace(Blending{kind, beta});
    // The rows are the blended ones; their load too.
    const ScalarFunctionFromFunctionObject<dim> load([&](const Point<dim> &x) {
      const double b = beta.value(x);
      return b * nonlocal_rhs.value(x) + (1 - b) * local_rhs.value(x);
    });
    assemble(load, volume_data, false);
    // Force blending's rows differ by bond where beta changes.
    model.symmetric_free_block = kind == LatticeBlending::energy;
  }



  template class ParticleDiffusion<2>;
  template class ParticleDiffusion<3>;
} // namespace ltn

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ltn/nonlocal/lattice_surrogate.h>

namespace ltn
{
  template <int dim>
  void
  assemble_lattice_surrogate(
    const ParticleLattice<dim> &lattice,
    const IndexSet             &owned_particles,
    const unsigned int          n_field_components,
    const double                diagonal,
    const double                long_wave_modulus,
    const std::vector<double>  &collar_trace,
    const double                spacing,
    const std::function<bool(const Point<dim> &, const Point<dim> &)> &is_cut,
    const MPI_Comm    communicator,
    LatticeSurrogate &surrogate)
  {
    using LatticeIndex    = typename ParticleLattice<dim>::LatticeIndex;
    const double coupling = diagonal / (2 * dim);
    // Per particle of Omega_n: the surrogate's numbers of its axis
    // neighbours in Omega_n and its diagonal weight (the number of uncut
    // axis bonds, collar neighbours included: their values are fixed).
    // Also, where an axis neighbour lies in the collar, the collar's
    // particles on that axis, layer by layer, with their trace weights.
    std::vector<types::global_dof_index>                    neighbours;
    std::vector<std::pair<types::global_dof_index, double>> collar_neighbours;
    const auto axis_bonds = [&](const auto p) {
      neighbours.clear();
      collar_neighbours.clear();
      const LatticeIndex index = lattice.index(p);
      unsigned int       bonds = 0;
      for (unsigned int d = 0; d < dim; ++d)
        for (const int step : {-1, 1})
          {
            LatticeIndex q = index;
            q[d] += step;
            if (is_cut(lattice.position(index), lattice.position(q)))
              continue;
            ++bonds;
            if (lattice.inside(q))
              neighbours.push_back(lattice.inside_number(q));
            else
              for (unsigned int m = 0; m < collar_trace.size(); ++m)
                {
                  LatticeIndex layer = index;
                  layer[d] += (m + 1) * step;
                  const auto number = lattice.number(layer);
                  // The collar is at least as deep as the stencil reaches
                  // (checked in release builds too: Epetra drops an invalid
                  // column on one rank and throws on two).
                  AssertThrow(number != ParticleLattice<dim>::invalid &&
                                !lattice.inside(layer),
                              ExcInternalError());
                  if (!is_cut(lattice.position(index), lattice.position(layer)))
                    collar_neighbours.emplace_back(number, collar_trace[m]);
                }
          }
      return bonds;
    };

    // Rows for the particles of Omega_n only: the collar's would be
    // identities, a fifth of the rows of the 10^6 bar's multigrid
    // hierarchy. A rank's particles of Omega_n have contiguous numbers
    // among those of Omega_n (ParticleLattice::inside_number).
    surrogate.nodes.clear();
    IndexSet rows(lattice.n_inside());
    for (const auto p : owned_particles)
      if (const LatticeIndex index = lattice.index(p); lattice.inside(index))
        {
          rows.add_index(lattice.inside_number(index));
          surrogate.nodes.push_back(owned_particles.index_within_set(p));
        }
    rows.compress();
    AssertThrow(rows.is_contiguous(), ExcInternalError());

    // The surrogate and C, the same bonds' weights to the collar spread
    // over its layers, from one pass over the axis bonds for the patterns
    // and one for the values.
    DynamicSparsityPattern dsp(rows.size(), rows.size(), rows);
    DynamicSparsityPattern collar_dsp(rows.size(), lattice.n_particles(), rows);
    for (const auto p : owned_particles)
      if (const LatticeIndex index = lattice.index(p); lattice.inside(index))
        {
          const auto row = lattice.inside_number(index);
          dsp.add(row, row);
          axis_bonds(p);
          for (const auto q : neighbours)
            dsp.add(row, q);
          for (const auto &[q, weight] : collar_neighbours)
            collar_dsp.add(row, q);
        }
    surrogate.matrix.reinit(rows, rows, dsp, communicator);
    surrogate.collar.reinit(rows, owned_particles, collar_dsp, communicator);
    for (const auto p : owned_particles)
      if (const LatticeIndex index = lattice.index(p); lattice.inside(index))
        {
          const auto row = lattice.inside_number(index);
          surrogate.matrix.set(row, row, coupling * axis_bonds(p));
          for (const auto q : neighbours)
            surrogate.matrix.set(row, q, -coupling);
          for (const auto &[q, weight] : collar_neighbours)
            surrogate.collar.set(row, q, coupling * weight);
        }
    surrogate.matrix.compress(VectorOperation::insert);
    surrogate.collar.compress(VectorOperation::insert);
    surrogate.components = n_field_components;
    surrogate.dimension  = dim;
    surrogate.long_wave_ratio =
      long_wave_modulus / (diagonal * spacing * spacing / (2 * dim));
  }

#define LTN_INSTANTIATE(dim)                                             \
  template void assemble_lattice_surrogate<dim>(                         \
    const ParticleLattice<dim> &,                                        \
    const IndexSet &,                                                    \
    unsigned int,                                                        \
    double,                                                              \
    double,                                                              \
    const std::vector<double> &,                                         \
    double,                                                              \
    const std::function<bool(const Point<dim> &, const Point<dim> &)> &, \
    MPI_Comm,                                                            \
    LatticeSurrogate &);
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

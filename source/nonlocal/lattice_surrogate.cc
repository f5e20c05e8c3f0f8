#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ltn/nonlocal/lattice_surrogate.h>

namespace ltn
{
  template <int dim>
  void
  assemble_lattice_surrogate(
    const ParticleLattice<dim> &lattice,
    const IndexSet             &owned_particles,
    const unsigned int          n_components,
    const unsigned int          n_field_components,
    const double                diagonal,
    const double                long_wave_modulus,
    const std::vector<double>  &collar_trace,
    const double                spacing,
    const std::function<bool(const Point<dim> &, const Point<dim> &)> &is_cut,
    DiscreteModel                                                     &model)
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
    model.surrogate_nodes.clear();
    IndexSet rows(lattice.n_inside());
    for (const auto p : owned_particles)
      if (const LatticeIndex index = lattice.index(p); lattice.inside(index))
        {
          rows.add_index(lattice.inside_number(index));
          model.surrogate_nodes.push_back(owned_particles.index_within_set(p));
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
    model.surrogate.reinit(rows, rows, dsp, model.communicator);
    model.surrogate_collar.reinit(rows,
                                  owned_particles,
                                  collar_dsp,
                                  model.communicator);
    for (const auto p : owned_particles)
      if (const LatticeIndex index = lattice.index(p); lattice.inside(index))
        {
          const auto row = lattice.inside_number(index);
          model.surrogate.set(row, row, coupling * axis_bonds(p));
          for (const auto q : neighbours)
            model.surrogate.set(row, q, -coupling);
          for (const auto &[q, weight] : collar_neighbours)
            model.surrogate_collar.set(row, q, coupling * weight);
        }
    model.surrogate.compress(VectorOperation::insert);
    model.surrogate_collar.compress(VectorOperation::insert);
    // Measured optimum ('Iterative model solvers'): 0.6 for 2D diffusion
    // (eps = 3h), 2D
    // LPS with a crack (eps = 2h) and the 3D cracked bar (eps = 2h) alike.
    // The two terms overlap at wavelengths between h and eps, hence less
    // than 1.
    const double overlap_factor = 0.6;
    model.short_wave_weight     = overlap_factor * long_wave_modulus /
                              (diagonal * spacing * spacing / (2 * dim));
    model.node_dofs            = n_components;
    model.surrogate_components = n_field_components;
    // Measured ('Iterative model solvers', "The hierarchy's size";
    // ModelPreconditioner).
    model.surrogate_coarsest_rows = dim == 2 ? 2000 : 200;
  }

  template void
  assemble_lattice_surrogate<2>(
    const ParticleLattice<2> &,
    const IndexSet &,
    unsigned int,
    unsigned int,
    double,
    double,
    const std::vector<double> &,
    double,
    const std::function<bool(const Point<2> &, const Point<2> &)> &,
    DiscreteModel &);
  template void
  assemble_lattice_surrogate<3>(
    const ParticleLattice<3> &,
    const IndexSet &,
    unsigned int,
    unsigned int,
    double,
    double,
    const std::vector<double> &,
    double,
    const std::function<bool(const Point<3> &, const Point<3> &)> &,
    DiscreteModel &);
} // namespace ltn

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
    const std::function<bool(const Point<dim> &, const Point<dim> &)> &is_cut,
    DiscreteModel                                                     &model)
  {
    using LatticeIndex    = typename ParticleLattice<dim>::LatticeIndex;
    const double coupling = diagonal / (2 * dim);
    // Per particle of Omega_n: its free axis neighbours and its diagonal
    // weight (the number of uncut axis bonds).
    std::vector<types::global_dof_index> neighbours;
    const auto                           axis_bonds = [&](const auto p) {
      neighbours.clear();
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
              neighbours.push_back(lattice.number(q));
          }
      return bonds;
    };

    const auto             n_particles = owned_particles.size();
    DynamicSparsityPattern dsp(n_particles, n_particles, owned_particles);
    for (const auto p : owned_particles)
      {
        dsp.add(p, p);
        if (lattice.inside(lattice.index(p)))
          {
            axis_bonds(p);
            for (const auto q : neighbours)
              dsp.add(p, q);
          }
      }
    model.surrogate.reinit(owned_particles,
                           owned_particles,
                           dsp,
                           model.communicator);
    for (const auto p : owned_particles)
      {
        if (!lattice.inside(lattice.index(p)))
          {
            model.surrogate.set(p, p, 1.);
            continue;
          }
        model.surrogate.set(p, p, coupling * axis_bonds(p));
        for (const auto q : neighbours)
          model.surrogate.set(p, q, -coupling);
      }
    model.surrogate.compress(VectorOperation::insert);
    model.node_dofs            = n_components;
    model.surrogate_components = n_field_components;
  }

  template void
  assemble_lattice_surrogate<2>(
    const ParticleLattice<2> &,
    const IndexSet &,
    unsigned int,
    unsigned int,
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
    const std::function<bool(const Point<3> &, const Point<3> &)> &,
    DiscreteModel &);
} // namespace ltn

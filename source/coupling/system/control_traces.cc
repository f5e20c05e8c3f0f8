#include <deal.II/fe/mapping_q1.h>

#include <ltn/coupling/system/control_traces.h>
#include <ltn/coupling/system/fe_component_row.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace ltn
{
  namespace
  {
    /**
     * Per owned control of @p model, in the order of its controls: its
     * degree of freedom, position and component.
     */
    template <int dim, typename F>
    void
    for_each_owned_control(const DiscreteModel &model, const F &f)
    {
      unsigned int k = 0;
      for (const auto i : model.controls)
        {
          Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = model.control_positions[k][d];
          f(i, x, model.control_components[k]);
          ++k;
        }
    }

    /**
     * The weights of the Lagrange polynomials on @p nodes at @p x.
     */
    std::vector<double>
    lagrange_weights(const std::vector<double> &nodes, const double x)
    {
      std::vector<double> weights(nodes.size(), 1.);
      for (std::size_t j = 0; j < nodes.size(); ++j)
        for (std::size_t m = 0; m < nodes.size(); ++m)
          if (m != j)
            weights[j] *= (x - nodes[m]) / (nodes[j] - nodes[m]);
      return weights;
    }
  } // namespace



  void
  add_control_traces(OverlapQuadrature<1>     &overlap,
                     const NonlocalWeakForm1D &nonlocal,
                     const DiscreteModel      &local_model,
                     const DoFHandler<1>      &local_dofs)
  {
    const MappingQ1<1>  mapping;
    const auto         &nonlocal_dofs = nonlocal.get_dof_handler();
    GridTools::Cache<1> nonlocal_cache(nonlocal_dofs.get_triangulation(),
                                       mapping);
    GridTools::Cache<1> local_cache(local_dofs.get_triangulation(), mapping);
    for_each_owned_control<1>(
      nonlocal.get_model(),
      [&](const types::global_dof_index i, const Point<1> &x, unsigned int) {
        overlap.nonlocal_control_traces.emplace_back(
          i, fe_evaluation_row(local_cache, local_dofs, x));
      });
    for_each_owned_control<1>(
      local_model,
      [&](const types::global_dof_index i, const Point<1> &x, unsigned int) {
        overlap.local_control_traces.emplace_back(
          i, fe_evaluation_row(nonlocal_cache, nonlocal_dofs, x));
      });
  }



  template <int dim, template <int> class ParticleModel>
  void
  add_control_traces(OverlapQuadrature<dim>   &overlap,
                     const ParticleModel<dim> &nonlocal,
                     const DiscreteModel      &local_model,
                     const DoFHandler<dim>    &local_dofs)
  {
    using Model          = ParticleModel<dim>;
    using LatticeIndex   = typename ParticleLattice<dim>::LatticeIndex;
    const auto  &lattice = nonlocal.get_lattice();
    const auto  &fe      = local_dofs.get_fe();
    const double tolerance =
      1e-9 * std::pow(nonlocal.particle_volume(), 1. / dim);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());

    // T_{l->n}: the control particles, each in the one owned cell that
    // holds it.
    for_each_in_owned_cells(
      lattice,
      local_dofs,
      tolerance,
      [&](const auto                   &cell,
          const LatticeIndex           &index,
          const types::global_dof_index number,
          const Point<dim>             &unit) {
        if (nonlocal.role(index) != DofRole::control)
          return;
        cell->get_dof_indices(dofs);
        for (unsigned int c = 0; c < Model::n_field_components; ++c)
          overlap.nonlocal_control_traces.emplace_back(
            Model::dof(number, c), fe_component_row(fe, dofs, unit, c));
      });

    // T_{n->l}: per axis the degree + 1 particle coordinates nearest to the
    // node (ties to the lower one), and the tensor product of their
    // Lagrange weights.
    const unsigned int n_nodes = fe.degree + 1;
    const double       h       = std::pow(nonlocal.particle_volume(), 1. / dim);
    for_each_owned_control<dim>(
      local_model,
      [&](const types::global_dof_index i,
          const Point<dim>             &x,
          const unsigned int            c) {
        std::map<LatticeIndex, types::global_dof_index> near;
        Point<dim>                                      lower = x, upper = x;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] -= 0.5 * (n_nodes + 1) * h;
            upper[d] += 0.5 * (n_nodes + 1) * h;
          }
        lattice.for_each_in_box(lower,
                                upper,
                                tolerance,
                                [&](const LatticeIndex           &index,
                                    const types::global_dof_index number) {
                                  near.emplace(index, number);
                                });
        AssertThrow(!near.empty(), ExcInternalError());
        std::array<std::vector<int>, dim>    chosen;
        std::array<std::vector<double>, dim> weights;
        for (unsigned int d = 0; d < dim; ++d)
          {
            std::vector<std::pair<double, int>> candidates;
            for (const auto &[index, number] : near)
              candidates.emplace_back(std::abs(lattice.position(index)[d] -
                                               x[d]),
                                      index[d]);
            std::sort(candidates.begin(), candidates.end());
            candidates.erase(std::unique(candidates.begin(),
                                         candidates.end(),
                                         [](const auto &a, const auto &b) {
                                           return a.second == b.second;
                                         }),
                             candidates.end());
            // One per coordinate: equal coordinates have equal distances,
            // so the sort puts them next to each other.
            AssertThrow(candidates.size() >= n_nodes, ExcInternalError());
            std::vector<double> coordinates;
            for (unsigned int m = 0; m < n_nodes; ++m)
              {
                chosen[d].push_back(candidates[m].second);
                LatticeIndex probe = near.begin()->first;
                probe[d]           = candidates[m].second;
                coordinates.push_back(lattice.position(probe)[d]);
              }
            weights[d] = lagrange_weights(coordinates, x[d]);
          }
        SparseRow                 row;
        std::array<unsigned, dim> m{};
        while (true)
          {
            LatticeIndex index;
            double       weight = 1;
            for (unsigned int d = 0; d < dim; ++d)
              {
                index[d] = chosen[d][m[d]];
                weight *= weights[d][m[d]];
              }
            const auto number = lattice.number(index);
            AssertThrow(number != ParticleLattice<dim>::invalid,
                        ExcMessage("a node of Gamma_c lies too close to the "
                                   "end of the particle lattice to be "
                                   "interpolated"));
            row.emplace_back(Model::dof(number, c), weight);
            unsigned int d = 0;
            for (; d < dim; ++d)
              {
                if (++m[d] < n_nodes)
                  break;
                m[d] = 0;
              }
            if (d == dim)
              break;
          }
        overlap.local_control_traces.emplace_back(i, std::move(row));
      });
  }

#define LTN_INSTANTIATE(dim, Model)                          \
  template void add_control_traces(OverlapQuadrature<dim> &, \
                                   const Model<dim> &,       \
                                   const DiscreteModel &,    \
                                   const DoFHandler<dim> &);
  LTN_INSTANTIATE(2, ParticleDiffusion)
  LTN_INSTANTIATE(3, ParticleDiffusion)
  LTN_INSTANTIATE(2, ParticleElasticity)
  LTN_INSTANTIATE(3, ParticleElasticity)
#undef LTN_INSTANTIATE
} // namespace ltn

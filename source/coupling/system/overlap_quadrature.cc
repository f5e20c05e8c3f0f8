#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <ltn/coupling/system/fe_component_row.h>
#include <ltn/coupling/system/overlap_quadrature.h>

#include <algorithm>

namespace ltn
{
  template <int dim>
  SparseRow
  fe_evaluation_row(const GridTools::Cache<dim> &cache,
                    const DoFHandler<dim>       &dofs,
                    const Point<dim>            &point)
  {
    const auto found = GridTools::find_active_cell_around_point(cache, point);
    AssertThrow(found.first.state() == IteratorState::valid,
                ExcMessage("An overlap point lies outside the local mesh."));
    const typename DoFHandler<dim>::active_cell_iterator cell(
      &dofs.get_triangulation(),
      found.first->level(),
      found.first->index(),
      &dofs);
    std::vector<types::global_dof_index> indices(
      dofs.get_fe().n_dofs_per_cell());
    cell->get_dof_indices(indices);
    SparseRow row;
    for (unsigned int i = 0; i < indices.size(); ++i)
      row.emplace_back(indices[i], dofs.get_fe().shape_value(i, found.second));
    return row;
  }

  template SparseRow
  fe_evaluation_row(const GridTools::Cache<1> &,
                    const DoFHandler<1> &,
                    const Point<1> &);



  OverlapQuadrature<1>
  create_overlap_quadrature_1d(const Geometry<1>   &geometry,
                               const double         horizon,
                               const DoFHandler<1> &nonlocal_dofs,
                               const DoFHandler<1> &local_dofs)
  {
    const Box<1>        region = geometry.nonlocal_region().bounding_box();
    std::vector<double> breaks = {region.lower[0] - horizon,
                                  region.upper[0] + horizon};
    for (const auto *dofs : {&nonlocal_dofs, &local_dofs})
      for (const auto &cell : dofs->active_cell_iterators())
        for (const auto v : cell->vertex_indices())
          breaks.push_back(cell->vertex(v)[0]);
    std::sort(breaks.begin(), breaks.end());
    const double tol = geometry.tolerance();
    breaks.erase(std::unique(breaks.begin(),
                             breaks.end(),
                             [&](const double a, const double b) {
                               return b - a <= tol;
                             }),
                 breaks.end());

    const unsigned int degree =
      std::max(nonlocal_dofs.get_fe().degree, local_dofs.get_fe().degree);
    const QGauss<1>     rule(degree + 1);
    const MappingQ1<1>  mapping;
    GridTools::Cache<1> nonlocal_cache(nonlocal_dofs.get_triangulation(),
                                       mapping);
    GridTools::Cache<1> local_cache(local_dofs.get_triangulation(), mapping);

    OverlapQuadrature<1> overlap;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
      {
        const double a = breaks[k], b = breaks[k + 1];
        if (!geometry.in_overlap(Point<1>(0.5 * (a + b)), horizon))
          continue;
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            const Point<1> point(a + (b - a) * rule.point(q)[0]);
            overlap.points.push_back(point);
            overlap.weights.push_back((b - a) * rule.weight(q));
            overlap.nonlocal_rows.push_back(
              fe_evaluation_row(nonlocal_cache, nonlocal_dofs, point));
            overlap.local_rows.push_back(
              fe_evaluation_row(local_cache, local_dofs, point));
          }
      }
    return overlap;
  }



  OverlapQuadrature<1>
  create_overlap_quadrature(const Geometry<1>        &geometry,
                            const double              horizon,
                            const NonlocalWeakForm1D &nonlocal,
                            const DoFHandler<1>      &local_dofs)
  {
    return create_overlap_quadrature_1d(geometry,
                                        horizon,
                                        nonlocal.get_dof_handler(),
                                        local_dofs);
  }



  template <int dim, template <int> class ParticleModel>
  OverlapQuadrature<dim>
  create_overlap_quadrature(
    const Geometry<dim> &geometry,
    const double /*horizon: the control particles are the collar*/,
    const ParticleModel<dim> &nonlocal,
    const DoFHandler<dim>    &local_dofs)
  {
    const auto                          &lattice = nonlocal.get_lattice();
    const auto                          &fe      = local_dofs.get_fe();
    const double                         tol     = geometry.tolerance();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());

    OverlapQuadrature<dim> overlap;
    for_each_in_owned_cells(
      lattice,
      local_dofs,
      tol,
      [&](const auto                   &cell,
          const auto                   &index,
          const types::global_dof_index number,
          const Point<dim>             &unit) {
        const Point<dim> x = lattice.position(index);
        cell->get_dof_indices(dofs);
        // Omega_b = Omega_l ∩ (Omega_n ∪ control collar): the control
        // particles are the control collar (all inside Omega_l).
        const DofRole role = nonlocal.role(index);
        if (role == DofRole::fixed ||
            (role == DofRole::free && !geometry.in_local_region(x)))
          return;
        for (unsigned int c = 0; c < ParticleModel<dim>::n_field_components;
             ++c)
          {
            overlap.points.push_back(x);
            overlap.weights.push_back(nonlocal.particle_volume());
            overlap.nonlocal_rows.push_back(
              {{ParticleModel<dim>::dof(number, c), 1.}});
            overlap.local_rows.push_back(fe_component_row(fe, dofs, unit, c));
          }
      });
    return overlap;
  }

  template OverlapQuadrature<2>
  create_overlap_quadrature(const Geometry<2> &,
                            double,
                            const ParticleDiffusion<2> &,
                            const DoFHandler<2> &);
  template OverlapQuadrature<3>
  create_overlap_quadrature(const Geometry<3> &,
                            double,
                            const ParticleDiffusion<3> &,
                            const DoFHandler<3> &);
  template OverlapQuadrature<2>
  create_overlap_quadrature(const Geometry<2> &,
                            double,
                            const ParticleElasticity<2> &,
                            const DoFHandler<2> &);
  template OverlapQuadrature<3>
  create_overlap_quadrature(const Geometry<3> &,
                            double,
                            const ParticleElasticity<3> &,
                            const DoFHandler<3> &);
} // namespace ltn

#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/grid_tools_cache.h>

#include <ltn/nonlocal/nonlocal_weak_form_1d.h>
#include <ltn/nonlocal/particle_diffusion.h>
#include <ltn/nonlocal/particle_elasticity.h>
#include <ltn/problem/blending_function.h>
#include <ltn/problem/geometry.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** A sparse row: (degree of freedom, coefficient) pairs. */
  using SparseRow = std::vector<std::pair<types::global_dof_index, double>>;

  /**
   * A control of one model as the trace of the other model's field at its
   * position: the control's degree of freedom and the row over the other
   * model's degrees of freedom that evaluates that field there.
   */
  using ControlTrace = std::pair<types::global_dof_index, SparseRow>;

  /**
   * The discrete mismatch on the overlap `Omega_b` as a quadrature:
   *
   *   J_h = 1/2 sum_q w_q (E_q x_n - P_q x_l)^2,
   *
   * where row `E_q` evaluates the nonlocal field and row `P_q` the local
   * field at point `q`. With particles, `E_q` picks a particle and `w_q` is
   * its volume; in 1D FEM-FEM the points are Gauss points of the common
   * refinement of both meshes, so `J_h` is the exact L2 mismatch.
   *
   * Each rank holds its own points, and the rows refer to the models'
   * global numbering.
   */
  template <int dim>
  struct OverlapQuadrature
  {
    std::vector<Point<dim>> points;
    std::vector<double>     weights;
    std::vector<SparseRow>  nonlocal_rows;
    std::vector<SparseRow>  local_rows;

    /**
     * For the alternating Schwarz method (doc/baseline_couplings.md, 'The
     * transfer operators'): the nonlocal controls as traces of the local
     * field (`T_{l->n}`) and the local controls as traces of the nonlocal
     * field (`T_{n->l}`), each held by the rank that found it. Empty unless
     * add_control_traces() filled them.
     */
    std::vector<ControlTrace> nonlocal_control_traces;
    std::vector<ControlTrace> local_control_traces;

    /**
     * For force-based blending in 1D (doc/baseline_couplings.md,
     * 'Force-based blending'): the nodes of a shared mesh of the body, each
     * with its blending weight `beta`, and per model (nonlocal, local) the
     * node of each of its degrees of freedom. Empty unless
     * add_blending_nodes() filled them.
     */
    struct BlendingNodes
    {
      std::vector<double>                                 beta;
      std::array<std::vector<types::global_dof_index>, 2> node_of_dof;
      /**
       * For energy-based blending ('Energy-based blending'): each model's
       * form weighted by `beta` (nonlocal) or `1 - beta` (local), in its
       * own numbering. Null unless the scene filled them.
       */
      std::array<std::shared_ptr<const WeightedForm>, 2> energy;
    } blending_nodes;
  };

  /** The row that evaluates the finite element field of @p dofs at
   * @p point, in the active cell @p cache finds around it. */
  template <int dim>
  SparseRow
  fe_evaluation_row(const GridTools::Cache<dim> &cache,
                    const DoFHandler<dim>       &dofs,
                    const Point<dim>            &point);

  /**
   * The exact L2 overlap quadrature of two 1D finite element fields: Gauss
   * points on every interval between consecutive vertices of the two meshes
   * (and the ends of `Omega_b`) that lies in `Omega_b`, with enough points to
   * integrate the square of the difference exactly.
   */
  OverlapQuadrature<1>
  create_overlap_quadrature_1d(const Geometry<1>   &geometry,
                               const double         horizon,
                               const DoFHandler<1> &nonlocal_dofs,
                               const DoFHandler<1> &local_dofs);

  /** The 1D FEM-FEM overlap quadrature of a NonlocalWeakForm1D. */
  OverlapQuadrature<1>
  create_overlap_quadrature(const Geometry<1>        &geometry,
                            const double              horizon,
                            const NonlocalWeakForm1D &nonlocal,
                            const DoFHandler<1>      &local_dofs);

  /**
   * The particle overlap quadrature: one point per particle of `Omega_b`
   * (the control particles, and the particles of `Omega_n` in `Omega_l`)
   * and per component of the field (one for diffusion, `dim` displacement
   * components for elasticity), with the particle's volume as weight; `E_q`
   * picks the particle's component and `P_q` evaluates that component of the
   * local finite element field at its position. Each rank holds the points
   * in its locally owned cells of the local mesh (which must be Cartesian).
   *
   * @p ParticleModel is ParticleDiffusion or ParticleElasticity: it gives
   * the lattice, the role of a particle, its volume, and the degree of
   * freedom `dof(number, c)` of field component `c < n_field_components`.
   */
  template <int dim, template <int> class ParticleModel>
  OverlapQuadrature<dim>
  create_overlap_quadrature(const Geometry<dim>      &geometry,
                            const double              horizon,
                            const ParticleModel<dim> &nonlocal,
                            const DoFHandler<dim>    &local_dofs);
} // namespace ltn

#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/direct_solver.h>
#include <ltn/base/discrete_model.h>
#include <ltn/output/run_summary.h>
#include <ltn/problem/geometry.h>

#include <array>
#include <memory>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The estimate's terms point by point, this rank's, for the output: the
   * points of `E` and of the strip along Dirichlet faces, their terms `V
   * |r_i|^2 / chi / c_G`, and 1 in the strip, 0 elsewhere; the composite
   * field itself on the whole body's lattice (the reference of another
   * region's true error, ModelAdaptivity).
   */
  template <int dim>
  struct ModelErrorField
  {
    std::vector<Point<dim>>       points;
    std::vector<double>           indicator;
    std::vector<double>           boundary_layer;
    TrilinosWrappers::MPI::Vector composite;
    /**
     * The long-wave terms `V r_i . z(x_i)` at the points of `E` (this
     * rank's cells of the representer's mesh): they sum to `eta_1^2`.
     */
    std::vector<Point<dim>> long_wave_points;
    std::vector<double>     long_wave_terms;
    /**
     * Under `Nonlocal regions = auto`: `eta_K^2` per block
     * (ModelAdaptivity::block_indicators()), summed once for the output
     * and the marking.
     */
    std::vector<double> block_indicators;
  };

  /**
   * What the estimate computes of the whole body's operators, the same for
   * every region at one spacing: kept by a caller that estimates several
   * regions (the model-adaptivity loop). Empty, the estimate fills it.
   */
  struct ModelErrorOperators
  {
    /** The diagonal at an uncut interior point; 0 until computed. */
    double chi = 0;
    /** The largest eigenvalue over `chi`. */
    double c_G = 0;
    /** The representer's factorization. */
    std::shared_ptr<const DirectSolver> representer_solver;
  };



  /**
   * The short-wave model-error estimate of a coupled solution
   * (doc/model_adaptivity.md, 'The model-error indicator'): the residual of
   * the nonlocal model on the whole body, `r = b - A w`, of the composite
   * field `w` (`u_n` on `Omega_n`, `u_l` on the rest of the body, the volume
   * constraint beyond it), at the lattice points `E` of the body within the
   * interaction range of the body outside `Omega_n`, away from the body's
   * faces (within that range of a Dirichlet face the sum is reported as
   * `boundary_layer`: the volume constraint of the reference and the local
   * model's boundary value differ there whatever the region); then
   *
   *   eta_0^2 = sum_E V |r_i|^2 / chi / c_G  <=  ||u_* - w||_{A_*}^2,
   *
   * `chi` the operator's diagonal at an uncut interior point, `c_G` the
   * largest eigenvalue of the operator over `chi`. Zero to round-off where
   * both models agree (polynomial fields the lattice operator reproduces).
   *
   * With @p representer (the local model on the whole body, assembled, on a
   * mesh without hanging nodes; @p representer_dofs its degrees of
   * freedom) also the long waves: `z` in its finite elements, zero on its
   * Dirichlet faces, with `a_l(z, v) = sum_E V r_i . v(x_i)` for all `v`,
   * and `eta_1^2 = a_l(z, z)`; the estimate is `(eta_0^2 + eta_1^2)^(1/2)`.
   * What @p operators holds is used, what it lacks computed into it.
   *
   * @p coupled is the coupled solution's nonlocal model, null where the
   * local model covers the body (then `w = u_l` on the whole body).
   * @p reference is the nonlocal model of the same level on the whole body
   * (`Geometry/Models = nonlocal only`, same spacing and stencil, assembled
   * with its data); its lattice must be the coupled one's shifted by whole
   * spacings. @p local_field is ghosted. With @p reference_solution (the
   * reference's solution, `u_*`), also the true modeling error
   * `||u_* - w||_{A_*}` and the effectivity `eta_0 / ||u_* - w||`; with
   * @p region_reference (the composite field of the coupled solution on the
   * largest admissible region, on the reference's lattice), the region's
   * own error `||w_max - w||_{A_*}` and `eta_0` over it. With @p field, the
   * terms point by point and the composite field. Collective.
   */
  template <int dim, typename ParticleModel>
  ModelErrorRecord
  estimate_model_error(const Geometry<dim>                 &geometry,
                       const ParticleModel                 *coupled,
                       const TrilinosWrappers::MPI::Vector &nonlocal_field,
                       const DoFHandler<dim>               &local_dofs,
                       const TrilinosWrappers::MPI::Vector &local_field,
                       const ParticleModel                 &reference,
                       const double                         interaction_range,
                       const std::array<bool, 2 * dim>     &dirichlet_faces,
                       const TrilinosWrappers::MPI::Vector *reference_solution,
                       const TrilinosWrappers::MPI::Vector *region_reference,
                       const DoFHandler<dim>               *representer_dofs,
                       const DiscreteModel                 *representer,
                       ModelErrorOperators                 &operators,
                       ModelErrorField<dim>                *field);
} // namespace ltn

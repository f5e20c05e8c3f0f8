#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/output/run_summary.h>
#include <ltn/problem/geometry.h>

#include <array>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The estimate's terms point by point, this rank's, for the output: the
   * points of `E` and of the strip along Dirichlet faces, their terms `V
   * |r_i|^2 / chi / c_G`, and 1 in the strip, 0 elsewhere.
   */
  template <int dim>
  struct ModelErrorField
  {
    std::vector<Point<dim>> points;
    std::vector<double>     indicator;
    std::vector<double>     boundary_layer;
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
   * @p reference is the nonlocal model of the same level on the whole body
   * (`Geometry/Models = nonlocal only`, same spacing and stencil, assembled
   * with its data); its lattice must be the coupled one's shifted by whole
   * spacings. @p local_field is ghosted. With @p reference_solution (the
   * reference's solution, `u_*`), also the true modeling error
   * `||u_* - w||_{A_*}` and the effectivity `eta_0 / ||u_* - w||`. With
   * @p field, the terms point by point. Collective.
   */
  template <int dim, typename ParticleModel>
  ModelErrorRecord
  estimate_model_error(const Geometry<dim>                 &geometry,
                       const ParticleModel                 &coupled,
                       const TrilinosWrappers::MPI::Vector &nonlocal_field,
                       const DoFHandler<dim>               &local_dofs,
                       const TrilinosWrappers::MPI::Vector &local_field,
                       const ParticleModel                 &reference,
                       const double                         interaction_range,
                       const std::array<bool, 2 * dim>     &dirichlet_faces,
                       const TrilinosWrappers::MPI::Vector *reference_solution,
                       ModelErrorField<dim>                *field);
} // namespace ltn

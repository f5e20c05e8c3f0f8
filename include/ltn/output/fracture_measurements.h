#pragma once

#include <deal.II/base/function.h>

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/json.h>
#include <ltn/local/elasticity_problem.h>
#include <ltn/local/local_parameters.h>
#include <ltn/nonlocal/particle_elasticity.h>
#include <ltn/problem/geometry.h>

#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The measurements of an elasticity scene that a user of fracture
   * mechanics checks, one per function, in the manner of ASPECT's
   * postprocessors: each computes its quantity on all ranks, returns its
   * lines of the level's console report and its entry of `summary.json`
   * (in `mechanics`).
   */

  /**
   * The force through each plane `x_d = c` of @p planes (pairs `(d, c)`) of
   * the local model's displacement @p field (ghosted), and its mean stress
   * over the body's section @p body: the array `section_forces`.
   */
  template <int dim>
  std::string
  measure_section_forces(
    const ElasticityProblem<dim>                       &local,
    const TrilinosWrappers::MPI::Vector                &field,
    const std::vector<std::pair<unsigned int, double>> &planes,
    const Box<dim>                                     &body,
    JsonValue                                          &entry);

  /**
   * The resultant of the loads @p traction and @p pressure on every face
   * of the body that is not clamped in all components (@p parameters' Dirichlet
   * masks): the array `applied_forces`; the report names the faces
   * whose resultant is not zero.
   */
  template <int dim>
  std::string
  measure_applied_forces(const ElasticityProblem<dim> &local,
                         const LocalParameters<dim>   &parameters,
                         const Function<dim>          &traction,
                         const Function<dim>          &pressure,
                         JsonValue                    &entry);

  /**
   * The opening of each of the @p n_cracks cracks in the particles'
   * displacement @p field: its points, values and maximum, and, given a
   * @p reference opening, the relative L2 difference to it: the array
   * `crack_openings`.
   */
  template <int dim>
  std::string
  measure_crack_openings(const ParticleElasticity<dim>       &nonlocal,
                         const TrilinosWrappers::MPI::Vector &field,
                         const unsigned int                   n_cracks,
                         const Function<dim>                 *reference,
                         JsonValue                           &entry);
} // namespace ltn

#pragma once

#include <deal.II/base/parameter_handler.h>

namespace ltn
{
  using namespace dealii;

  /**
   * The isotropic linear elastic material of an elasticity scene (subsection
   * `Material`): Young's modulus `E` and Poisson ratio `nu`, and in 2D
   * whether the body is a slice of a long body (plane strain) or a thin plate
   * (plane stress). Both models of a scene take their constants from here:
   * Navier–Cauchy `-[(lambda + mu) grad div u + mu Laplace u] = b` with the
   * Lamé constants of the dimension, and LPS with the constants derived from
   * them (doc/discretization.md, 'Linearized peridynamics (LPS) on
   * particles').
   */
  struct Material
  {
    enum class Plane
    {
      strain,
      stress
    };

    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check: an InputError names a bad modulus or ratio. */
    void
    parse_parameters(ParameterHandler &prm);

    /** The shear modulus `mu = E / (2 (1 + nu))`. */
    double
    mu() const;

    /**
     * The first Lamé constant of the @p dim dimensional Navier–Cauchy model:
     * `lambda = E nu / ((1 + nu)(1 - 2 nu))` in 3D and plane strain,
     * `2 lambda mu / (lambda + 2 mu) = E nu / (1 - nu^2)` in plane stress.
     */
    double
    lambda(const unsigned int dim) const;

    /**
     * The modulus of the classical crack-opening profile: `E / (1 - nu^2)`
     * in plane strain, `E` in plane stress.
     */
    double
    crack_modulus(const unsigned int dim) const;

    double youngs_modulus = 1;
    double poisson_ratio  = 0.25;
    Plane  plane          = Plane::strain;
  };
} // namespace ltn

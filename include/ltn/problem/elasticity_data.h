#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ltn/base/expression.h>
#include <ltn/problem/data_entries.h>
#include <ltn/problem/material.h>

#include <memory>
#include <string>

namespace ltn
{
  using namespace dealii;

  /**
   * The data of an elasticity scene (subsection `Elasticity data`), as text
   * expressions of `dim` components separated by `;` (the pressure has one):
   * the body force of both models, Dirichlet data of the local model, the
   * volume constraint of the nonlocal one, the traction and pressure on the
   * local model's Neumann faces, and an optional exact displacement. Besides
   * `x`, `y`, `z` every expression may use the constants of the material and
   * of the level: `E`, `nu`, `lambda` and `mu` (the Lamé constants of the
   * dimension: plane stress has its own lambda), `eps`, `h`, and `pi`.
   */
  struct ElasticityData : SolutionData
  {
    ElasticityData();

    /** Declare the subsection `Elasticity data`. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read the expressions. */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * An InputError names the first elasticity-only parameter (of
     * `Elasticity data`, `Material`, `Cracks` or `Postprocess`) that a
     * diffusion scene
     * sets to other than its default.
     */
    static void
    check_unused(ParameterHandler &prm);

    template <int dim>
    struct Functions
    {
      /** Null when the scene gives no exact solution. */
      std::unique_ptr<Expression<dim>> exact_solution;
      std::unique_ptr<Expression<dim>> body_force;
      std::unique_ptr<Expression<dim>> boundary_data;
      std::unique_ptr<Expression<dim>> volume_constraint_data;
      std::unique_ptr<Expression<dim>> traction;
      std::unique_ptr<Expression<dim>> pressure;
    };

    /**
     * Parse every expression with the constants of @p material and of a
     * level with horizon @p horizon and mesh size @p h.
     */
    template <int dim>
    Functions<dim>
    functions(const Material &material,
              const double    horizon,
              const double    h) const;

    std::string body_force;
    std::string traction;
    std::string pressure;
  };
} // namespace ltn

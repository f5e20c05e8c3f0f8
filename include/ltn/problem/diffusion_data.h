#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ltn/base/expression.h>
#include <ltn/problem/data_entries.h>

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace ltn
{
  using namespace dealii;

  /**
   * The data of a diffusion scene (subsection `Diffusion data`), as text
   * expressions:
   * right-hand sides of both models, physical data, and an optional exact
   * solution. Besides `x`, `y`, `z`, every expression may use the constants
   * of the level it is evaluated on: `eps` (horizon), `h` (mesh size), `k`
   * (the `Plane wave number`), `sigma` (the symbol of the nonlocal operator
   * on the plane wave `e^{ikx}`: `L e^{ikx} = sigma e^{ikx}`), and `pi`.
   * With them, `f_n = -L u` of a plane-wave solution is written exactly,
   * e.g. `-sigma*sin(k*x)`, even when the horizon changes with the level.
   */
  struct DiffusionData : SolutionData
  {
    DiffusionData();

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * An InputError names the first entry of `Diffusion data` that an
     * elasticity scene sets to other than its default.
     */
    static void
    check_unused(ParameterHandler &prm);

    /** The functions of one level. */
    template <int dim>
    struct Functions
    {
      /** Null when the scene gives no exact solution. */
      std::unique_ptr<Expression<dim>> exact_solution;
      std::unique_ptr<Expression<dim>> nonlocal_rhs;
      std::unique_ptr<Expression<dim>> local_rhs;
      std::unique_ptr<Expression<dim>> boundary_data;
      std::unique_ptr<Expression<dim>> volume_constraint_data;
      std::unique_ptr<Expression<dim>> boundary_gradient;
    };

    /**
     * Parse every expression with the constants of a level with mesh size
     * @p h, whose nonlocal operator has the horizon @p horizon and the
     * plane-wave symbol @p plane_wave_symbol (`k -> sigma(k)`; the kernel's,
     * which the problem's data do not depend on otherwise); throws an
     * InputError naming the parameter of a malformed one.
     */
    template <int dim>
    Functions<dim>
    functions(const double                         horizon,
              const std::function<double(double)> &plane_wave_symbol,
              const double                         h) const;

    std::string nonlocal_rhs;
    std::string local_rhs;
    std::string boundary_gradient;
    double      wave_number = 0;
  };
} // namespace ltn

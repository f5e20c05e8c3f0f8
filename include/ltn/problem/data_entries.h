#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ltn/base/expression.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * An entry of a subsection with its default: `{subsection, name,
   * default}`.
   */
  using DefaultEntry = std::array<std::string, 3>;

  /**
   * Throw an InputError naming the first of @p entries that is set to other
   * than its default: a parameter only @p scenes use (e.g. "elasticity
   * scenes only (Model = elasticity)"), which this scene would ignore.
   */
  void
  check_at_defaults(ParameterHandler                &prm,
                    const std::vector<DefaultEntry> &entries,
                    const std::string               &scenes);

  /**
   * What every physics' data subsection (`Diffusion data`, `Elasticity
   * data`) holds for its field, as text: an optional exact solution, the
   * local model's Dirichlet data and the nonlocal model's volume constraint;
   * and how the physics turns its texts into the expressions of a level.
   */
  struct SolutionData
  {
    /** The data of the subsection @p subsection. */
    explicit SolutionData(std::string subsection);

    /**
     * Declare the subsection @p subsection: `Exact solution`, `Boundary
     * data` and `Volume constraint data` for the field @p field (e.g. "u"),
     * then the physics' own entries by @p declare_physics_entries.
     */
    static void
    declare_subsection(ParameterHandler            &prm,
                       const std::string           &subsection,
                       const std::string           &field,
                       const std::function<void()> &declare_physics_entries);

    /**
     * Read the subsection: the solution entries, then the physics' own by
     * @p parse_physics_entries.
     */
    void
    parse_subsection(ParameterHandler            &prm,
                     const std::function<void()> &parse_physics_entries);

    /** Them, with their defaults. */
    std::vector<DefaultEntry>
    solution_entries() const;

    /**
     * The expression @p text of the entry @p name, with @p n_components
     * components and the level's @p constants; an InputError names
     * `subsection/name` if it does not parse.
     */
    template <int dim>
    std::unique_ptr<Expression<dim>>
    expression(const std::string                   &name,
               const std::string                   &text,
               const std::map<std::string, double> &constants,
               const unsigned int                   n_components) const;

    /**
     * expression() of @p text, or of the exact solution if @p text is empty;
     * an InputError if both are, saying that the entry is @p what.
     */
    template <int dim>
    std::unique_ptr<Expression<dim>>
    or_exact(const std::string                   &name,
             const std::string                   &text,
             const std::map<std::string, double> &constants,
             const unsigned int                   n_components,
             const std::string                   &what) const;

    std::string subsection;
    std::string exact_solution;
    std::string boundary_data;
    std::string volume_constraint_data;
  };
} // namespace ltn

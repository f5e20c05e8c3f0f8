#pragma once

#include <deal.II/base/function_parser.h>

#include <map>
#include <memory>
#include <string>

namespace ltn
{
  using namespace dealii;

  /**
   * A function of space given by the user as a text expression in the
   * `.prm` file (muparser syntax, variables `x`, `y`, `z` by dimension).
   *
   * The expression is parsed and evaluated once on construction, so that a
   * malformed expression or an unknown symbol is reported as an InputError
   * naming the parameter it came from, before any work is done.
   */
  template <int dim>
  class Expression : public FunctionParser<dim>
  {
  public:
    /**
     * @param parameter the parameter's path, for error messages.
     * @param expression the text given by the user.
     * @param constants named constants the expression may use (such as the
     *   horizon `eps` or the mesh size `h` of the current level).
     * @param n_components the number of components, separated by `;` in
     *   @p expression.
     */
    Expression(const std::string                   &parameter,
               const std::string                   &expression,
               const std::map<std::string, double> &constants,
               const unsigned int                   n_components = 1);
  };

  /** The variable names of an expression in @p dim dimensions: "x,y". */
  std::string
  expression_variables(const unsigned int dim);
} // namespace ltn

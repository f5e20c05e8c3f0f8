#include <deal.II/lac/vector.h>

#include <ltn/base/expression.h>
#include <ltn/base/input_error.h>

#include <cmath>

namespace ltn
{
  std::string
  expression_variables(const unsigned int dim)
  {
    static const char *names[] = {"x", "x,y", "x,y,z"};
    return names[dim - 1];
  }



  template <int dim>
  Expression<dim>::Expression(const std::string                   &parameter,
                              const std::string                   &expression,
                              const std::map<std::string, double> &constants,
                              const unsigned int                   n_components)
    : FunctionParser<dim>(n_components)
  {
    std::string allowed = std::to_string(n_components) +
                          " ';'-separated function(s) of " +
                          expression_variables(dim) +
                          " in muparser syntax, using only the constants";
    for (const auto &c : constants)
      allowed += " " + c.first;

    check_input(!expression.empty(), parameter, expression, allowed);
    try
      {
        this->initialize(expression_variables(dim), expression, constants);
        // muparser compiles lazily: evaluate once so that syntax errors and
        // unknown symbols surface here, with the parameter's name.
        Vector<double> probe(n_components);
        this->vector_value(Point<dim>(), probe);
      }
    catch (const std::exception &error)
      {
        throw InputError(parameter, expression, allowed);
      }
  }

  template class Expression<1>;
  template class Expression<2>;
  template class Expression<3>;
} // namespace ltn

#include <deal.II/lac/vector.h>

#include <ltn/base/expression.h>
#include <ltn/base/input_error.h>

#include <boost/io/ios_state.hpp>

#include <cmath>
#include <iostream>
#include <sstream>

namespace ltn
{
  std::string
  expression_variables(const unsigned int dim)
  {
    static const char *names[] = {"x", "x,y", "x,y,z"};
    return names[dim - 1];
  }



  namespace
  {
    /**
     * From FunctionParser's diagnosis, its line `Message:  <...>`, as
     * " (muparser: ...)"; empty if there is none.
     */
    std::string
    parser_message(const std::string &diagnosis)
    {
      const std::string tag   = "Message:  <";
      const auto        begin = diagnosis.find(tag);
      if (begin == std::string::npos)
        return "";
      const auto start = begin + tag.size();
      const auto end   = diagnosis.find(">\n", start);
      if (end == std::string::npos)
        return "";
      return " (muparser: " + diagnosis.substr(start, end - start) + ")";
    }
  } // namespace



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
    // deal.II's FunctionParser writes muparser's diagnosis of a bad
    // expression to std::cerr, five lines ahead of the error that names the
    // parameter: it is kept here, and its message goes into that error.
    std::ostringstream diagnosis;
    try
      {
        const boost::io::ios_rdbuf_saver restore(std::cerr);
        std::cerr.rdbuf(diagnosis.rdbuf());
        this->initialize(expression_variables(dim), expression, constants);
        // muparser compiles lazily: evaluate once so that syntax errors and
        // unknown symbols surface here, with the parameter's name.
        Vector<double> probe(n_components);
        this->vector_value(Point<dim>(), probe);
      }
    catch (const std::exception &)
      {
        throw InputError(parameter,
                         expression,
                         allowed + parser_message(diagnosis.str()));
      }
  }

  template class Expression<1>;
  template class Expression<2>;
  template class Expression<3>;
} // namespace ltn

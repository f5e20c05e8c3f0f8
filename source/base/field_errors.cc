#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <ltn/base/field_errors.h>

#include <cmath>
#include <limits>

namespace ltn
{
  void
  ErrorNorms::add(const ErrorNorms &other)
  {
    l2_squared += other.l2_squared;
    add_pointwise(other.linf);
  }



  void
  ErrorNorms::add_pointwise(const double error)
  {
    // Written so that a NaN error makes linf NaN (std::max would drop it).
    if (!(std::abs(error) <= linf))
      linf = std::abs(error);
  }



  double
  ErrorNorms::l2() const
  {
    return std::sqrt(l2_squared);
  }



  ErrorNorms
  ErrorNorms::over_all_ranks(const MPI_Comm communicator) const
  {
    ErrorNorms result;
    result.l2_squared = Utilities::MPI::sum(l2_squared, communicator);
    // MPI's max would not keep a NaN: count them.
    const bool any_nan =
      Utilities::MPI::sum(std::isnan(linf) ? 1 : 0, communicator) > 0;
    result.linf = any_nan ? std::numeric_limits<double>::quiet_NaN() :
                            Utilities::MPI::max(linf, communicator);
    return result;
  }



  template <int dim>
  ErrorNorms
  field_errors(const DoFHandler<dim>                         &dof_handler,
               const TrilinosWrappers::MPI::Vector           &field,
               const Function<dim>                           &exact,
               const std::function<bool(const Point<dim> &)> &in_region)
  {
    const auto        &fe           = dof_handler.get_fe();
    const unsigned int n_components = fe.n_components();
    AssertThrow(exact.n_components == n_components,
                ExcDimensionMismatch(exact.n_components, n_components));
    const QGauss<dim>           l2_rule(fe.degree + 3);
    const QIterated<dim>        max_rule(QTrapezoid<1>(), 4 * fe.degree);
    FEValues<dim>               l2_values(fe,
                            l2_rule,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    FEValues<dim>               max_values(fe,
                             max_rule,
                             update_values | update_quadrature_points);
    std::vector<Vector<double>> values_at_l2(l2_rule.size(),
                                             Vector<double>(n_components)),
      values_at_max(max_rule.size(), Vector<double>(n_components));

    // Component by component: |u_h - u|^2 summed for L2, the largest
    // component for max.
    ErrorNorms errors;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && in_region(cell->center()))
        {
          l2_values.reinit(cell);
          l2_values.get_function_values(field, values_at_l2);
          for (unsigned int q = 0; q < l2_rule.size(); ++q)
            for (unsigned int c = 0; c < n_components; ++c)
              {
                const double e = values_at_l2[q][c] -
                                 exact.value(l2_values.quadrature_point(q), c);
                errors.l2_squared += e * e * l2_values.JxW(q);
              }
          max_values.reinit(cell);
          max_values.get_function_values(field, values_at_max);
          for (unsigned int q = 0; q < max_rule.size(); ++q)
            for (unsigned int c = 0; c < n_components; ++c)
              errors.add_pointwise(
                values_at_max[q][c] -
                exact.value(max_values.quadrature_point(q), c));
        }
    return errors.over_all_ranks(dof_handler.get_communicator());
  }

  template ErrorNorms
  field_errors(const DoFHandler<1> &,
               const TrilinosWrappers::MPI::Vector &,
               const Function<1> &,
               const std::function<bool(const Point<1> &)> &);
  template ErrorNorms
  field_errors(const DoFHandler<2> &,
               const TrilinosWrappers::MPI::Vector &,
               const Function<2> &,
               const std::function<bool(const Point<2> &)> &);
  template ErrorNorms
  field_errors(const DoFHandler<3> &,
               const TrilinosWrappers::MPI::Vector &,
               const Function<3> &,
               const std::function<bool(const Point<3> &)> &);
} // namespace ltn

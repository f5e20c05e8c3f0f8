#include <ltn/base/input_error.h>
#include <ltn/problem/data_entries.h>

namespace ltn
{
  void
  check_at_defaults(ParameterHandler                &prm,
                    const std::vector<DefaultEntry> &entries,
                    const std::string               &scenes)
  {
    for (const auto &[subsection, name, default_value] : entries)
      {
        prm.enter_subsection(subsection);
        const std::string value = prm.get(name);
        prm.leave_subsection();
        check_input(value == default_value,
                    subsection + "/" + name,
                    value,
                    "its default `" + default_value + "`: " + scenes);
      }
  }



  SolutionData::SolutionData(std::string subsection)
    : subsection(std::move(subsection))
  {}



  void
  SolutionData::declare_subsection(
    ParameterHandler            &prm,
    const std::string           &subsection,
    const std::string           &field,
    const std::function<void()> &declare_physics_entries)
  {
    prm.enter_subsection(subsection);
    {
      prm.declare_entry("Exact solution",
                        "",
                        Patterns::Anything(),
                        "The exact solution, " + field +
                          ", if known: errors are reported against it. "
                          "Empty: none.");
      prm.declare_entry("Boundary data",
                        "",
                        Patterns::Anything(),
                        "Dirichlet data g of the local model on its "
                        "Dirichlet boundaries. Empty: the exact solution.");
      prm.declare_entry("Volume constraint data",
                        "",
                        Patterns::Anything(),
                        "Data u_n = g of the nonlocal model on its physical "
                        "collar. Empty: the exact solution.");
      declare_physics_entries();
    }
    prm.leave_subsection();
  }



  void
  SolutionData::parse_subsection(
    ParameterHandler            &prm,
    const std::function<void()> &parse_physics_entries)
  {
    prm.enter_subsection(subsection);
    {
      exact_solution         = prm.get("Exact solution");
      boundary_data          = prm.get("Boundary data");
      volume_constraint_data = prm.get("Volume constraint data");
      parse_physics_entries();
    }
    prm.leave_subsection();
  }



  std::vector<DefaultEntry>
  SolutionData::solution_entries() const
  {
    return {{{subsection, "Exact solution", ""}},
            {{subsection, "Boundary data", ""}},
            {{subsection, "Volume constraint data", ""}}};
  }



  template <int dim>
  std::unique_ptr<Expression<dim>>
  SolutionData::expression(const std::string                   &name,
                           const std::string                   &text,
                           const std::map<std::string, double> &constants,
                           const unsigned int n_components) const
  {
    return std::make_unique<Expression<dim>>(subsection + "/" + name,
                                             text,
                                             constants,
                                             n_components);
  }



  template <int dim>
  std::unique_ptr<Expression<dim>>
  SolutionData::or_exact(const std::string                   &name,
                         const std::string                   &text,
                         const std::map<std::string, double> &constants,
                         const unsigned int                   n_components,
                         const std::string                   &what) const
  {
    check_input(!text.empty() || !exact_solution.empty(),
                subsection + "/" + name,
                text,
                what +
                  "; it may be empty only when an Exact solution is given, "
                  "which is then used");
    return expression<dim>(name,
                           text.empty() ? exact_solution : text,
                           constants,
                           n_components);
  }

#define LTN_INSTANTIATE(dim)                                               \
  template std::unique_ptr<Expression<dim>> SolutionData::expression<dim>( \
    const std::string &,                                                   \
    const std::string &,                                                   \
    const std::map<std::string, double> &,                                 \
    unsigned int) const;                                                   \
  template std::unique_ptr<Expression<dim>> SolutionData::or_exact<dim>(   \
    const std::string &,                                                   \
    const std::string &,                                                   \
    const std::map<std::string, double> &,                                 \
    unsigned int,                                                          \
    const std::string &) const;
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

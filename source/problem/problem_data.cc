#include <deal.II/base/numbers.h>

#include <ltn/base/input_error.h>
#include <ltn/problem/problem_data.h>

namespace ltn
{
  void
  ProblemData::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem data");
    {
      prm.declare_entry("Exact solution",
                        "",
                        Patterns::Anything(),
                        "The exact solution u, if known: errors are reported "
                        "against it. Empty: none.");
      prm.declare_entry("Nonlocal right-hand side",
                        "0",
                        Patterns::Anything(),
                        "f_n in -L u_n = f_n on the nonlocal region.");
      prm.declare_entry("Local right-hand side",
                        "0",
                        Patterns::Anything(),
                        "f_l in -Laplace u_l = f_l on the local region.");
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
      prm.declare_entry("Boundary gradient",
                        "",
                        Patterns::Anything(),
                        "A flux vector q (dim components separated by ';') "
                        "whose normal component q.n is the Neumann data "
                        "du/dn on the local model's Neumann boundaries. "
                        "Empty: zero flux.");
      prm.declare_entry("Plane wave number",
                        "0",
                        Patterns::Double(0),
                        "The wave number k of a plane-wave solution: defines "
                        "the constants k and sigma = sigma(k) of the kernel "
                        "for all expressions.");
    }
    prm.leave_subsection();
  }



  void
  ProblemData::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem data");
    {
      exact_solution         = prm.get("Exact solution");
      nonlocal_rhs           = prm.get("Nonlocal right-hand side");
      local_rhs              = prm.get("Local right-hand side");
      boundary_data          = prm.get("Boundary data");
      volume_constraint_data = prm.get("Volume constraint data");
      boundary_gradient      = prm.get("Boundary gradient");
      wave_number            = prm.get_double("Plane wave number");
    }
    prm.leave_subsection();
  }



  template <int dim>
  ProblemData::Functions<dim>
  ProblemData::functions(const double                         horizon,
                         const std::function<double(double)> &plane_wave_symbol,
                         const double                         h) const
  {
    check_input(wave_number * horizon <= 20,
                "Problem data/Plane wave number",
                to_string(wave_number),
                "k eps must be at most 20 for sigma(k) to be accurate (eps = " +
                  to_string(horizon) + ")");
    const std::map<std::string, double> constants = {
      {"pi", numbers::PI},
      {"eps", horizon},
      {"h", h},
      {"k", wave_number},
      {"sigma", plane_wave_symbol(wave_number)}};

    const auto make = [&](const std::string &name,
                          const std::string &text,
                          const unsigned int n_components = 1) {
      return std::make_unique<Expression<dim>>("Problem data/" + name,
                                               text,
                                               constants,
                                               n_components);
    };
    const auto or_exact = [&](const std::string &name,
                              const std::string &text) {
      check_input(!text.empty() || !exact_solution.empty(),
                  "Problem data/" + name,
                  text,
                  "an expression; it may be empty only when an Exact "
                  "solution is given, which is then used");
      return make(name, text.empty() ? exact_solution : text);
    };

    Functions<dim> f;
    if (!exact_solution.empty())
      f.exact_solution = make("Exact solution", exact_solution);
    f.nonlocal_rhs  = make("Nonlocal right-hand side", nonlocal_rhs);
    f.local_rhs     = make("Local right-hand side", local_rhs);
    f.boundary_data = or_exact("Boundary data", boundary_data);
    f.volume_constraint_data =
      or_exact("Volume constraint data", volume_constraint_data);
    std::string zero_flux = "0";
    for (unsigned int d = 1; d < dim; ++d)
      zero_flux += "; 0";
    f.boundary_gradient =
      make("Boundary gradient",
           boundary_gradient.empty() ? zero_flux : boundary_gradient,
           dim);
    return f;
  }

  template ProblemData::Functions<1>
  ProblemData::functions<1>(double,
                            const std::function<double(double)> &,
                            double) const;
  template ProblemData::Functions<2>
  ProblemData::functions<2>(double,
                            const std::function<double(double)> &,
                            double) const;
  template ProblemData::Functions<3>
  ProblemData::functions<3>(double,
                            const std::function<double(double)> &,
                            double) const;
} // namespace ltn

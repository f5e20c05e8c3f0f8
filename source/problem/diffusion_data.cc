#include <deal.II/base/numbers.h>

#include <ltn/base/input_error.h>
#include <ltn/problem/data_entries.h>
#include <ltn/problem/diffusion_data.h>

namespace ltn
{
  DiffusionData::DiffusionData()
    : SolutionData("Diffusion data")
  {}



  void
  DiffusionData::declare_parameters(ParameterHandler &prm)
  {
    declare_subsection(prm, "Diffusion data", "u", [&prm] {
      prm.declare_entry("Nonlocal right-hand side",
                        "0",
                        Patterns::Anything(),
                        "f_n in -L u_n = f_n on the nonlocal region.");
      prm.declare_entry("Local right-hand side",
                        "0",
                        Patterns::Anything(),
                        "f_l in -Laplace u_l = f_l on the local region.");
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
    });
  }



  void
  DiffusionData::parse_parameters(ParameterHandler &prm)
  {
    parse_subsection(prm, [&] {
      nonlocal_rhs      = prm.get("Nonlocal right-hand side");
      local_rhs         = prm.get("Local right-hand side");
      boundary_gradient = prm.get("Boundary gradient");
      wave_number       = prm.get_double("Plane wave number");
    });
  }



  void
  DiffusionData::check_unused(ParameterHandler &prm)
  {
    std::vector<DefaultEntry> entries = DiffusionData().solution_entries();
    for (const auto &[name, default_value] :
         {std::pair<std::string, std::string>{"Nonlocal right-hand side", "0"},
          {"Local right-hand side", "0"},
          {"Boundary gradient", ""},
          {"Plane wave number", "0"}})
      entries.push_back({{"Diffusion data", name, default_value}});
    check_at_defaults(prm,
                      entries,
                      "diffusion scenes only (Model = diffusion); elasticity "
                      "scenes give their data in `Elasticity data`");
  }



  template <int dim>
  DiffusionData::Functions<dim>
  DiffusionData::functions(
    const double                         horizon,
    const std::function<double(double)> &plane_wave_symbol,
    const double                         h) const
  {
    check_input(wave_number * horizon <= 20,
                "Diffusion data/Plane wave number",
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
      return expression<dim>(name, text, constants, n_components);
    };
    const auto or_exact = [&](const std::string &name,
                              const std::string &text) {
      return this->or_exact<dim>(name, text, constants, 1, "an expression");
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

  template DiffusionData::Functions<1>
  DiffusionData::functions<1>(double,
                              const std::function<double(double)> &,
                              double) const;
  template DiffusionData::Functions<2>
  DiffusionData::functions<2>(double,
                              const std::function<double(double)> &,
                              double) const;
  template DiffusionData::Functions<3>
  DiffusionData::functions<3>(double,
                              const std::function<double(double)> &,
                              double) const;
} // namespace ltn

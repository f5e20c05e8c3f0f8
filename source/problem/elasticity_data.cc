#include <deal.II/base/numbers.h>

#include <ltn/base/input_error.h>
#include <ltn/problem/elasticity_data.h>

#include <array>
#include <vector>

namespace ltn
{
  void
  ElasticityData::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem data");
    {
      prm.declare_entry("Body force",
                        "",
                        Patterns::Anything(),
                        "Elasticity: the body force b (dim components "
                        "separated by ';') of both models. Empty: zero.");
      prm.declare_entry("Traction",
                        "",
                        Patterns::Anything(),
                        "Elasticity: the traction t (dim components) on the "
                        "local model's Neumann faces (the body faces of the "
                        "local region that are not Dirichlet for a "
                        "component). Empty: zero.");
      prm.declare_entry("Pressure",
                        "0",
                        Patterns::Anything(),
                        "Elasticity: a pressure p on the same faces, adding "
                        "the traction -p n (n the outward normal): a negative "
                        "pressure pulls.");
    }
    prm.leave_subsection();
  }



  void
  ElasticityData::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem data");
    {
      exact_solution         = prm.get("Exact solution");
      body_force             = prm.get("Body force");
      boundary_data          = prm.get("Boundary data");
      volume_constraint_data = prm.get("Volume constraint data");
      traction               = prm.get("Traction");
      pressure               = prm.get("Pressure");
      for (const std::string name :
           {"Nonlocal right-hand side", "Local right-hand side"})
        check_input(prm.get(name) == "0",
                    "Problem data/" + name,
                    prm.get(name),
                    "the default 0: diffusion scenes only (elasticity "
                    "scenes give a Body force)");
      check_input(prm.get("Boundary gradient").empty(),
                  "Problem data/Boundary gradient",
                  prm.get("Boundary gradient"),
                  "empty: diffusion scenes only (elasticity scenes give a "
                  "Traction or Pressure)");
      check_input(prm.get_double("Plane wave number") == 0,
                  "Problem data/Plane wave number",
                  prm.get("Plane wave number"),
                  "0: diffusion scenes only");
    }
    prm.leave_subsection();
  }



  void
  ElasticityData::check_unused(ParameterHandler &prm)
  {
    // Each elasticity-only entry with its default: a diffusion scene that
    // sets one would silently ignore it.
    const std::vector<std::array<std::string, 3>> entries = {
      {{"Problem data", "Body force", ""}},
      {{"Problem data", "Traction", ""}},
      {{"Problem data", "Pressure", "0"}},
      {{"Material", "Young's modulus", "1"}},
      {{"Material", "Poisson ratio", "0.25"}},
      {{"Material", "Plane", "strain"}},
      {{"Cracks", "Corners", ""}},
      {{"Postprocess", "Section planes", ""}},
      {{"Postprocess", "Reference crack opening", ""}}};
    for (const auto &[subsection, name, default_value] : entries)
      {
        prm.enter_subsection(subsection);
        const std::string value = prm.get(name);
        prm.leave_subsection();
        check_input(value == default_value,
                    subsection + "/" + name,
                    value,
                    "its default `" + default_value +
                      "`: elasticity scenes only (Model = elasticity)");
      }
  }



  template <int dim>
  ElasticityData::Functions<dim>
  ElasticityData::functions(const Material &material,
                            const double    horizon,
                            const double    h) const
  {
    const std::map<std::string, double> constants = {
      {"pi", numbers::PI},
      {"eps", horizon},
      {"h", h},
      {"E", material.youngs_modulus},
      {"nu", material.poisson_ratio},
      {"lambda", material.lambda(dim)},
      {"mu", material.mu()}};
    std::string zero = "0";
    for (unsigned int d = 1; d < dim; ++d)
      zero += "; 0";

    const auto make = [&](const std::string &name,
                          const std::string &text,
                          const unsigned int n_components = dim) {
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
                  "an expression of " + std::to_string(dim) +
                    " components separated by ';'; it may be empty only "
                    "when an Exact solution is given, which is then used");
      return make(name, text.empty() ? exact_solution : text);
    };

    Functions<dim> f;
    if (!exact_solution.empty())
      f.exact_solution = make("Exact solution", exact_solution);
    f.body_force = make("Body force", body_force.empty() ? zero : body_force);
    f.boundary_data = or_exact("Boundary data", boundary_data);
    f.volume_constraint_data =
      volume_constraint_data.empty() && exact_solution.empty() ?
        make("Volume constraint data",
             boundary_data.empty() ? zero : boundary_data) :
        or_exact("Volume constraint data", volume_constraint_data);
    f.traction = make("Traction", traction.empty() ? zero : traction);
    f.pressure = make("Pressure", pressure, 1);
    return f;
  }

  template ElasticityData::Functions<2>
  ElasticityData::functions<2>(const Material &, double, double) const;
  template ElasticityData::Functions<3>
  ElasticityData::functions<3>(const Material &, double, double) const;
} // namespace ltn

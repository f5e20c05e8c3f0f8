#include <deal.II/base/numbers.h>

#include <ltn/base/input_error.h>
#include <ltn/problem/data_entries.h>
#include <ltn/problem/elasticity_data.h>

#include <array>
#include <vector>

namespace ltn
{
  ElasticityData::ElasticityData()
    : SolutionData("Elasticity data")
  {}



  void
  ElasticityData::declare_parameters(ParameterHandler &prm)
  {
    declare_subsection(
      prm,
      "Elasticity data",
      "the displacement u (dim components separated by ';')",
      [&prm] {
        prm.declare_entry("Body force",
                          "",
                          Patterns::Anything(),
                          "The body force b (dim components "
                          "separated by ';') of both models. Empty: zero.");
        prm.declare_entry("Traction",
                          "",
                          Patterns::Anything(),
                          "The traction t (dim components) on the "
                          "local model's Neumann faces (the body faces of the "
                          "local region that are not Dirichlet for a "
                          "component). Empty: zero.");
        prm.declare_entry("Pressure",
                          "0",
                          Patterns::Anything(),
                          "A pressure p on the same faces, adding "
                          "the traction -p n (n the outward normal): a "
                          "negative pressure pulls.");
      });
  }



  void
  ElasticityData::parse_parameters(ParameterHandler &prm)
  {
    parse_subsection(prm, [&] {
      body_force = prm.get("Body force");
      traction   = prm.get("Traction");
      pressure   = prm.get("Pressure");
    });
  }



  void
  ElasticityData::check_unused(ParameterHandler &prm)
  {
    // Each elasticity-only entry with its default: a diffusion scene that
    // sets one would silently ignore it.
    std::vector<DefaultEntry> entries = ElasticityData().solution_entries();
    const std::vector<DefaultEntry> others = {
      {{"Elasticity data", "Body force", ""}},
      {{"Elasticity data", "Traction", ""}},
      {{"Elasticity data", "Pressure", "0"}},
      {{"Material", "Young's modulus", "1"}},
      {{"Material", "Poisson ratio", "0.25"}},
      {{"Material", "Plane", "strain"}},
      {{"Cracks", "Corners", ""}},
      {{"Postprocess", "Section planes", ""}},
      {{"Postprocess", "Reference crack opening", ""}}};
    entries.insert(entries.end(), others.begin(), others.end());
    check_at_defaults(prm,
                      entries,
                      "elasticity scenes only (Model = elasticity)");
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
      return expression<dim>(name, text, constants, n_components);
    };
    const auto or_exact = [&](const std::string &name,
                              const std::string &text) {
      return this->or_exact<dim>(name,
                                 text,
                                 constants,
                                 dim,
                                 "an expression of " + std::to_string(dim) +
                                   " components separated by ';'");
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

#include <ltn/base/input_error.h>
#include <ltn/problem/material.h>

namespace ltn
{
  void
  Material::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Young's modulus",
                        "1",
                        Patterns::Double(),
                        "Young's modulus E of the isotropic elastic body "
                        "(stress units). Must be positive.");
      prm.declare_entry("Poisson ratio",
                        "0.25",
                        Patterns::Double(),
                        "Poisson's ratio nu, in (-1, 0.5): 0.5 itself is "
                        "incompressible, which neither model can represent.");
      prm.declare_entry("Plane",
                        "strain",
                        Patterns::Selection("strain|stress"),
                        "2D only: `strain` (a slice of a long body, u_z = 0) "
                        "or `stress` (a thin plate, sigma_zz = 0). The two "
                        "give different 2D constants to both models.");
    }
    prm.leave_subsection();
  }



  void
  Material::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      youngs_modulus = prm.get_double("Young's modulus");
      poisson_ratio  = prm.get_double("Poisson ratio");
      plane = prm.get("Plane") == "stress" ? Plane::stress : Plane::strain;
    }
    prm.leave_subsection();
    check_input(youngs_modulus > 0,
                "Material/Young's modulus",
                to_string(youngs_modulus),
                "a positive modulus");
    check_input(poisson_ratio > -1 && poisson_ratio < 0.5,
                "Material/Poisson ratio",
                to_string(poisson_ratio),
                "a ratio strictly between -1 and 0.5 (0.5 is incompressible)");
  }



  double
  Material::mu() const
  {
    return youngs_modulus / (2 * (1 + poisson_ratio));
  }



  double
  Material::lambda(const unsigned int dim) const
  {
    const double nu = poisson_ratio;
    if (dim == 2 && plane == Plane::stress)
      return youngs_modulus * nu / (1 - nu * nu);
    return youngs_modulus * nu / ((1 + nu) * (1 - 2 * nu));
  }



  double
  Material::crack_modulus(const unsigned int dim) const
  {
    const double nu = poisson_ratio;
    return (dim == 2 && plane == Plane::strain) ?
             youngs_modulus / (1 - nu * nu) :
             youngs_modulus;
  }
} // namespace ltn

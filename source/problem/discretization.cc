#include <ltn/base/input_error.h>
#include <ltn/problem/discretization.h>

#include <cmath>

namespace ltn
{
  void
  Discretization::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    {
      prm.declare_entry("Mesh size",
                        "0.125",
                        Patterns::Double(),
                        "Mesh size h of the coarsest level, for both the "
                        "local and the nonlocal discretization (length "
                        "units). It must divide the body and the offsets of "
                        "the nonlocal region a whole number of times.");
      prm.declare_entry("Number of levels",
                        "1",
                        Patterns::Integer(1, 12),
                        "Number of refinement levels; level l has mesh size "
                        "h / 2^l. More than one makes a convergence study.");
    }
    prm.leave_subsection();
  }



  void
  Discretization::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    {
      coarsest_mesh_size = prm.get_double("Mesh size");
      n_levels           = prm.get_integer("Number of levels");
      check_input(coarsest_mesh_size > 0,
                  "Discretization/Mesh size",
                  to_string(coarsest_mesh_size),
                  "the mesh size must be positive");
    }
    prm.leave_subsection();
  }



  double
  Discretization::mesh_size(const unsigned int level) const
  {
    return coarsest_mesh_size / std::pow(2., level);
  }
} // namespace ltn

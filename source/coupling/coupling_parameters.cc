#include <ltn/base/input_error.h>
#include <ltn/coupling/coupling_parameters.h>
#include <ltn/coupling/full_space_direct_solver.h>
#include <ltn/coupling/reduced_space_solver.h>

namespace ltn
{
  void
  CouplingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Coupling");
    {
      prm.declare_entry("Method",
                        "full space direct",
                        Patterns::Selection("full space direct|"
                                            "reduced space cg"),
                        "How to solve the optimality system: `full space "
                        "direct` (states, controls and multipliers in one "
                        "saddle-point system, sparse direct solver) or "
                        "`reduced space cg` (CG on the controls; each "
                        "iteration one forward and one adjoint solve per "
                        "model).");
      prm.declare_entry("Tikhonov parameter",
                        "0",
                        Patterns::Double(0),
                        "alpha >= 0 of the regularization alpha/2 |theta|^2 "
                        "of the controls (Euclidean norm of their values).");
      prm.declare_entry("Relative tolerance",
                        "1e-12",
                        Patterns::Double(0),
                        "Reduction of the residual at which the reduced-space "
                        "CG stops.");
      prm.declare_entry("Maximum iterations",
                        "1000",
                        Patterns::Integer(1),
                        "Iteration limit of the reduced-space CG.");
    }
    prm.leave_subsection();
  }



  void
  CouplingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Coupling");
    {
      method             = prm.get("Method");
      tikhonov_parameter = prm.get_double("Tikhonov parameter");
      relative_tolerance = prm.get_double("Relative tolerance");
      max_iterations     = prm.get_integer("Maximum iterations");
      check_input(relative_tolerance > 0 && relative_tolerance < 1,
                  "Coupling/Relative tolerance",
                  to_string(relative_tolerance),
                  "a tolerance in (0, 1)");
    }
    prm.leave_subsection();
  }



  template <int dim>
  CouplingSolution
  CouplingParameters::solve(const CouplingSystem<dim> &system) const
  {
    if (method == "reduced space cg")
      return solve_reduced_space_cg(system, relative_tolerance, max_iterations);
    return solve_full_space_direct(system);
  }

  template CouplingSolution
  CouplingParameters::solve(const CouplingSystem<1> &) const;
  template CouplingSolution
  CouplingParameters::solve(const CouplingSystem<2> &) const;
  template CouplingSolution
  CouplingParameters::solve(const CouplingSystem<3> &) const;
} // namespace ltn

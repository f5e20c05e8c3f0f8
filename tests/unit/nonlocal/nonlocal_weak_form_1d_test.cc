// The 1D nonlocal weak form on polynomials it must treat exactly: for every
// u in the FE space with degree <= 3, a(u, phi_i) = (-u'', phi_i) on every
// free node, because L u = u'' for such u. This checks the breakpoint
// quadrature, including the singular kernels, to round-off.

#include <deal.II/base/function_lib.h>
#include <deal.II/base/function_parser.h>

#include <deal.II/numerics/vector_tools.h>

#include <ltn/nonlocal/nonlocal_weak_form_1d.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "seed_geometry.h"

using namespace ltn;

namespace
{
  /** max over free rows |A I(u) - F(-u'')| / max |F| (or 1). */
  double
  consistency_error(const std::string &kernel_name,
                    const double       eps,
                    const unsigned int degree,
                    const std::string &u,
                    const std::string &minus_u_second_derivative)
  {
    const Geometry<1>  geometry = seed_geometry();
    const Kernel       kernel(parse_selection(kernel_names(), kernel_name),
                        0.3,
                        1,
                        eps);
    NonlocalWeakForm1D nonlocal(geometry, kernel, degree, 1. / 32);
    FunctionParser<1>  exact(u), rhs(minus_u_second_derivative);
    nonlocal.assemble(rhs, exact);

    const DiscreteModel          &model       = nonlocal.get_model();
    TrilinosWrappers::MPI::Vector interpolant = model.new_vector();
    VectorTools::interpolate(nonlocal.get_dof_handler(), exact, interpolant);
    TrilinosWrappers::MPI::Vector Au = model.new_vector();
    model.matrix.vmult(Au, interpolant);

    double error = 0, scale = 0;
    for (const auto i : model.owned)
      if (model.role(i) == DofRole::free)
        {
          error = std::max(error, std::abs(Au(i) - model.rhs(i)));
          scale = std::max(scale, std::abs(model.rhs(i)));
        }
    // Rows of A are O(1/h): measure against that size for zero data.
    return error / std::max(scale, 1.);
  }
} // namespace



TEST_CASE("nonlocal weak form annihilates constants and linears", "[nonlocal]")
{
  for (const std::string kernel :
       {"constant", "inverse distance", "fractional"})
    for (const double eps : {1. / 32, 0.05, 3. / 32, 0.2})
      for (const unsigned int degree : {1u, 2u})
        for (const std::string u : {"1", "x", "3 - 2*x"})
          {
            INFO(kernel << " eps " << eps << " P" << degree << " u = " << u);
            CHECK(consistency_error(kernel, eps, degree, u, "0") < 1e-12);
          }
}



TEST_CASE("nonlocal weak form equals the Laplacian on quadratics (P2)",
          "[nonlocal]")
{
  for (const std::string kernel :
       {"constant", "inverse distance", "fractional"})
    for (const double eps : {1. / 32, 0.05, 3. / 32, 0.2})
      {
        INFO(kernel << " eps " << eps);
        CHECK(consistency_error(kernel, eps, 2, "x^2", "-2") < 1e-11);
        CHECK(consistency_error(kernel, eps, 2, "1 + x - 0.5*x^2", "1") <
              1e-11);
      }
}



TEST_CASE("nonlocal degrees of freedom are classified by region", "[nonlocal]")
{
  const Geometry<1>  geometry = seed_geometry();
  const double       h = 1. / 16, eps = 0.15;
  const Kernel       kernel(KernelKind::constant, 0.5, 1, eps);
  NonlocalWeakForm1D nonlocal(geometry, kernel, 1, h);
  const auto        &points = nonlocal.get_support_points();
  const auto        &model  = nonlocal.get_model();
  // ceil(eps / h) = 3 collar elements per side: nodes -3h .. 1 + 3h.
  REQUIRE(points.size() == 16 + 6 + 1);
  for (std::size_t i = 0; i < points.size(); ++i)
    {
      const double x = points[i][0];
      if (x <= 1e-12)
        CHECK(model.role(i) == DofRole::fixed);
      else if (x >= 1 - 1e-12)
        CHECK(model.role(i) == DofRole::control);
      else
        CHECK(model.role(i) == DofRole::free);
    }
}

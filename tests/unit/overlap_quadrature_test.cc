// The overlap quadrature evaluates FE fields exactly at its points, and its
// weights integrate exactly over Omega_b = [0.75, 1 + eps].

#include <deal.II/base/function_parser.h>

#include <deal.II/numerics/vector_tools.h>

#include <ltn/coupling/overlap_quadrature.h>
#include <ltn/local/poisson_problem.h>
#include <ltn/nonlocal/nonlocal_weak_form_1d.h>

#include <catch2/catch.hpp>

#include "seed_geometry.h"

using namespace ltn;

TEST_CASE("overlap quadrature interpolates FE fields exactly", "[coupling]")
{
  const Geometry<1> geometry = seed_geometry();

  for (const unsigned int degree : {1u, 2u})
    for (const double eps : {0.1, 0.125, 0.3})
      {
        const double                  h = 1. / 16;
        const Kernel                  kernel("constant", 0.5, 1, eps);
        NonlocalWeakForm1D            nonlocal(geometry, kernel, degree, h);
        PoissonProblem<1>::Parameters parameters;
        parameters.degree = degree;
        PoissonProblem<1> local(geometry, parameters, h);

        const auto overlap = create_overlap_quadrature_1d(
          geometry, eps, nonlocal.get_dof_handler(), local.get_dof_handler());

        double measure = 0;
        for (const double w : overlap.weights)
          measure += w;
        INFO("P" << degree << " eps " << eps);
        CHECK(measure == Approx(1 + eps - 0.75).epsilon(1e-14));

        const std::string u = (degree == 1) ? "2*x - 1" : "x^2 - 3*x";
        FunctionParser<1> field(u);
        Vector<double>    u_n(nonlocal.get_dof_handler().n_dofs()),
          u_l(local.get_dof_handler().n_dofs());
        VectorTools::interpolate(nonlocal.get_dof_handler(), field, u_n);
        VectorTools::interpolate(local.get_dof_handler(), field, u_l);
        for (std::size_t q = 0; q < overlap.points.size(); ++q)
          {
            double e = 0, p = 0;
            for (const auto &[i, value] : overlap.nonlocal_rows[q])
              e += value * u_n[i];
            for (const auto &[j, value] : overlap.local_rows[q])
              p += value * u_l[j];
            const double exact = field.value(overlap.points[q]);
            CHECK(e == Approx(exact).margin(1e-13));
            CHECK(p == Approx(exact).margin(1e-13));
          }
      }
}

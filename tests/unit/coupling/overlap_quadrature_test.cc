// The overlap quadrature evaluates FE fields exactly at its points: in 1D
// its weights integrate exactly over Omega_b = [0.75, 1 + eps]; in 2D and 3D
// every particle of Omega_b is a point exactly once over all ranks, also
// where particles lie on cell faces.

#include <deal.II/base/function_parser.h>

#include <deal.II/numerics/vector_tools.h>

#include <ltn/coupling/system/overlap_quadrature.h>
#include <ltn/local/poisson_problem.h>
#include <ltn/nonlocal/nonlocal_weak_form_1d.h>
#include <ltn/nonlocal/particle_diffusion.h>

#include <catch2/catch.hpp>

#include "box_layout.h"
#include "seed_geometry.h"

using namespace ltn;

TEST_CASE("overlap quadrature interpolates FE fields exactly", "[coupling]")
{
  const Geometry<1> geometry = seed_geometry();

  for (const unsigned int degree : {1u, 2u})
    for (const double eps : {0.1, 0.125, 0.3})
      {
        const double       h = 1. / 16;
        const Kernel       kernel(KernelKind::constant, 0.5, 1, eps);
        NonlocalWeakForm1D nonlocal(geometry, kernel, degree, h);
        LocalParameters<1> parameters;
        parameters.degree = degree;
        PoissonProblem<1> local(geometry, parameters, h, MPI_COMM_SELF);

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



namespace
{
  /**
   * Interpolate a polynomial of the degree of FE_Q(p) on the local mesh and
   * evaluate it at the particle overlap points; count the points.
   */
  template <int dim>
  void
  check_particle_overlap(const unsigned int degree, const double spacing)
  {
    // Omega_n = (0,1)^dim on the left of the body (0,2) x (0,1)^(dim-1).
    const Geometry<dim> geometry =
      box_layout<dim>(slab<dim>(0, 2, 0, 1), {slab<dim>(0, 1, 0, 1)}, 0.25);
    const double h = 1. / 8, eps = 2 * spacing;

    LocalParameters<dim> parameters;
    parameters.degree = degree;
    PoissonProblem<dim>    local(geometry, parameters, h, MPI_COMM_WORLD);
    const Kernel           kernel(KernelKind::constant, 0.5, dim, eps);
    ParticleDiffusion<dim> particles(geometry, kernel, spacing, MPI_COMM_WORLD);
    const auto             overlap = create_overlap_quadrature(geometry,
                                                   eps,
                                                   particles,
                                                   local.get_dof_handler());

    const std::string   variables = (dim == 2) ? "x,y" : "x,y,z";
    FunctionParser<dim> u(degree == 1 ?
                            (dim == 2 ? "1 + 2*x - y" : "1 + 2*x - y + z") :
                            (dim == 2 ? "x*y - x^2 + 3*y^2" :
                                        "x*y - x^2 + y*z - z^2"),
                          "",
                          variables);
    TrilinosWrappers::MPI::Vector field = local.get_model().new_vector();
    VectorTools::interpolate(local.get_dof_handler(), u, field);
    const auto ghosted = local.get_model().ghosted(field);

    const auto &lattice = particles.get_lattice();
    double      worst   = 0;
    for (std::size_t q = 0; q < overlap.points.size(); ++q)
      {
        REQUIRE(overlap.nonlocal_rows[q].size() == 1);
        const auto [number, one] = overlap.nonlocal_rows[q][0];
        CHECK(one == 1.);
        CHECK(
          lattice.position(lattice.index(number)).distance(overlap.points[q]) <
          1e-14);
        double value = 0;
        for (const auto &[j, p] : overlap.local_rows[q])
          value += p * ghosted(j);
        worst = std::max(worst, std::abs(value - u.value(overlap.points[q])));
      }
    CHECK(Utilities::MPI::max(worst, MPI_COMM_WORLD) < 1e-13);

    // The particles of Omega_b: the control particles, and those of Omega_n
    // in Omega_l.
    std::size_t expected = 0;
    for (const auto i : particles.get_model().owned)
      {
        const auto index = lattice.index(i);
        const auto role  = particles.role(index);
        expected += role == DofRole::control ||
                    (role == DofRole::free &&
                     geometry.in_local_region(lattice.position(index)));
      }
    const std::size_t points = overlap.points.size();
    CHECK(Utilities::MPI::sum(points, MPI_COMM_WORLD) ==
          Utilities::MPI::sum(expected, MPI_COMM_WORLD));
    CHECK(Utilities::MPI::sum(points, MPI_COMM_WORLD) > 0);
  }
} // namespace



TEST_CASE("particle overlap points interpolate FE fields exactly",
          "[coupling][particles]")
{
  // Spacing h/2 lines up with the mesh; 0.4 h does not, and puts particles
  // on cell faces (x = 0.125 = 2.5 * 0.05).
  for (const unsigned int degree : {1u, 2u})
    for (const double spacing : {1. / 16, 0.05})
      {
        INFO("P" << degree << " spacing " << spacing);
        check_particle_overlap<2>(degree, spacing);
        check_particle_overlap<3>(degree, spacing);
      }
}

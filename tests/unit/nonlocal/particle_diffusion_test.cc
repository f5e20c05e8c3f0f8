// The particle operator of nonlocal diffusion on polynomials: at every
// particle of the nonlocal region, -L_h p = -Laplace p to round-off for every
// polynomial of degree <= 3 (quadratic exactness of the stencil, cubic terms
// cancelling by the lattice's symmetry), and constants give zero.

#include <deal.II/base/function_parser.h>

#include <ltn/nonlocal/particle_diffusion.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "box_layout.h"

using namespace ltn;

namespace
{
  template <int dim>
  Geometry<dim>
  unit_layout()
  {
    // Omega_n = (0,1)^dim touching the body on its lower faces.
    return box_layout<dim>(slab<dim>(0, 2, 0, 1),
                           {slab<dim>(0, 1, 0, 1)},
                           0.25);
  }

  /** max over free particles |A p - (-Laplace p)|, relative to max |A|. */
  template <int dim>
  double
  operator_defect(const std::string &kernel_name,
                  const double       m,
                  const double       h,
                  const std::string &p,
                  const std::string &minus_laplacian)
  {
    const Geometry<dim>    geometry = unit_layout<dim>();
    const Kernel           kernel(parse_selection(kernel_names(), kernel_name),
                        0.5,
                        dim,
                        m * h);
    ParticleDiffusion<dim> particles(geometry, kernel, h, MPI_COMM_WORLD);
    const std::string      variables = dim == 2 ? "x,y" : "x,y,z";
    FunctionParser<dim>    u(p), f(minus_laplacian);
    particles.assemble(f, u);

    const auto                   &model     = particles.get_model();
    const auto                    positions = particles.owned_positions();
    TrilinosWrappers::MPI::Vector values    = model.new_vector(),
                                  Au        = model.new_vector();
    std::size_t k                           = 0;
    for (const auto i : model.owned)
      values(i) = u.value(positions[k++]);
    values.compress(VectorOperation::insert);
    model.matrix.vmult(Au, values);
    double defect = 0, diagonal = 0;
    for (const auto i : model.owned)
      if (model.role(i) == DofRole::free)
        {
          defect   = std::max(defect, std::abs(Au(i) - model.rhs(i)));
          diagonal = model.matrix.diag_element(i);
        }
    // Scale: the diagonal of A, ~ 1/h^2.
    return Utilities::MPI::max(defect, MPI_COMM_WORLD) /
           Utilities::MPI::max(diagonal, MPI_COMM_WORLD);
  }
} // namespace



TEST_CASE("particle operator is exact on polynomials of degree 3 in 2D",
          "[particles][patch]")
{
  const std::vector<std::pair<std::string, std::string>> polynomials = {
    {"1", "0"},
    {"x", "0"},
    {"3*y - x", "0"},
    {"x^2", "-2"},
    {"x*y", "0"},
    {"y^2 - 0.5*x^2", "-1"},
    {"x^3 + x*y^2", "-8*x"},
    {"x^2*y", "-2*y"}};
  for (const std::string kernel : {"constant", "inverse distance"})
    for (const double m : {1., 2., 2.5, 3., 4.2, 6.})
      for (const auto &[p, f] : polynomials)
        {
          INFO(kernel << " m " << m << " p = " << p);
          CHECK(operator_defect<2>(kernel, m, 1. / 16, p, f) < 1e-12);
        }
}



TEST_CASE("particle operator is exact on polynomials of degree 3 in 3D",
          "[particles][patch]")
{
  const std::vector<std::pair<std::string, std::string>> polynomials = {
    {"1", "0"},
    {"x - 2*z", "0"},
    {"z^2", "-2"},
    {"x*y + y*z", "0"},
    {"x^2 + y^2 + z^2", "-6"},
    {"x*y*z + z^3", "-6*z"}};
  for (const std::string kernel : {"constant", "inverse distance"})
    for (const double m : {2., 2.5, 3.})
      for (const auto &[p, f] : polynomials)
        {
          INFO(kernel << " m " << m << " p = " << p);
          CHECK(operator_defect<3>(kernel, m, 1. / 8, p, f) < 1e-12);
        }
}



TEST_CASE("stencil moments match the kernel's", "[particles]")
{
  for (const std::string kernel : {"constant", "inverse distance"})
    for (const double m : {2., 3.5, 5.})
      {
        const double h = 0.01;
        const Kernel k2(parse_selection(kernel_names(), kernel), 0.5, 2, m * h);
        const LatticeStencil<2> stencil(k2, h);
        INFO(kernel << " m " << m);
        CHECK(stencil.exact_degree() == 4);
        // Second moment in x: 1; fourth moments: exact ones.
        double second = 0, fourth = 0, mixed = 0;
        for (std::size_t j = 0; j < stencil.offsets().size(); ++j)
          {
            const double x = stencil.offsets()[j][0] * h;
            const double y = stencil.offsets()[j][1] * h;
            second += stencil.coefficients()[j] * x * x;
            fourth += stencil.coefficients()[j] * std::pow(x / (m * h), 4);
            mixed +=
              stencil.coefficients()[j] * x * x * y * y / std::pow(m * h, 4);
          }
        CHECK(second == Approx(1).epsilon(1e-12));
        CHECK(
          fourth ==
          Approx(LatticeStencil<2>::exact_moment(k2, {{4, 0}})).epsilon(1e-12));
        CHECK(
          mixed ==
          Approx(LatticeStencil<2>::exact_moment(k2, {{2, 2}})).epsilon(1e-12));
        // Every coefficient positive: the operator stays an M-matrix.
        for (const double a : stencil.coefficients())
          CHECK(a > 0);
      }
}

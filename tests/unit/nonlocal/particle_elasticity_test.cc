// The LPS particle operator against the continuum it discretizes: zero on
// rigid-body motions (with and without cracks), equal to Navier–Cauchy on
// every quadratic displacement at every particle of the nonlocal region (its
// dilatation equal to div u), in 2D (plane strain and plane stress constants)
// and 3D, for both influence functions and several horizons; and a crack
// across the whole lattice decouples the two sides exactly.

#include <ltn/base/matrix_rows.h>
#include <ltn/nonlocal/particle_elasticity.h>
#include <ltn/problem/material.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "box_layout.h"

using namespace ltn;

namespace
{
  /** The body (0,2)x(0,1)^(dim-1), Omega_n = (0.25,1.25)x(0.25,0.75)^..., */
  template <int dim>
  Geometry<dim>
  bar_layout()
  {
    return box_layout<dim>(slab<dim>(0, 2, 0, 1),
                           {slab<dim>(0.25, 1.25, 0.25, 0.75)},
                           0.125);
  }

  /** A displacement u_a = 1/2 x.H_a x + g_a.x + c_a (or W x + c). */
  template <int dim>
  struct Displacement : public Function<dim>
  {
    Displacement()
      : Function<dim>(dim)
    {}
    double
    value(const Point<dim> &x, const unsigned int a) const override
    {
      return 0.5 * x * (H[a] * x) + g[a] * x + c[a];
    }
    double
    divergence(const Point<dim> &x) const
    {
      double div = 0;
      for (unsigned int a = 0; a < dim; ++a)
        div += (H[a] * x)[a] + g[a][a];
      return div;
    }
    /** -[(lambda + mu) grad div u + mu Laplace u]. */
    Tensor<1, dim>
    body_force(const double lambda, const double mu) const
    {
      Tensor<1, dim> b;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int c = 0; c < dim; ++c)
          b[c] -= (lambda + mu) * H[a][a][c] + (a == c ? mu * trace(H[a]) : 0);
      return b;
    }
    std::array<Tensor<2, dim>, dim> H;
    std::array<Tensor<1, dim>, dim> g;
    Tensor<1, dim>                  c;
  };

  template <int dim>
  Displacement<dim>
  random_quadratic(std::mt19937 &random)
  {
    std::uniform_real_distribution<double> coefficient(-1, 1);
    Displacement<dim>                      u;
    for (unsigned int a = 0; a < dim; ++a)
      {
        for (unsigned int b = 0; b < dim; ++b)
          {
            u.g[a][b] = coefficient(random);
            for (unsigned int c = 0; c <= b; ++c)
              u.H[a][b][c] = u.H[a][c][b] = coefficient(random);
          }
        u.c[a] = coefficient(random);
      }
    return u;
  }

  template <int dim>
  Displacement<dim>
  random_rigid_motion(std::mt19937 &random)
  {
    std::uniform_real_distribution<double> coefficient(-1, 1);
    Displacement<dim>                      u;
    for (unsigned int a = 0; a < dim; ++a)
      {
        u.c[a] = coefficient(random);
        for (unsigned int b = 0; b < a; ++b)
          {
            u.g[a][b] = coefficient(random);
            u.g[b][a] = -u.g[a][b];
          }
      }
    return u;
  }

  /**
   * max over the free rows of |(M x)_i - r_i| / sum_j |M_ij x_j|, where x
   * holds u and theta = div u at every particle (zero where theta is fixed)
   * and r_i is b(x_i) in displacement rows and 0 in dilatation rows.
   */
  template <int dim>
  double
  relative_defect(const ParticleElasticity<dim> &particles,
                  const Displacement<dim>       &u,
                  const Tensor<1, dim>          &b)
  {
    const auto                   &model    = particles.get_model();
    const auto                   &lat      = particles.get_lattice();
    TrilinosWrappers::MPI::Vector x        = model.new_vector(),
                                  Mx       = model.new_vector(),
                                  absolute = model.new_vector();
    for (const auto i : model.owned)
      {
        const auto       n = i / (dim + 1);
        const unsigned   c = i % (dim + 1);
        const Point<dim> p = lat.position(lat.index(n));
        x(i)               = (c < dim)                      ? u.value(p, c) :
                             model.role(i) == DofRole::free ? u.divergence(p) :
                                                              0.;
      }
    x.compress(VectorOperation::insert);
    model.matrix.vmult(Mx, x);
    TrilinosWrappers::MPI::Vector x_ghosted = model.ghosted(x);
    double                        defect    = 0;
    for (const auto i : model.owned)
      if (model.role(i) == DofRole::free)
        {
          double scale = 0;
          for_each_in_row(model.matrix, i, [&](const auto j, const double v) {
            scale += std::abs(v * x_ghosted(j));
          });
          const unsigned c        = i % (dim + 1);
          const double   expected = (c < dim) ? b[c] : 0.;
          defect = std::max(defect, std::abs(Mx(i) - expected) / scale);
        }
    return Utilities::MPI::max(defect, MPI_COMM_WORLD);
  }

  template <int dim>
  void
  check_quadratic_exactness(const std::string &influence,
                            const double       m,
                            const Material    &material)
  {
    const Geometry<dim>     geometry = bar_layout<dim>();
    const double            h        = (dim == 2) ? 1. / 32 : 1. / 16;
    const double            lambda = material.lambda(dim), mu = material.mu();
    ParticleElasticity<dim> particles(
      geometry,
      Kernel(parse_selection(kernel_names(), influence), 0.5, dim, m * h),
      h,
      lambda,
      mu,
      {},
      MPI_COMM_WORLD);
    std::mt19937 random(dim * 100 + static_cast<int>(10 * m));
    for (unsigned int trial = 0; trial < 2; ++trial)
      {
        const auto           u = random_quadratic<dim>(random);
        const Tensor<1, dim> b = u.body_force(lambda, mu);
        particles.assemble(ConstantFunction<dim>(b.begin_raw(), dim), u);
        const double defect = relative_defect(particles, u, b);
        INFO(dim << "D, " << influence << ", m = " << m << ", nu = "
                 << material.poisson_ratio << ": defect " << defect);
        CHECK(defect < 1e-12);
      }
  }
} // namespace



TEST_CASE("LPS equals Navier-Cauchy on quadratic displacements", "[lps][unit]")
{
  Material material;
  for (const double nu : {0.1, 0.25, 0.45})
    {
      material.poisson_ratio = nu;
      for (const auto plane :
           {Material::Plane::strain, Material::Plane::stress})
        {
          material.plane = plane;
          for (const std::string influence : {"constant", "inverse distance"})
            for (const double m : {2., 3.})
              check_quadratic_exactness<2>(influence, m, material);
        }
      material.plane = Material::Plane::strain;
      for (const std::string influence : {"constant", "inverse distance"})
        check_quadratic_exactness<3>(influence, 2., material);
    }
  material.poisson_ratio = 0.3;
  check_quadratic_exactness<2>("constant", 5., material);
  check_quadratic_exactness<3>("constant", 3., material);
}



namespace
{
  /** A crack of the plane x_0 = c that reaches far beyond the lattice. */
  template <int dim>
  Crack<dim>
  crack_across(const double c)
  {
    Crack<dim> crack;
    for (unsigned int k = 0; k < dim; ++k)
      {
        crack.corners[k][0] = c;
        for (unsigned int d = 1; d < dim; ++d)
          crack.corners[k][d] = (k == d) ? 10 : -10;
      }
    return crack;
  }

  template <int dim>
  void
  check_rigid_motions_and_crack(const std::string &influence)
  {
    const Geometry<dim> geometry = bar_layout<dim>();
    const double        h        = (dim == 2) ? 1. / 32 : 1. / 16;
    const double        lambda = 1.3, mu = 0.7, plane = 0.75;
    // An inner crack and one across the whole lattice at x = 0.75.
    Crack<dim> inner = crack_across<dim>(0.5);
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int d = 1; d < dim; ++d)
        inner.corners[k][d] = (k == d) ? 0.6 : 0.4;
    ParticleElasticity<dim> particles(
      geometry,
      Kernel(parse_selection(kernel_names(), influence), 0.5, dim, 3 * h),
      h,
      lambda,
      mu,
      {inner, crack_across<dim>(plane)},
      MPI_COMM_WORLD);
    std::mt19937 random(dim);
    const auto   u = random_rigid_motion<dim>(random);
    particles.assemble(ZeroFunction<dim>(dim), u);
    const double defect = relative_defect(particles, u, Tensor<1, dim>());
    INFO(dim << "D, " << influence << ": rigid motion defect " << defect);
    CHECK(defect < 1e-12);

    // No entry of a row on one side of the plane in a column on the other.
    const auto  &model   = particles.get_model();
    const auto  &lat     = particles.get_lattice();
    unsigned int coupled = 0, broken = 0;
    for (const auto i : model.owned)
      {
        const double xi = lat.position(lat.index(i / (dim + 1)))[0];
        for_each_in_row(model.matrix, i, [&](const auto j, const double v) {
          const double xj = lat.position(lat.index(j / (dim + 1)))[0];
          if ((xi - plane) * (xj - plane) < 0 && v != 0)
            ++coupled;
        });
      }
    for (const double f : particles.owned_broken_bond_fractions())
      broken += f > 0 ? 1 : 0;
    CHECK(Utilities::MPI::sum(coupled, MPI_COMM_WORLD) == 0);
    CHECK(Utilities::MPI::sum(broken, MPI_COMM_WORLD) > 0);
  }
} // namespace



TEST_CASE("LPS is zero on rigid motions and a crack decouples its sides",
          "[lps][unit]")
{
  for (const std::string influence : {"constant", "inverse distance"})
    {
      check_rigid_motions_and_crack<2>(influence);
      check_rigid_motions_and_crack<3>(influence);
    }
}

// The local elasticity model reproduces what its elements contain: linear
// displacements with FE_Q(1), quadratic ones (with their body force, a
// varying traction and hanging nodes) with FE_Q(2), and uniaxial tension on
// rollers, with the section forces equal to the applied load; in 2D (plane
// strain) and 3D, on one or two ranks; the free block factorized alone,
// with hanging nodes too, solving as the LU of the whole matrix. Bad
// `Dirichlet components` are an InputError.

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/numerics/vector_tools.h>

#include <ltn/app/parameter_reading.h>
#include <ltn/base/field_errors.h>
#include <ltn/base/input_error.h>
#include <ltn/local/elasticity_problem.h>
#include <ltn/model_solvers/model_solver.h>
#include <ltn/output/elasticity_output.h>
#include <ltn/scene/diffusion_scene.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "box_layout.h"
#include "lu_difference.h"

using namespace ltn;

namespace
{
  const double lambda = 1.5, mu = 0.75;

  /** The body (0,2) x (0,1)^(dim-1), local model only. */
  template <int dim>
  Geometry<dim>
  box_geometry()
  {
    Geometry<dim> geometry;
    geometry.models = Geometry<dim>::Models::local_only;
    for (unsigned int d = 0; d < dim; ++d)
      geometry.body.upper[d] = (d == 0) ? 2 : 1;
    geometry.set_nonlocal_boxes({geometry.body});
    return geometry;
  }



  /** `u_c = a_c + g_c . x + x . H_c x / 2`, and its stress and body force. */
  template <int dim>
  class Polynomial : public Function<dim>
  {
  public:
    explicit Polynomial(const bool quadratic)
      : Function<dim>(dim)
    {
      for (unsigned int c = 0; c < dim; ++c)
        {
          a[c] = 0.1 * (c + 1);
          for (unsigned int j = 0; j < dim; ++j)
            {
              g[c][j] = 0.3 * std::sin(1. + c + 2. * j);
              if (quadratic)
                for (unsigned int k = j; k < dim; ++k)
                  H[c][j][k] = 0.2 * std::cos(1. + 3. * c + j + k);
            }
        }
    }

    double
    value(const Point<dim> &p, const unsigned int c) const override
    {
      return a[c] + g[c] * p + 0.5 * (p * (H[c] * p));
    }

    SymmetricTensor<2, dim>
    stress(const Point<dim> &p) const
    {
      Tensor<2, dim> gradient;
      for (unsigned int c = 0; c < dim; ++c)
        gradient[c] = g[c] + H[c] * p;
      const SymmetricTensor<2, dim> strain = symmetrize(gradient);
      return lambda * trace(strain) * unit_symmetric_tensor<dim>() +
             2 * mu * strain;
    }

    /** `b = -[(lambda + mu) grad div u + mu Laplace u]`, constant. */
    Vector<double>
    body_force() const
    {
      Vector<double> b(dim);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          b[i] -= (lambda + mu) * H[j][i][j] + mu * H[i][j][j];
      return b;
    }

  private:
    Tensor<1, dim>                           a;
    std::array<Tensor<1, dim>, dim>          g;
    std::array<SymmetricTensor<2, dim>, dim> H;
  };



  /** `sigma(u) e_0` of a Polynomial: its traction on the face x+. */
  template <int dim>
  class TractionOnXPlus : public Function<dim>
  {
  public:
    explicit TractionOnXPlus(const Polynomial<dim> &u)
      : Function<dim>(dim)
      , u(u)
    {}

    double
    value(const Point<dim> &p, const unsigned int c) const override
    {
      return u.stress(p)[c][0];
    }

  private:
    const Polynomial<dim> &u;
  };



  /** @p value in component @p component where x = 2, zero elsewhere. */
  template <int dim>
  class OnRightEnd : public Function<dim>
  {
  public:
    OnRightEnd(const unsigned int n_components,
               const unsigned int component,
               const double       value)
      : Function<dim>(n_components)
      , component(component)
      , load(value)
    {}

    double
    value(const Point<dim> &p, const unsigned int c) const override
    {
      return (c == component && std::abs(p[0] - 2) < 1e-9) ? load : 0.;
    }

  private:
    const unsigned int component;
    const double       load;
  };



  /** Solve the closed model directly; the field with ghosts. */
  template <int dim>
  TrilinosWrappers::MPI::Vector
  solve(const ElasticityProblem<dim> &problem)
  {
    const ModelSolver solver(problem.get_model(), false);
    return problem.get_model().ghosted(
      solver.forward(solver.new_control_vector(), true));
  }



  /** The largest nodal error against @p exact, relative to its largest
   * nodal value, over all ranks. */
  template <int dim>
  double
  relative_nodal_error(const ElasticityProblem<dim>        &problem,
                       const TrilinosWrappers::MPI::Vector &solution,
                       const Function<dim>                 &exact)
  {
    TrilinosWrappers::MPI::Vector interpolant =
      problem.get_model().new_vector();
    VectorTools::interpolate(problem.get_dof_handler(), exact, interpolant);
    double error = 0, size = 0;
    for (const auto i : problem.get_model().owned)
      {
        error = std::max(error, std::abs(solution(i) - interpolant(i)));
        size  = std::max(size, std::abs(interpolant(i)));
      }
    const MPI_Comm comm = problem.get_model().communicator;
    return Utilities::MPI::max(error, comm) / Utilities::MPI::max(size, comm);
  }



  /**
   * Degree @p degree, every face of the box Dirichlet but @p free_face
   * (none by default).
   */
  template <int dim>
  LocalParameters<dim>
  dirichlet_box(const unsigned int degree,
                const unsigned int free_face = numbers::invalid_unsigned_int)
  {
    LocalParameters<dim> parameters;
    parameters.degree = degree;
    for (unsigned int face = 0; face < 2 * dim; ++face)
      if (face != free_face)
        parameters.dirichlet_faces.insert(face);
    return parameters;
  }



  template <int dim>
  LocalParameters<dim>
  parse_local_parameters(const std::string &boundaries,
                         const std::string &components,
                         const unsigned int degree = 1)
  {
    ParameterHandler prm;
    LocalParameters<dim>::declare_parameters(prm);
    prm.enter_subsection("Local model");
    prm.set("Finite element degree", std::to_string(degree));
    prm.set("Dirichlet boundaries", boundaries);
    prm.set("Dirichlet components", components);
    prm.leave_subsection();
    LocalParameters<dim> parameters;
    parameters.parse_parameters(prm);
    return parameters;
  }



  template <int dim>
  void
  check_linear()
  {
    const Geometry<dim>        geometry   = box_geometry<dim>();
    const LocalParameters<dim> parameters = dirichlet_box<dim>(1);
    ElasticityProblem<dim>     problem(
      geometry, parameters, lambda, mu, 0.25, MPI_COMM_WORLD);
    CHECK(problem.lambda() == lambda);
    CHECK(problem.mu() == mu);

    const Polynomial<dim>              u(false);
    const Functions::ZeroFunction<dim> zero(dim), no_pressure(1);
    problem.assemble(zero, u, zero, no_pressure);
    CHECK(problem.get_model().n_controls() == 0);
    const auto solution = solve(problem);
    CHECK(relative_nodal_error(problem, solution, u) < 1e-12);

    // field_errors of a vector field: exact in L2 and max.
    const ErrorNorms errors =
      field_errors<dim>(problem.get_dof_handler(),
                        solution,
                        u,
                        [](const Point<dim> &) { return true; });
    CHECK(errors.l2() < 1e-12);
    CHECK(errors.linf < 1e-12);
  }



  template <int dim>
  void
  check_quadratic()
  {
    // Dirichlet everywhere but x+, which carries the varying traction.
    const Geometry<dim>        geometry   = box_geometry<dim>();
    const LocalParameters<dim> parameters = dirichlet_box<dim>(2, 1);
    ElasticityProblem<dim>     problem(
      geometry, parameters, lambda, mu, 0.25, MPI_COMM_WORLD);

    const Polynomial<dim>                  u(true);
    const Functions::ConstantFunction<dim> b(u.body_force());
    const TractionOnXPlus<dim>             traction(u);
    const Functions::ZeroFunction<dim>     no_pressure(1);
    problem.assemble(b, u, traction, no_pressure);
    // The direct solver factorizes the symmetric positive definite free
    // block alone (doc/discretization.md, 'The reduced space'), with
    // hanging nodes
    // too (below).
    CHECK(ModelDirectSolver(problem.get_model()).factorizes_free_block());
    auto solution = solve(problem);
    CHECK(relative_nodal_error(problem, solution, u) < 1e-10);

    // Again with hanging nodes: the field stays exact.
    const types::global_dof_index n_dofs = problem.get_dof_handler().n_dofs();
    problem.refine(solution, [](const Point<dim> &, double) { return true; });
    CHECK(problem.get_dof_handler().n_dofs() > n_dofs);
    problem.assemble(b, u, traction, no_pressure);
    CHECK(Utilities::MPI::sum(problem.get_model().constrained.n_elements(),
                              MPI_COMM_WORLD) > 0);
    CHECK(ModelDirectSolver(problem.get_model()).factorizes_free_block());
    const double difference = difference_to_lu(problem.get_model());
    INFO("largest relative difference to the LU " << difference);
    CHECK(difference < 1e-11);
    solution = solve(problem);
    CHECK(relative_nodal_error(problem, solution, u) < 1e-10);
    const ErrorNorms errors =
      field_errors<dim>(problem.get_dof_handler(),
                        solution,
                        u,
                        [](const Point<dim> &) { return true; });
    CHECK(errors.linf < 1e-10);
  }



  template <int dim>
  void
  check_uniaxial_tension(const bool by_pressure)
  {
    const std::string boundaries = dim == 2 ? "x-, y-" : "x-, y-, z-";
    const std::string components =
      dim == 2 ? "x-: x, y-: y" : "x-: x, y-: y, z-: z";
    const LocalParameters<dim> parameters =
      parse_local_parameters<dim>(boundaries, components);
    const Geometry<dim>    geometry = box_geometry<dim>();
    ElasticityProblem<dim> problem(
      geometry, parameters, lambda, mu, 0.25, MPI_COMM_WORLD);

    // Zero boundary data: only the roller components may be held.
    const double                       sigma = 0.8, area = 1;
    const Functions::ZeroFunction<dim> zero(dim), no_pressure(1);
    const OnRightEnd<dim> pull(dim, 0, sigma), suction(1, 0, -sigma);
    using F                       = const Function<dim> &;
    const Function<dim> &traction = by_pressure ? F(zero) : F(pull);
    const Function<dim> &pressure = by_pressure ? F(suction) : F(no_pressure);
    problem.assemble(zero, zero, traction, pressure);
    const auto solution = solve(problem);

    // In 2D plane strain: E' = E / (1 - nu^2), nu' = nu / (1 - nu).
    const double E = dim == 2 ? 4 * mu * (lambda + mu) / (lambda + 2 * mu) :
                                mu * (3 * lambda + 2 * mu) / (lambda + mu);
    const double nu =
      dim == 2 ? lambda / (lambda + 2 * mu) : lambda / (2 * (lambda + mu));
    // u = (1, -nu, -nu) sigma / E * x componentwise.
    class Uniaxial : public Function<dim>
    {
    public:
      Uniaxial(const double strain, const double nu)
        : Function<dim>(dim)
        , strain(strain)
        , nu(nu)
      {}
      double
      value(const Point<dim> &p, const unsigned int c) const override
      {
        return (c == 0 ? 1 : -nu) * strain * p[c];
      }

    private:
      const double strain, nu;
    } exact(sigma / E, nu);
    CHECK(relative_nodal_error(problem, solution, exact) < 1e-10);

    // The load goes through every section, including the rollers' face.
    for (const double x : {0., 0.5, 1.5, 2.})
      {
        INFO("section x = " << x);
        const Tensor<1, dim> force = problem.section_force(solution, 0, x);
        CHECK(force[0] == Approx(sigma * area).epsilon(1e-10));
        for (unsigned int d = 1; d < dim; ++d)
          CHECK(std::abs(force[d]) < 1e-10 * sigma * area);
      }
    const Tensor<1, dim> across = problem.section_force(solution, 1, 0.5);
    CHECK(across.norm() < 1e-10 * sigma * area);
    CHECK_THROWS_AS(problem.section_force(solution, 0, 0.3), ExceptionBase);

    const Tensor<1, dim> applied = problem.applied_force(traction, pressure, 1);
    CHECK(applied[0] == Approx(sigma * area).epsilon(1e-12));
    for (unsigned int d = 1; d < dim; ++d)
      CHECK(std::abs(applied[d]) < 1e-14);
    CHECK(problem.applied_force(traction, pressure, 3).norm() < 1e-14);
  }


  /**
   * With the nonlocal region (0,1)^dim in the body, Gamma_c is x = 0.75:
   * every component of its nodes is a control, except where a Dirichlet
   * face fixes it; controls set to a linear field give that field.
   */
  template <int dim>
  void
  check_controls()
  {
    Geometry<dim> geometry = box_geometry<dim>();
    geometry.models        = Geometry<dim>::Models::coupled;
    geometry.overlap_width = 0.25;
    geometry.set_nonlocal_boxes({slab<dim>(0, 1, 0, 1)});
    // y- a roller: the traction acts on its other components.
    const LocalParameters<dim> parameters = parse_local_parameters<dim>(
      dim == 2 ? "x+, y-, y+" : "x+, y-, y+, z-, z+", "y-: y");
    ElasticityProblem<dim> problem(
      geometry, parameters, lambda, mu, 0.25, MPI_COMM_WORLD);

    const Polynomial<dim>              u(false);
    const Functions::ZeroFunction<dim> zero(dim), no_pressure(1);
    // sigma(u) n on y-, n = -e_y; sigma is constant.
    Vector<double> t(dim);
    for (unsigned int c = 0; c < dim; ++c)
      t[c] = -u.stress(Point<dim>())[c][1];
    const Functions::ConstantFunction<dim> traction(t);

    // 2D: 5 nodes on Gamma_c, (0.75, 1) fixed, (0.75, 0) only in y.
    // 3D: 3 x 3 inner nodes, and 3 on the edge y = 0 with x and z free.
    const types::global_dof_index expected =
      (dim == 2) ? 3 * 2 + 1 : 9 * 3 + 3 * 2;
    for (unsigned int cycle = 0; cycle < 2; ++cycle)
      {
        INFO("cycle " << cycle);
        problem.assemble(zero, u, traction, no_pressure);
        const DiscreteModel &model = problem.get_model();
        if (cycle == 0)
          CHECK(model.n_controls() == expected);
        else
          CHECK(model.n_controls() > expected);

        TrilinosWrappers::MPI::Vector interpolant = model.new_vector();
        VectorTools::interpolate(problem.get_dof_handler(), u, interpolant);
        const ModelSolver             solver(model, false);
        TrilinosWrappers::MPI::Vector theta   = solver.new_control_vector();
        types::global_dof_index       control = theta.local_range().first;
        for (const auto i : model.controls)
          theta(control++) = interpolant(i);
        theta.compress(VectorOperation::insert);
        const auto solution = model.ghosted(solver.forward(theta, true));
        CHECK(relative_nodal_error(problem, solution, u) < 1e-12);
        // The free block factorized alone solves M and M^T as the LU of
        // the whole matrix does, with controls, fixed data and (in 3D,
        // refined) hanging nodes.
        const double difference = difference_to_lu(model);
        INFO("largest relative difference to the LU " << difference);
        CHECK(difference < 1e-11);

        // Refine by the indicators of a bump (in u_x) on Gamma_c: more
        // nodes there, in 3D hanging ones too.
        Point<dim> bump_center;
        for (unsigned int d = 0; d < dim; ++d)
          bump_center[d] = (d == 0) ? 0.75 : 0.5;
        TrilinosWrappers::MPI::Vector bumps = model.new_vector();
        VectorTools::interpolate(problem.get_dof_handler(),
                                 VectorFunctionFromScalarFunctionObject<dim>(
                                   [&](const Point<dim> &p) {
                                     return std::exp(
                                       -20 * p.distance_square(bump_center));
                                   },
                                   0,
                                   dim),
                                 bumps);
        problem.refine(bumps, [](const Point<dim> &, double) { return true; });
      }
  }
} // namespace



TEST_CASE("elasticity reproduces linear displacements with FE_Q(1)",
          "[elasticity]")
{
  check_linear<2>();
  check_linear<3>();
}



TEST_CASE("elasticity reproduces quadratic displacements with FE_Q(2)",
          "[elasticity]")
{
  check_quadratic<2>();
  check_quadratic<3>();
}



TEST_CASE("elasticity: every component on Gamma_c is a control", "[elasticity]")
{
  check_controls<2>();
  check_controls<3>();
}



TEST_CASE("elasticity: uniaxial tension on rollers", "[elasticity]")
{
  for (const bool by_pressure : {false, true})
    {
      INFO((by_pressure ? "pressure" : "traction") << " on x+");
      check_uniaxial_tension<2>(by_pressure);
      check_uniaxial_tension<3>(by_pressure);
    }
}



TEST_CASE("Dirichlet components select the fixed components", "[elasticity]")
{
  const auto p2 = parse_local_parameters<2>("x-, x+, y-", " x-: x , y-: y|x");
  CHECK(p2.dirichlet_mask(0, 2) ==
        ComponentMask(std::vector<bool>{true, false}));
  CHECK(p2.dirichlet_mask(1, 2) == ComponentMask(2, true));
  CHECK(p2.dirichlet_mask(2, 2) == ComponentMask(2, true));
  CHECK(p2.dirichlet_mask(3, 2) == ComponentMask(2, false));
  CHECK(p2.dirichlet_mask(1, 1) == ComponentMask(1, true));

  const auto p3 = parse_local_parameters<3>("z-", "z-: z|y");
  CHECK(p3.dirichlet_mask(4, 3) ==
        ComponentMask(std::vector<bool>{false, true, true}));
  CHECK(parse_local_parameters<3>("z-", "").dirichlet_components.empty());
}



TEST_CASE("bad Dirichlet components are an InputError", "[elasticity]")
{
  for (const std::string text : {"x-",
                                 "x-: w",
                                 "x-: z",
                                 "x-: xy",
                                 "q-: x",
                                 "z-: z",
                                 "y+: x",
                                 "x-: x,",
                                 "x-: x|",
                                 ": x",
                                 "x-:",
                                 "x-: x, x-: y"})
    {
      INFO("Dirichlet components = '" << text << "'");
      try
        {
          parse_local_parameters<2>("x-, y-", text);
          FAIL("no InputError");
        }
      catch (const InputError &error)
        {
          CHECK(error.parameter == "Local model/Dirichlet components");
        }
    }

  // Poisson has no components.
  ParameterHandler prm;
  declare_all_parameters(prm);
  read_parameters(prm,
                  std::string(LTN_SOURCE_DIR) +
                    "/parameter_files/diffusion_2d_patch.prm",
                  {"Local model/Dirichlet components=x-: x"});
  try
    {
      DiffusionScene<2> scene(prm, "diffusion_2d_patch");
      FAIL("no InputError");
    }
  catch (const InputError &error)
    {
      CHECK(error.parameter == "Local model/Dirichlet components");
      CHECK(std::string(error.what()).find("only elasticity scenes") !=
            std::string::npos);
    }
}



TEST_CASE("elasticity output has displacement, strain, stress, von Mises",
          "[elasticity]")
{
  const Geometry<2>        geometry   = box_geometry<2>();
  const LocalParameters<2> parameters = dirichlet_box<2>(1);
  ElasticityProblem<2>     problem(
    geometry, parameters, lambda, mu, 0.5, MPI_COMM_WORLD);
  const Polynomial<2>              u(false);
  const Functions::ZeroFunction<2> zero(2), no_pressure(1);
  problem.assemble(zero, u, zero, no_pressure);
  const auto solution = solve(problem);

  const std::string directory =
    (std::filesystem::temp_directory_path() / "ltn_elasticity_output_test")
      .string();
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::filesystem::create_directories(directory);
  MPI_Barrier(MPI_COMM_WORLD);
  // The material with these Lamé constants, plane strain.
  Material material;
  material.poisson_ratio   = lambda / (2 * (lambda + mu));
  material.youngs_modulus  = 2 * mu * (1 + material.poisson_ratio);
  const std::string record = write_elasticity_vtu<2>(
    problem.get_dof_handler(),
    solution,
    material,
    &u,
    [](const Point<2> &) { return Region::local; },
    directory,
    "elasticity");
  CHECK(record == "elasticity.pvtu");
  MPI_Barrier(MPI_COMM_WORLD);

  std::ifstream     in(directory + "/" + record);
  std::stringstream text;
  text << in.rdbuf();
  for (const std::string name :
       {"\"displacement\" NumberOfComponents=\"3\"",
        "\"strain\" NumberOfComponents=\"9\"",
        "\"stress\" NumberOfComponents=\"9\"",
        "\"von_mises\"",
        "\"region\"",
        "\"displacement_exact\" NumberOfComponents=\"3\"",
        "\"error\" NumberOfComponents=\"3\""})
    {
      INFO(name);
      CHECK(text.str().find(name) != std::string::npos);
    }
}

#pragma once

#include <deal.II/base/function.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/tria.h>

#include <ltn/base/discrete_model.h>
#include <ltn/base/field_errors.h>
#include <ltn/nonlocal/kernel.h>
#include <ltn/problem/blending_function.h>
#include <ltn/problem/geometry.h>

#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * Nonlocal diffusion in 1D, discretized in weak form by continuous finite
   * elements `FE_Q(p)` on a uniform mesh of `Omega_n` and its collar:
   *
   *   a(u, v) = int int (u(x) - u(y)) (v(x) - v(y)) gamma(|x - y|) dy dx,
   *
   * over all pairs of points of `Omega_n ∪ collar`, tested with the basis
   * functions of the free nodes (those inside `Omega_n`). The double integral
   * is computed element pair by element pair in the variables
   * `(x, xi = y - x)`: for fixed `xi` the inner integral over `x` is of a
   * polynomial over an interval whose ends move linearly with `xi`, so it is
   * a polynomial in `xi` between the breakpoints `xi = a2 - b1, a2 - a1,
   * b2 - b1, b2 - a1, 0, ±eps`. Each piece is integrated against
   * `gamma(|xi|) = c |xi|^-beta`: by Gauss-Jacobi for the weight
   * `|xi|^(2-beta)` on pieces that touch `xi = 0` (where the integrand
   * vanishes like `xi^2`), exactly; by Gauss-Legendre elsewhere, exactly for
   * the constant kernel and to round-off for the others (there a piece
   * `[l, r]` has `r <= 2 l`). See doc/discretization.md.
   *
   * The model is serial (on MPI_COMM_SELF): under MPI every rank holds and
   * solves all of it.
   */
  class NonlocalWeakForm1D
  {
  public:
    /**
     * Build the mesh of `Omega_n` and its collar with mesh size @p h; the
     * collar is covered by `ceil(eps / h)` elements on each side.
     */
    NonlocalWeakForm1D(const Geometry<1> &geometry,
                       const Kernel      &kernel,
                       const unsigned int degree,
                       const double       h);

    /**
     * Assemble the matrix, the load vector of @p rhs over `Omega_n`, and the
     * volume constraint @p volume_data on the physical collar.
     */
    void
    assemble(const Function<1> &rhs, const Function<1> &volume_data);

    const DoFHandler<1> &
    get_dof_handler() const;

    const DiscreteModel &
    get_model() const;

    /** The region tag of a point of the mesh. */
    Region
    region_of(const Point<1> &p) const;

    /** The support point of each degree of freedom. */
    const std::vector<Point<1>> &
    get_support_points() const;

    /** The error of @p field against @p exact over `Omega_n`. */
    ErrorNorms
    errors(const TrilinosWrappers::MPI::Vector &field,
           const Function<1>                   &exact) const;

    /**
     * For energy-based blending (doc/baseline_couplings.md, 'Energy-based
     * blending'): the form with the bond weight `(beta(x) + beta(y)) / 2`
     * and the load of `beta rhs` over `Omega_n`, every row a test function
     * (the collar's too), exact on the pieces where @p beta is affine.
     */
    WeightedForm
    weighted_form(const Function<1>         &rhs,
                  const BlendingFunction<1> &beta) const;

  private:
    /**
     * The pair form into @p matrix, its pattern made anew; with @p beta,
     * weighted as weighted_form() says.
     */
    void
    assemble_pair_form(TrilinosWrappers::SparseMatrix &matrix,
                       const BlendingFunction<1>      *beta) const;

    void
    assemble_rhs(const Function<1> &rhs);

    const Geometry<1>    &geometry;
    const Kernel          kernel;
    Triangulation<1>      triangulation;
    FE_Q<1>               fe;
    DoFHandler<1>         dof_handler;
    std::vector<Point<1>> support_points;
    DiscreteModel         model;
  };
} // namespace ltn

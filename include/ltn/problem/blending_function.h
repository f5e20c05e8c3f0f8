#pragma once

#include <deal.II/base/function.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ltn/problem/geometry.h>

#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The weight of the blending couplings (doc/baseline_couplings.md, 'The
   * blending function and the shared unknowns'): `beta = min(1, s / delta)`,
   * `s` the depth in the nonlocal region and `delta` the overlap width: 1 on
   * the shrunk region, 0 off `Omega_n`, linear across the overlap band; beyond
   * the body (the collars of the volume constraint), the value at the
   * nearest point of the body.
   */
  template <int dim>
  class BlendingFunction : public Function<dim>
  {
  public:
    /** The weight of @p geometry (kept alive by the caller). */
    explicit BlendingFunction(const Geometry<dim> &geometry);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    /**
     * The coordinates along direction @p d where `beta` may bend: the faces
     * of the nonlocal region's boxes and those faces moved by `delta` into
     * them. Between two of them `beta` is affine along `d` (a superset:
     * faces on the body's boundary bend nothing).
     */
    std::vector<double>
    kinks(const unsigned int d) const;

  private:
    const Geometry<dim> &geometry;
  };

  /**
   * One model's part of a blended energy: the bilinear form weighted by a
   * blending weight, with no boundary condition or control applied (every
   * row a test function), and its weighted load, in the model's numbering.
   */
  struct WeightedForm
  {
    TrilinosWrappers::SparseMatrix matrix;
    TrilinosWrappers::MPI::Vector  load;
  };
} // namespace ltn

// The matrix-free particle operators (LatticeOperator) against the assembled
// matrices they replace: equal products M x and M^T x to round-off on random
// vectors, whole and at the rows of the kept or of the eliminated degrees of
// freedom only (the LPS dilatation), for nonlocal diffusion and LPS in 2D
// and 3D, with cracks (an inner one and one across the lattice) and a collar
// partly outside the body (volume constraint) and partly inside (controls);
// and the products of only the rows near the collar where they are exact;
// on any number of ranks.

#include <ltn/nonlocal/lattice_operator.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>

#include "particle_layout.h"

using namespace ltn;

namespace
{
  /**
   * max |M x - M_mf x| / max |M x| and the same for the transposes, over
   * random vectors, comparing the rows @p rows (of `DiscreteModel::eliminated`
   * or the others) of the matrix-free product that computes only them.
   */
  double
  product_difference(const DiscreteModel &assembled,
                     const DiscreteModel &matrix_free,
                     const RowSubset      rows = RowSubset::all)
  {
    REQUIRE(assembled.matrix_free == nullptr);
    REQUIRE(matrix_free.matrix_free != nullptr);
    std::mt19937 random(7);
    double       worst = 0;
    for (unsigned int trial = 0; trial < 3; ++trial)
      {
        const auto x = random_vector(assembled, random);
        auto       y = assembled.new_vector(), z = assembled.new_vector();
        for (const bool transpose : {false, true})
          {
            assembled.vmult_rows(y, x, transpose, RowSubset::all);
            if (rows == RowSubset::all)
              matrix_free.vmult_rows(z, x, transpose, rows);
            else
              {
                // A marker first: a row of the subset the product missed
                // would keep it. The other rows are not compared.
                z = 1e300;
                matrix_free.vmult_rows(z, x, transpose, rows);
                for (const auto i : matrix_free.owned)
                  if (matrix_free.eliminated.is_element(i) !=
                      (rows == RowSubset::eliminated))
                    z(i) = y(i);
                z.compress(VectorOperation::insert);
              }
            const double scale = y.linfty_norm();
            z -= y;
            worst = std::max(worst, z.linfty_norm() / scale);
          }
      }
    return worst;
  }

  /**
   * Products restricted to the rows near some degrees of freedom
   * (MatrixFreeOperator::rows_near(), of those that are not free: the
   * collar): for a random vector zero outside layer `l`, the rows within
   * layer `l + 1` give the whole product (`l` = 0, 1); for any random
   * vector, the rows within layer 0 give its rows there. The largest
   * difference to the whole product, relative, over both transposes and
   * all row subsets; CHECKs that each layer is larger than the one before.
   */
  double
  near_rows_difference(const DiscreteModel &model)
  {
    REQUIRE(model.matrix_free != nullptr);
    auto marked = model.new_vector();
    for (const auto i : model.owned)
      if (model.role(i) != DofRole::free)
        marked(i) = 1.;
    marked.compress(VectorOperation::insert);
    const std::vector<RowRanges> layers = model.rows_near(marked, 2);
    REQUIRE(layers.size() == 3);
    const auto inside = [&](const unsigned int layer) {
      std::vector<bool> is_inside(model.owned.n_elements());
      for (const auto &[from, past] : layers[layer])
        std::fill(is_inside.begin() + from, is_inside.begin() + past, true);
      return is_inside;
    };
    std::vector<unsigned int> sizes;
    for (unsigned int layer = 0; layer < 3; ++layer)
      {
        const auto is_inside = inside(layer);
        sizes.push_back(Utilities::MPI::sum<unsigned int>(
          std::count(is_inside.begin(), is_inside.end(), true),
          model.communicator));
      }
    INFO("rows within 0, 1, 2 bonds of the collar: "
         << sizes[0] << ", " << sizes[1] << ", " << sizes[2] << " of "
         << model.owned.size());
    CHECK(sizes[0] > 0);
    CHECK(sizes[0] < sizes[1]);
    CHECK(sizes[1] < sizes[2]);

    std::mt19937 random(9);
    double       worst = 0;
    // (layer of x's support, or 3 for all; layer of the rows computed and
    // compared, or 3 for all rows compared).
    for (const auto &[support, within, compared] :
         std::vector<std::array<unsigned int, 3>>{{{0, 1, 3}},
                                                  {{1, 2, 3}},
                                                  {{3, 0, 0}}})
      for (const bool transpose : {false, true})
        for (const RowSubset rows :
             {RowSubset::all, RowSubset::kept, RowSubset::eliminated})
          {
            auto x = random_vector(model, random);
            if (support < 3)
              {
                const auto is_inside = inside(support);
                for (std::size_t p = 0; p < is_inside.size(); ++p)
                  if (!is_inside[p])
                    x.begin()[p] = 0.;
              }
            auto y = model.new_vector(), z = model.new_vector();
            model.vmult_rows(y, x, transpose, RowSubset::all);
            // A marker first: a row the product missed would keep it.
            z = 1e300;
            model.vmult_rows(z, x, transpose, rows, &layers[within]);
            const auto is_compared =
              compared < 3 ? inside(compared) :
                             std::vector<bool>(model.owned.n_elements(), true);
            for (std::size_t p = 0; p < is_compared.size(); ++p)
              {
                const bool in_subset = rows == RowSubset::all ||
                                       model.eliminated.is_element(
                                         model.owned.nth_index_in_set(p)) ==
                                         (rows == RowSubset::eliminated);
                if (!is_compared[p] || !in_subset)
                  z.begin()[p] = y.begin()[p];
              }
            const double scale = y.linfty_norm();
            z -= y;
            worst = std::max(worst, z.linfty_norm() / scale);
          }
    return worst;
  }

  template <int dim>
  void
  check_elasticity(
    const double         h,
    const double         m,
    const Geometry<dim> &geometry = lasting_particle_layout<dim>())
  {
    const auto   assembled   = cracked_lps<dim>(h, m, false, geometry);
    const auto   matrix_free = cracked_lps<dim>(h, m, true, geometry);
    const double difference =
      product_difference(assembled->get_model(), matrix_free->get_model());
    const auto &op = dynamic_cast<const LatticeOperator<dim> &>(
      *matrix_free->get_model().matrix_free);
    const auto n = matrix_free->get_lattice().n_particles();
    INFO(dim << "D LPS, m = " << m << ": " << op.n_stored_rows() << " of "
             << (dim + 1) * n << " rows not shared, " << op.n_scaled_rows()
             << " scaled, " << op.n_compressed_rows()
             << " compressed, difference " << difference);
    CHECK(difference < 1e-13);
    CHECK(near_rows_difference(matrix_free->get_model()) < 1e-13);
    for (const RowSubset rows : {RowSubset::kept, RowSubset::eliminated})
      CHECK(product_difference(assembled->get_model(),
                               matrix_free->get_model(),
                               rows) < 1e-13);
    // The shared stencil serves most particles, not all; the rows next to
    // cracks are the shared ones scaled, and no row is left to a sparse
    // matrix.
    CHECK(op.n_stored_rows() > 0);
    CHECK(op.n_stored_rows() < (dim + 1) * n);
    CHECK(op.n_scaled_rows() > 0);
    CHECK(op.n_compressed_rows() == 0);
    auto rhs_difference = assembled->get_model().rhs;
    rhs_difference -= matrix_free->get_model().rhs;
    CHECK(rhs_difference.linfty_norm() == 0);
  }

  template <int dim>
  void
  check_diffusion(
    const double         h,
    const double         m,
    const Geometry<dim> &geometry = lasting_particle_layout<dim>())
  {
    const auto   assembled   = layout_diffusion<dim>(h, m, false, geometry);
    const auto   matrix_free = layout_diffusion<dim>(h, m, true, geometry);
    const double difference =
      product_difference(assembled->get_model(), matrix_free->get_model());
    INFO(dim << "D diffusion, m = " << m << ": difference " << difference);
    CHECK(difference < 1e-13);
    CHECK(near_rows_difference(matrix_free->get_model()) < 1e-13);
  }
} // namespace



TEST_CASE("matrix-free particle operators equal the assembled ones",
          "[matrix-free][unit]")
{
  check_diffusion<2>(1. / 32, 3);
  check_diffusion<3>(1. / 16, 2);
  check_elasticity<2>(1. / 32, 2);
  check_elasticity<2>(1. / 32, 3.5);
  check_elasticity<3>(1. / 16, 2);
}



// Lines through boxes apart have runs with gaps: a segment of the products
// ends where a neighbour's line enters its next run (without that end, the
// 2D diffusion products differ by 12 %).
TEST_CASE("matrix-free particle operators on a region of four boxes",
          "[matrix-free][unit]")
{
  check_diffusion<2>(1. / 32, 3, lasting_union_layout<2>());
  check_diffusion<3>(1. / 16, 2, lasting_union_layout<3>());
  check_elasticity<2>(1. / 32, 2, lasting_union_layout<2>());
  check_elasticity<3>(1. / 16, 2, lasting_union_layout<3>());
}

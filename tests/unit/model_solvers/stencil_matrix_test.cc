// StencilMatrix, the lattice surrogate's product without its compressed rows:
// it equals the compressed rows' product to round-off on random vectors (2D
// and 3D, with cracks, on any number of ranks); a matrix not of the form is
// told apart; and ML's V-cycle with the stencil's product at its finest level
// equals the one with the compressed rows'.

#include <deal.II/lac/trilinos_precondition.h>

#include <ltn/model_solvers/stencil_matrix.h>

#include <Teuchos_ParameterList.hpp>
#include <catch2/catch.hpp>

#include "particle_layout.h"

using namespace ltn;

namespace
{
  using VectorType = TrilinosWrappers::MPI::Vector;

  VectorType
  random_surrogate_vector(const DiscreteModel &model, std::mt19937 &random)
  {
    std::uniform_real_distribution<double> value(-1, 1);
    VectorType                             x(
      model.lattice->surrogate().matrix.locally_owned_domain_indices(),
      model.communicator);
    for (auto &x_i : x)
      x_i = value(random);
    return x;
  }

  /** max |A x - S x| / max |A x| over random x, S the stencil's product. */
  double
  product_difference(const DiscreteModel &model, const StencilMatrix &stencil)
  {
    std::mt19937 random(11);
    double       worst = 0;
    for (unsigned int trial = 0; trial < 3; ++trial)
      {
        const VectorType x = random_surrogate_vector(model, random);
        VectorType       y(x), z(x);
        model.lattice->surrogate().matrix.vmult(y, x);
        stencil.apply(x.begin(), z.begin());
        const double scale = y.linfty_norm();
        z -= y;
        worst = std::max(worst, z.linfty_norm() / scale);
      }
    return worst;
  }

  /** ML's V-cycle on @p matrix, with its stencil's product or its rows'. */
  VectorType
  v_cycle(const Epetra_CrsMatrix &matrix,
          const VectorType       &x,
          const bool              stencil_product)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic        = true;
    data.smoother_sweeps = 3;
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> no_modes;
    data.set_parameters(parameters, no_modes, matrix);
    parameters.set("coarse: max size", 200);
    TrilinosWrappers::PreconditionAMG amg;
    amg.initialize(matrix, parameters);
    const StencilMatrix stencil(matrix);
    if (stencil_product)
      REQUIRE(stencil.serve_finest_level(amg));
    VectorType y(x);
    amg.vmult(y, x);
    return y;
  }

  template <int dim>
  void
  check(const DiscreteModel &model)
  {
    const StencilMatrix stencil(
      model.lattice->surrogate().matrix.trilinos_matrix());
    REQUIRE(stencil.is_stencil());
    const double difference = product_difference(model, stencil);
    INFO(dim << "D: product difference " << difference);
    CHECK(difference < 1e-14);
    CHECK(stencil.memory_consumption() > 0);

    std::mt19937     random(3);
    const VectorType x    = random_surrogate_vector(model, random);
    const auto &matrix    = model.lattice->surrogate().matrix.trilinos_matrix();
    const VectorType rows = v_cycle(matrix, x, false);
    VectorType       cycle = v_cycle(matrix, x, true);
    const double     scale = rows.linfty_norm();
    cycle -= rows;
    INFO(dim << "D: V-cycle difference " << cycle.linfty_norm() / scale);
    CHECK(cycle.linfty_norm() < 1e-12 * scale);
  }
} // namespace



TEST_CASE("the stencil matrix's product equals the compressed rows'",
          "[matrix-free][unit]")
{
  check<2>(cracked_lps<2>(1. / 32, 2, true)->get_model());
  check<3>(cracked_lps<3>(1. / 16, 2, true)->get_model());
  check<2>(layout_diffusion<2>(1. / 32, 3, true)->get_model());
}



TEST_CASE("a matrix whose off-diagonal entries differ is no stencil",
          "[matrix-free][unit]")
{
  const auto           particles = cracked_lps<2>(1. / 32, 2, true);
  const DiscreteModel &model     = particles->get_model();
  Epetra_CrsMatrix changed(model.lattice->surrogate().matrix.trilinos_matrix());
  // One off-diagonal entry of rank 0's first row halved.
  if (Utilities::MPI::this_mpi_process(model.communicator) == 0)
    {
      int     count;
      double *values;
      int    *columns;
      changed.ExtractMyRowView(0, count, values, columns);
      for (int j = 0; j < count; ++j)
        if (changed.GCID64(columns[j]) != changed.GRID64(0))
          {
            values[j] *= 0.5;
            break;
          }
    }
  CHECK_FALSE(StencilMatrix(changed).is_stencil());
  CHECK(StencilMatrix(model.lattice->surrogate().matrix.trilinos_matrix())
          .is_stencil());
}

// The full-space optimality system without a matrix (KktOperator,
// doc/discretization.md, 'The full-space system without a matrix') is the
// assembled system of 'The full-space KKT system'
// with the multipliers scaled: K_s = diag(I, sI) K diag(I, sI), and its
// right-hand side diag(I, sI) b. Checked on random vectors for 2D nonlocal
// diffusion on the shared particle layout coupled to Poisson, with the
// particle operator assembled and matrix-free, Tikhonov term on.

#include <ltn/coupling/solvers/full_space_direct_solver.h>
#include <ltn/coupling/system/kkt_operator.h>

#include <catch2/catch.hpp>

#include "coupled_layout.h"

using namespace ltn;

namespace
{
  /** The entries of the blocks of @p v at their offsets in one vector. */
  TrilinosWrappers::MPI::Vector
  flatten(const TrilinosWrappers::MPI::BlockVector &v, const IndexSet &owned)
  {
    TrilinosWrappers::MPI::Vector flat(owned, MPI_COMM_WORLD);
    types::global_dof_index       offset = 0;
    for (unsigned int b = 0; b < v.n_blocks(); ++b)
      {
        for (const auto i : v.block(b).locally_owned_elements())
          flat(offset + i) = v.block(b)(i);
        offset += v.block(b).size();
      }
    flat.compress(VectorOperation::insert);
    return flat;
  }

  /** The inverse of flatten(): the entries of @p flat into @p v's blocks. */
  void
  unflatten(const TrilinosWrappers::MPI::Vector &flat,
            TrilinosWrappers::MPI::BlockVector  &v)
  {
    types::global_dof_index offset = 0;
    for (unsigned int b = 0; b < v.n_blocks(); ++b)
      {
        for (const auto i : v.block(b).locally_owned_elements())
          v.block(b)(i) = flat(offset + i);
        v.block(b).compress(VectorOperation::insert);
        offset += v.block(b).size();
      }
  }
} // namespace



TEST_CASE("the KKT operator is the assembled optimality system with scaled "
          "multipliers",
          "[coupling]")
{
  constexpr int dim = 2;
  const double  h = 0.125, spacing = h / 4, m = 2, alpha = 0.3;
  // The assembled model gives K (and the overlap: the lattice is the same);
  // the operator works on the model as the solvers see it.
  const DiffusionPoissonLayout<dim> layout(h, spacing, m);
  const auto                       &assembled = layout.particles;
  const auto                       &local     = layout.local;
  const auto                       &overlap   = layout.overlap;
  const CouplingSystem<dim>         reference(assembled->get_model(),
                                      local.get_model(),
                                      overlap,
                                      alpha);
  TrilinosWrappers::SparseMatrix    K;
  TrilinosWrappers::MPI::Vector     b;
  assemble_full_space_system(reference, K, b);
  const IndexSet owned = b.locally_owned_elements();

  std::mt19937 random(7);
  for (const bool matrix_free : {false, true})
    {
      const auto matrix_free_model =
        matrix_free ? layout_diffusion<dim>(spacing, m, true) : nullptr;
      const CouplingSystem<dim> system(matrix_free ?
                                         matrix_free_model->get_model() :
                                         assembled->get_model(),
                                       local.get_model(),
                                       overlap,
                                       alpha);
      const KktOperator<dim> kkt(system);
      const double           s = kkt.scale;
      INFO((matrix_free ? "matrix-free" : "assembled") << ", scale " << s);
      REQUIRE(s > 0);

      // z = [x | mu'], K_s z against diag(I, sI) K [x | s mu'].
      auto z = kkt.new_vector();
      for (const unsigned int k : {0u, 1u})
        {
          const DiscreteModel &model = *system.models[k];
          z.block(k)                 = random_vector(model, random);
          z.block(2 + k)             = random_vector(model, random);
        }
      auto y = kkt.new_vector();
      kkt.vmult(y, z);

      auto z_scaled = z;
      auto y_scaled = y;
      for (const unsigned int k : {0u, 1u})
        {
          z_scaled.block(2 + k) *= s;
          y_scaled.block(2 + k) /= s;
        }
      TrilinosWrappers::MPI::Vector Kz(owned, MPI_COMM_WORLD);
      K.vmult(Kz, flatten(z_scaled, owned));
      // Block by block: the optimality rows are of the size of the overlap
      // weights, the constraint rows of the models' matrices.
      auto expected = kkt.new_vector();
      unflatten(Kz, expected);
      for (unsigned int block = 0; block < 4; ++block)
        {
          INFO("block " << block);
          auto difference = y_scaled.block(block);
          difference -= expected.block(block);
          CHECK(expected.block(block).l2_norm() > 0);
          CHECK(difference.l2_norm() <=
                1e-12 * expected.block(block).l2_norm());
        }

      // The right-hand side: [0 | s r].
      auto rhs = kkt.rhs();
      for (const unsigned int k : {0u, 1u})
        rhs.block(2 + k) /= s;
      TrilinosWrappers::MPI::Vector rhs_difference = flatten(rhs, owned);
      rhs_difference -= b;
      CHECK(rhs_difference.l2_norm() <= 1e-14 * b.l2_norm());
      CHECK(b.l2_norm() > 0);
    }
}

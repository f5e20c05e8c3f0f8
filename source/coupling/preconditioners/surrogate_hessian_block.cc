#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ltn/base/matrix_rows.h>
#include <ltn/coupling/preconditioners/surrogate_hessian_block.h>

#include <algorithm>

namespace ltn
{
  namespace
  {
    /**
     * One rank's part of the saddle-point system: its surrogate rows
     * (`first_row` on, `n_rows` of them) and controls, and where its
     * unknowns begin: `n_controls` of `y`, then per component `n_rows` of
     * `v`, then as many of `l`.
     */
    struct RankLayout
    {
      types::global_dof_index first_row  = 0;
      types::global_dof_index n_rows     = 0;
      types::global_dof_index n_controls = 0;
      types::global_dof_index begin      = 0;
    };

    /** The lattice of a particle model. */
    const ModelLattice &
    lattice_of(const DiscreteModel &model)
    {
      AssertThrow(model.lattice,
                  ExcMessage("the surrogate model of the nonlocal controls' "
                             "Hessian block needs a particle model's lattice "
                             "surrogate (2D or 3D)"));
      return *model.lattice;
    }
  } // namespace



  SurrogateHessianBlock::SurrogateHessianBlock(
    const DiscreteModel                 &model,
    const ModelSolver                   &solver,
    const TrilinosWrappers::MPI::Vector &diagonal,
    const TrilinosWrappers::MPI::Vector &observation)
    : model(model)
    , lattice(lattice_of(model))
    , surrogate(lattice.surrogate())
    , solver(solver)
    , diagonal(diagonal)
  {
    const IndexSet &rows = surrogate.matrix.locally_owned_range_indices();
    for (unsigned int c = 0; c < surrogate.components; ++c)
      {
        weights.emplace_back(rows, model.communicator);
        for (std::size_t i = 0; i < surrogate.nodes.size(); ++i)
          weights[c].begin()[i] =
            observation.begin()[lattice.node_dofs * surrogate.nodes[i] + c];
      }
    assemble_saddle_point();
    // Symmetric indefinite, LDL^T with 2x2 pivots: on the 3D diffusion
    // scene's 67,584 unknowns 10 s and 44 million factor entries, where the
    // general LU took 45-57 s (pivots on the zero diagonal blocks delayed)
    // or, with the rows permuted to put L on the diagonal, 10 s and 100
    // million entries; in 2D at h = 1/256 0.44 s against 0.9 s. Nested
    // dissection, the FEM models' order, helped in 3D and not in 2D (doc
    // 'A surrogate model of the nonlocal control block'):
    // it keeps minimum degree.
    saddle_point_solver =
      std::make_unique<DirectSolver>(saddle_point,
                                     0.5,
                                     DirectSolver::Symmetry::symmetric);
    saddle_point_rhs.reinit(saddle_point_owned, model.communicator);
    saddle_point_solution.reinit(saddle_point_rhs);
  }



  SurrogateHessianBlock::~SurrogateHessianBlock() = default;



  void
  SurrogateHessianBlock::assemble_saddle_point()
  {
    const MPI_Comm     communicator = model.communicator;
    const unsigned int n_components = surrogate.components;
    const IndexSet    &rows = surrogate.matrix.locally_owned_range_indices();
    RankLayout         mine;
    mine.first_row     = rows.n_elements() > 0 ? *rows.begin() : 0;
    mine.n_rows        = rows.n_elements();
    mine.n_controls    = diagonal.locally_owned_size();
    saddle_point_owned = Utilities::MPI::create_ascending_partitioning(
      communicator,
      mine.n_controls +
        2 * n_components *
          mine.n_rows)[Utilities::MPI::this_mpi_process(communicator)];
    mine.begin =
      saddle_point_owned.n_elements() > 0 ? *saddle_point_owned.begin() : 0;
    const std::vector<RankLayout> layouts =
      Utilities::MPI::all_gather(communicator, mine);

    // The unknowns v (second = false) or l (true) of surrogate row g.
    const auto field_unknown = [&](const types::global_dof_index g,
                                   const unsigned int            c,
                                   const bool                    multiplier) {
      const auto rank = std::find_if(
        layouts.begin(), layouts.end(), [g](const RankLayout &layout) {
          return g >= layout.first_row && g < layout.first_row + layout.n_rows;
        });
      Assert(rank != layouts.end(), ExcInternalError());
      return rank->begin + rank->n_controls +
             (multiplier ? n_components + c : c) * rank->n_rows +
             (g - rank->first_row);
    };
    // The unknown y of each control, at its degree of freedom (1 + its
    // number; 0: not a control), read at the collar's particles.
    TrilinosWrappers::MPI::Vector numbers = solver.new_control_vector();
    for (std::size_t i = 0; i < numbers.locally_owned_size(); ++i)
      numbers.begin()[i] = mine.begin + i + 1;
    const TrilinosWrappers::MPI::Vector control_unknown =
      model.ghosted(solver.extend_controls(numbers));
    const auto control_of = [&](const types::global_dof_index particle,
                                const unsigned int            c) {
      return static_cast<types::global_dof_index>(
        control_unknown(lattice.node_dofs * particle + c));
    };

    // Rows: this rank's, and those of the controls its rows of C reach.
    IndexSet touched = saddle_point_owned;
    for (const auto g : rows)
      for_each_in_row(surrogate.collar,
                      g,
                      [&](const auto particle, const double) {
                        for (unsigned int c = 0; c < n_components; ++c)
                          if (const auto y = control_of(particle, c); y > 0)
                            touched.add_index(y - 1);
                      });
    touched.compress();
    DynamicSparsityPattern pattern(saddle_point_owned.size(),
                                   saddle_point_owned.size(),
                                   touched);
    const auto             for_each_entry = [&](const auto &enter) {
      for (std::size_t i = 0; i < mine.n_controls; ++i)
        enter(mine.begin + i, mine.begin + i, diagonal.begin()[i]);
      for (unsigned int c = 0; c < n_components; ++c)
        for (std::size_t r = 0; r < mine.n_rows; ++r)
          {
            const auto g = rows.nth_index_in_set(r);
            const auto v = field_unknown(g, c, false);
            const auto l = field_unknown(g, c, true);
            enter(v, v, weights[c].begin()[r]);
            // L is symmetric.
            for_each_in_row(surrogate.matrix,
                            g,
                            [&](const auto column, const double value) {
                              enter(v, field_unknown(column, c, true), value);
                              enter(l, field_unknown(column, c, false), value);
                            });
            for_each_in_row(surrogate.collar,
                            g,
                            [&](const auto particle, const double value) {
                              if (const auto y = control_of(particle, c); y > 0)
                                {
                                  enter(l, y - 1, -value);
                                  enter(y - 1, l, -value);
                                }
                            });
          }
    };
    for_each_entry([&](const auto row, const auto column, const double) {
      pattern.add(row, column);
    });
    saddle_point.reinit(
      saddle_point_owned, saddle_point_owned, pattern, communicator, true);
    for_each_entry([&](const auto row, const auto column, const double value) {
      saddle_point.add(row, column, value);
    });
    saddle_point.compress(VectorOperation::add);
  }



  void
  SurrogateHessianBlock::vmult(TrilinosWrappers::MPI::Vector       &dst,
                               const TrilinosWrappers::MPI::Vector &src) const
  {
    if (!surrogate_solver)
      surrogate_solver = std::make_unique<DirectSolver>(surrogate.matrix);
    TrilinosWrappers::MPI::Vector node_values(
      surrogate.collar.locally_owned_domain_indices(), model.communicator);
    TrilinosWrappers::MPI::Vector row_values(
      surrogate.matrix.locally_owned_range_indices(), model.communicator);
    TrilinosWrappers::MPI::Vector row_solution(row_values);
    // Over the model's degrees of freedom, numbered node_dofs * node + c.
    const TrilinosWrappers::MPI::Vector values   = solver.extend_controls(src);
    TrilinosWrappers::MPI::Vector       gradient = model.new_vector();
    const std::size_t n_nodes = node_values.locally_owned_size();
    for (unsigned int c = 0; c < surrogate.components; ++c)
      {
        for (std::size_t n = 0; n < n_nodes; ++n)
          node_values.begin()[n] = values.begin()[lattice.node_dofs * n + c];
        surrogate.collar.vmult(row_values, node_values);
        surrogate_solver->solve(row_solution, row_values);
        row_solution.scale(weights[c]);
        surrogate_solver->solve(row_values, row_solution);
        surrogate.collar.Tvmult(node_values, row_values);
        for (std::size_t n = 0; n < n_nodes; ++n)
          gradient.begin()[lattice.node_dofs * n + c] = node_values.begin()[n];
      }
    dst = solver.restrict_to_controls(gradient);
    for (std::size_t i = 0; i < dst.locally_owned_size(); ++i)
      dst.begin()[i] += diagonal.begin()[i] * src.begin()[i];
  }



  void
  SurrogateHessianBlock::solve(TrilinosWrappers::MPI::Vector       &dst,
                               const TrilinosWrappers::MPI::Vector &src) const
  {
    saddle_point_rhs = 0;
    std::copy(src.begin(), src.end(), saddle_point_rhs.begin());
    saddle_point_solver->solve(saddle_point_solution, saddle_point_rhs);
    std::copy(saddle_point_solution.begin(),
              saddle_point_solution.begin() + dst.locally_owned_size(),
              dst.begin());
  }



  types::global_dof_index
  SurrogateHessianBlock::n_saddle_point_unknowns() const
  {
    return saddle_point_owned.size();
  }
} // namespace ltn

#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/types.h>

#include <ltn/base/discrete_model.h>

#include <functional>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** Per component, the entries `(column, value)` of a particle's row. */
  using ParticleRows =
    std::vector<std::vector<std::pair<types::global_dof_index, double>>>;

  /**
   * Assemble @p model's matrix from the rows of its particles: this rank's
   * @p owned_particles, @p n_components degrees of freedom each (numbered
   * `n_components p + c`), each row given by @p rows_of. Sets
   * `model.relevant` to the owned degrees of freedom and those the rows
   * read.
   */
  void
  assemble_rows(
    const IndexSet    &owned_particles,
    const unsigned int n_components,
    const std::function<void(types::global_dof_index, ParticleRows &)> &rows_of,
    DiscreteModel                                                      &model);
} // namespace ltn

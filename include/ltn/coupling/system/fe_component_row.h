#pragma once

#include <deal.II/base/point.h>

#include <deal.II/fe/fe.h>

#include <ltn/coupling/system/overlap_quadrature.h>

#include <vector>

namespace ltn
{
  /**
   * The row that evaluates component @p c of the finite element field of
   * @p fe at @p unit, the unit coordinates of a point in a cell whose
   * degrees of freedom are @p dofs: an overlap point's `P_q`, a control
   * particle's trace.
   */
  template <int dim>
  SparseRow
  fe_component_row(const FiniteElement<dim>                   &fe,
                   const std::vector<types::global_dof_index> &dofs,
                   const Point<dim>                           &unit,
                   const unsigned int                          c)
  {
    SparseRow row;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (fe.system_to_component_index(i).first == c)
        row.emplace_back(dofs[i], fe.shape_value_component(i, unit, c));
    return row;
  }
} // namespace ltn

#include <ltn/base/discrete_model.h>

#include <algorithm>

namespace ltn
{
  types::global_dof_index
  DiscreteModel::count(const DofRole role) const
  {
    return std::count(roles.begin(), roles.end(), role);
  }
} // namespace ltn

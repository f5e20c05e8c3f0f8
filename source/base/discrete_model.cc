#include <ltn/base/discrete_model.h>

namespace ltn
{
  DofRole
  DiscreteModel::role(const types::global_dof_index i) const
  {
    return controls.is_element(i) ? DofRole::control :
           fixed.is_element(i)    ? DofRole::fixed :
                                    DofRole::free;
  }



  TrilinosWrappers::MPI::Vector
  DiscreteModel::new_vector() const
  {
    return TrilinosWrappers::MPI::Vector(owned, communicator);
  }



  TrilinosWrappers::MPI::Vector
  DiscreteModel::ghosted(const TrilinosWrappers::MPI::Vector &field) const
  {
    TrilinosWrappers::MPI::Vector result(owned, relevant, communicator);
    result = field;
    return result;
  }



  types::global_dof_index
  DiscreteModel::n_controls() const
  {
    return Utilities::MPI::sum<types::global_dof_index>(controls.n_elements(),
                                                        communicator);
  }
} // namespace ltn

#include <ltn/base/partition.h>
#include <ltn/coupling/model_solver.h>

namespace ltn
{
  ModelSolver::ModelSolver(const DiscreteModel &model, const bool with_adjoint)
    : model(model)
    , control_dofs(model.controls.begin(), model.controls.end())
    , direct(model.matrix, with_adjoint)
  {
    control_partition =
      contiguous_partition(control_dofs.size(), model.communicator);
    first_control =
      control_partition.is_empty() ? 0 : control_partition.nth_index_in_set(0);
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::new_control_vector() const
  {
    return TrilinosWrappers::MPI::Vector(control_partition, model.communicator);
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::forward(const TrilinosWrappers::MPI::Vector &theta,
                       const bool                           with_data) const
  {
    TrilinosWrappers::MPI::Vector rhs = model.new_vector();
    if (with_data)
      rhs = model.rhs;
    for (std::size_t c = 0; c < control_dofs.size(); ++c)
      rhs(control_dofs[c]) = theta(first_control + c);
    rhs.compress(VectorOperation::insert);

    TrilinosWrappers::MPI::Vector field = model.new_vector();
    direct.solve(field, rhs);
    return field;
  }



  TrilinosWrappers::MPI::Vector
  ModelSolver::adjoint(const TrilinosWrappers::MPI::Vector &z) const
  {
    TrilinosWrappers::MPI::Vector multiplier = model.new_vector();
    direct.solve_transposed(multiplier, z);

    TrilinosWrappers::MPI::Vector gradient = new_control_vector();
    for (std::size_t c = 0; c < control_dofs.size(); ++c)
      gradient(first_control + c) = multiplier(control_dofs[c]);
    gradient.compress(VectorOperation::insert);
    return gradient;
  }
} // namespace ltn

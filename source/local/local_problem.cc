#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/numerics/vector_tools.h>

#include <ltn/local/local_problem.h>

#include <map>

namespace ltn
{
  template <int dim, typename FE>
  void
  LocalProblem<dim, FE>::refine(
    const TrilinosWrappers::MPI::Vector                   &solution,
    const std::function<bool(const Point<dim> &, double)> &may_refine)
  {
    mesh.refine(dof_handler,
                model.ghosted(solution),
                parameters.refinement_fraction,
                may_refine);
    setup_local_dofs(dof_handler, fe, communicator, hanging_nodes, model);
  }



  template <int dim, typename FE>
  const DoFHandler<dim> &
  LocalProblem<dim, FE>::get_dof_handler() const
  {
    return dof_handler;
  }



  template <int dim, typename FE>
  const DiscreteModel &
  LocalProblem<dim, FE>::get_model() const
  {
    return model;
  }



  template <int dim, typename FE>
  void
  LocalProblem<dim, FE>::close_model(const Function<dim> &boundary_data)
  {
    model.matrix.compress(VectorOperation::add);
    model.rhs.compress(VectorOperation::add);
    std::map<types::global_dof_index, double> dirichlet_values;
    for (const unsigned int face : parameters.dirichlet_faces)
      VectorTools::interpolate_boundary_values(
        dof_handler,
        face,
        boundary_data,
        dirichlet_values,
        parameters.dirichlet_mask(face, fe.n_components()));
    close_local_model(
      dof_handler, hanging_nodes, dirichlet_values, control_boundary_id, model);
  }



  template class LocalProblem<1, FE_Q<1>>;
  template class LocalProblem<2, FE_Q<2>>;
  template class LocalProblem<3, FE_Q<3>>;
  template class LocalProblem<2, FESystem<2>>;
  template class LocalProblem<3, FESystem<3>>;
} // namespace ltn

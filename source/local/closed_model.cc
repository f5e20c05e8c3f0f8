#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/mapping_q1.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <ltn/local/closed_model.h>

#include <vector>

namespace ltn
{
  template <int dim>
  void
  setup_local_dofs(DoFHandler<dim>           &dof_handler,
                   const FiniteElement<dim>  &fe,
                   const MPI_Comm             communicator,
                   AffineConstraints<double> &hanging_nodes,
                   DiscreteModel             &model)
  {
    dof_handler.distribute_dofs(fe);
    model.communicator = communicator;
    model.owned        = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, model.relevant);
    hanging_nodes.clear();
    hanging_nodes.reinit(model.relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_nodes);
    hanging_nodes.close();
    // One translation per component: the near null space AMG needs.
    DoFTools::extract_constant_modes(dof_handler,
                                     ComponentMask(fe.n_components(), true),
                                     model.constant_modes);
  }



  template <int dim>
  void
  reinit_local_model(const DoFHandler<dim>           &dof_handler,
                     const AffineConstraints<double> &hanging_nodes,
                     DiscreteModel                   &model)
  {
    const types::global_dof_index n_dofs = dof_handler.n_dofs();
    DynamicSparsityPattern        dsp(n_dofs, n_dofs, model.relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, hanging_nodes, true);
    for (const auto &line : hanging_nodes.get_lines())
      for (const auto &entry : line.entries)
        dsp.add(line.index, entry.first);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               model.owned,
                                               model.communicator,
                                               model.relevant);
    model.matrix.reinit(model.owned, model.owned, dsp, model.communicator);
    model.mesh_couplings = true;
    model.rhs            = model.new_vector();
  }



  template <int dim>
  void
  close_local_model(
    const DoFHandler<dim>                           &dof_handler,
    const AffineConstraints<double>                 &hanging_nodes,
    const std::map<types::global_dof_index, double> &dirichlet_values,
    const types::boundary_id                         control_boundary_id,
    DiscreteModel                                   &model)
  {
    const types::global_dof_index n_dofs = dof_handler.n_dofs();

    // A hanging node on Gamma_c follows its masters: not a control of its
    // own. Dirichlet data wins over the control where Gamma_c meets a
    // Dirichlet face.
    model.controls = DoFTools::extract_boundary_dofs(dof_handler,
                                                     ComponentMask(),
                                                     {control_boundary_id});
    model.controls = model.controls & model.owned;
    model.fixed    = IndexSet(n_dofs);
    for (const auto &entry : dirichlet_values)
      if (model.owned.is_element(entry.first))
        model.fixed.add_index(entry.first);
    model.fixed.compress();
    IndexSet hanging(n_dofs);
    for (const auto &line : hanging_nodes.get_lines())
      if (model.owned.is_element(line.index) &&
          !model.fixed.is_element(line.index))
        hanging.add_index(line.index);
    hanging.compress();
    model.controls.subtract_set(hanging);
    model.controls.subtract_set(model.fixed);

    std::map<types::global_dof_index, Point<dim>> support_points;
    DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                         dof_handler,
                                         support_points);
    const unsigned int    n_components = dof_handler.get_fe().n_components();
    std::vector<IndexSet> of_component;
    for (unsigned int c = 0; c < n_components; ++c)
      {
        ComponentMask mask(n_components, false);
        mask.set(c, true);
        of_component.push_back(DoFTools::extract_dofs(dof_handler, mask));
      }
    model.locate_controls<dim>(
      [&](const types::global_dof_index i) { return support_points.at(i); },
      [&](const types::global_dof_index i) {
        unsigned int c = 0;
        while (!of_component[c].is_element(i))
          ++c;
        return c;
      });

    std::vector<types::global_dof_index> identity_rows;
    for (const IndexSet *rows : {&model.fixed, &model.controls, &hanging})
      identity_rows.insert(identity_rows.end(), rows->begin(), rows->end());
    model.matrix.clear_rows(identity_rows, 1.);
    for (const auto i : model.controls)
      model.rhs(i) = 0;
    for (const auto i : model.fixed)
      model.rhs(i) = dirichlet_values.at(i);
    for (const auto i : hanging)
      {
        for (const auto &entry : *hanging_nodes.get_constraint_entries(i))
          model.matrix.set(i, entry.first, -entry.second);
        model.rhs(i) = 0;
      }
    model.matrix.compress(VectorOperation::insert);
    model.rhs.compress(VectorOperation::insert);
    model.constrained = hanging;
    // Both local problems' bilinear forms are symmetric, the assembly
    // condensed the hanging nodes (their columns are zero off the diagonal),
    // and the controls and Dirichlet data pin the rigid motions: the free
    // block without the hanging nodes' rows is symmetric positive definite.
    model.symmetric_free_block = true;
  }



#define LTN_INSTANTIATE(dim)                                          \
  template void setup_local_dofs(DoFHandler<dim> &,                   \
                                 const FiniteElement<dim> &,          \
                                 const MPI_Comm,                      \
                                 AffineConstraints<double> &,         \
                                 DiscreteModel &);                    \
  template void reinit_local_model(const DoFHandler<dim> &,           \
                                   const AffineConstraints<double> &, \
                                   DiscreteModel &);                  \
  template void close_local_model(                                    \
    const DoFHandler<dim> &,                                          \
    const AffineConstraints<double> &,                                \
    const std::map<types::global_dof_index, double> &,                \
    const types::boundary_id,                                         \
    DiscreteModel &);
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ltn/coupling/model_solver.h>

namespace ltn
{
  ModelSolver::ModelSolver(const DiscreteModel &model,
                           const ModelUnknowns &unknowns)
    : model(model)
    , unknowns(unknowns)
  {
    using index           = types::global_dof_index;
    const index n_free    = unknowns.free.size();
    const index n_control = unknowns.control.size();

    DynamicSparsityPattern ff(n_free, n_free), fc(n_free, n_control);
    for (index r = 0; r < n_free; ++r)
      for (auto entry = model.matrix.begin(unknowns.free[r]);
           entry != model.matrix.end(unknowns.free[r]);
           ++entry)
        {
          const index position = unknowns.position[entry->column()];
          if (position == ModelUnknowns::none)
            continue;
          if (position < n_free)
            ff.add(r, position);
          else
            fc.add(r, position - n_free);
        }
    free_free_sparsity.copy_from(ff);
    free_control_sparsity.copy_from(fc);
    free_free.reinit(free_free_sparsity);
    free_control.reinit(free_control_sparsity);

    data_rhs.reinit(n_free);
    for (index r = 0; r < n_free; ++r)
      {
        const index row = unknowns.free[r];
        data_rhs[r]     = model.rhs[row];
        for (auto entry = model.matrix.begin(row);
             entry != model.matrix.end(row);
             ++entry)
          {
            const index position = unknowns.position[entry->column()];
            if (position == ModelUnknowns::none)
              data_rhs[r] -=
                entry->value() * model.fixed_values[entry->column()];
            else if (position < n_free)
              free_free.set(r, position, entry->value());
            else
              free_control.set(r, position - n_free, entry->value());
          }
      }
    direct.initialize(free_free);
  }



  Vector<double>
  ModelSolver::forward(const Vector<double> &theta, const bool with_data) const
  {
    const auto     n_free = unknowns.free.size();
    Vector<double> rhs(n_free);
    free_control.vmult(rhs, theta);
    rhs *= -1.;
    if (with_data)
      rhs += data_rhs;
    Vector<double> state(n_free);
    direct.vmult(state, rhs);

    Vector<double> field(model.roles.size());
    if (with_data)
      field = model.fixed_values;
    for (std::size_t r = 0; r < n_free; ++r)
      field[unknowns.free[r]] = state[r];
    for (std::size_t c = 0; c < unknowns.control.size(); ++c)
      field[unknowns.control[c]] = theta[c];
    return field;
  }



  Vector<double>
  ModelSolver::adjoint(const Vector<double> &z) const
  {
    Vector<double> z_free(unknowns.free.size());
    for (std::size_t r = 0; r < z_free.size(); ++r)
      z_free[r] = z[unknowns.free[r]];
    Vector<double> multiplier(z_free.size());
    direct.Tvmult(multiplier, z_free);

    Vector<double> gradient(unknowns.control.size());
    free_control.Tvmult(gradient, multiplier);
    gradient *= -1.;
    for (std::size_t c = 0; c < gradient.size(); ++c)
      gradient[c] += z[unknowns.control[c]];
    return gradient;
  }
} // namespace ltn

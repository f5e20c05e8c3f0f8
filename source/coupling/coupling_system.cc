#include <ltn/coupling/coupling_system.h>

namespace ltn
{
  ModelUnknowns::ModelUnknowns(const DiscreteModel &model)
    : position(model.roles.size(), none)
  {
    for (types::global_dof_index i = 0; i < model.roles.size(); ++i)
      if (model.roles[i] == DofRole::free)
        free.push_back(i);
      else if (model.roles[i] == DofRole::control)
        control.push_back(i);
    for (types::global_dof_index k = 0; k < free.size(); ++k)
      position[free[k]] = k;
    for (types::global_dof_index k = 0; k < control.size(); ++k)
      position[control[k]] = free.size() + k;
  }



  types::global_dof_index
  ModelUnknowns::n_unknowns() const
  {
    return free.size() + control.size();
  }



  template <int dim>
  CouplingSystem<dim>::CouplingSystem(const DiscreteModel          &nonlocal,
                                      const DiscreteModel          &local,
                                      const OverlapQuadrature<dim> &overlap,
                                      const double tikhonov_parameter)
    : models{{&nonlocal, &local}}
    , unknowns{{ModelUnknowns(nonlocal), ModelUnknowns(local)}}
    , overlap(overlap)
    , alpha(tikhonov_parameter)
  {}



  template <int dim>
  Vector<double>
  CouplingSystem<dim>::mismatch(const Vector<double> &u_nonlocal,
                                const Vector<double> &u_local) const
  {
    Vector<double> d(overlap.weights.size());
    for (std::size_t q = 0; q < d.size(); ++q)
      {
        for (const auto &[i, e] : overlap.nonlocal_rows[q])
          d[q] += e * u_nonlocal[i];
        for (const auto &[j, p] : overlap.local_rows[q])
          d[q] -= p * u_local[j];
      }
    return d;
  }



  template <int dim>
  double
  CouplingSystem<dim>::objective(const Vector<double> &u_nonlocal,
                                 const Vector<double> &u_local) const
  {
    const Vector<double> d = mismatch(u_nonlocal, u_local);
    double               J = 0;
    for (std::size_t q = 0; q < d.size(); ++q)
      J += 0.5 * overlap.weights[q] * d[q] * d[q];
    return J;
  }



  template <int dim>
  void
  CouplingSystem<dim>::mismatch_gradient(const Vector<double> &d,
                                         Vector<double> &gradient_nonlocal,
                                         Vector<double> &gradient_local) const
  {
    gradient_nonlocal.reinit(models[nonlocal_model]->roles.size());
    gradient_local.reinit(models[local_model]->roles.size());
    for (std::size_t q = 0; q < d.size(); ++q)
      {
        const double wd = overlap.weights[q] * d[q];
        for (const auto &[i, e] : overlap.nonlocal_rows[q])
          gradient_nonlocal[i] += e * wd;
        for (const auto &[j, p] : overlap.local_rows[q])
          gradient_local[j] -= p * wd;
      }
  }



  template <int dim>
  types::global_dof_index
  CouplingSystem<dim>::n_controls() const
  {
    return unknowns[0].control.size() + unknowns[1].control.size();
  }

  template class CouplingSystem<1>;
  template class CouplingSystem<2>;
  template class CouplingSystem<3>;
} // namespace ltn

#pragma once

#include <deal.II/lac/vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/coupling/overlap_quadrature.h>

#include <array>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /** Which of the two models: index into the arrays of CouplingSystem. */
  enum ModelIndex : unsigned int
  {
    nonlocal_model = 0,
    local_model    = 1
  };

  /**
   * The unknowns of one model in the optimality system: its free degrees of
   * freedom (the states, numbered first) and its controls (numbered after),
   * as positions in the model's block. Fixed degrees of freedom have none.
   */
  struct ModelUnknowns
  {
    explicit ModelUnknowns(const DiscreteModel &model);

    /** Sentinel of `position` for fixed degrees of freedom. */
    static constexpr types::global_dof_index none = numbers::invalid_dof_index;

    std::vector<types::global_dof_index> free;
    std::vector<types::global_dof_index> control;
    /** Position of each degree of freedom in [free, control], or `none`. */
    std::vector<types::global_dof_index> position;

    types::global_dof_index
    n_unknowns() const;
  };

  /**
   * The pieces of the discrete optimality problem (section 4 of the design)
   * that every solver of it shares:
   *
   *   minimize J_h = 1/2 sum_q w_q (E_q u_n - P_q u_l)^2 + alpha/2 |theta|^2
   *   subject to the free rows of A_n u_n = F_n and of A_l u_l = F_l,
   *
   * where each `u_k` holds the states, the controls `theta_k`, and the fixed
   * physical data of model `k`.
   */
  template <int dim>
  class CouplingSystem
  {
  public:
    CouplingSystem(const DiscreteModel          &nonlocal,
                   const DiscreteModel          &local,
                   const OverlapQuadrature<dim> &overlap,
                   const double                  tikhonov_parameter);

    /** The mismatch `d_q = E_q u_n - P_q u_l` at every overlap point. */
    Vector<double>
    mismatch(const Vector<double> &u_nonlocal,
             const Vector<double> &u_local) const;

    /** `J_h` without the Tikhonov term. */
    double
    objective(const Vector<double> &u_nonlocal,
              const Vector<double> &u_local) const;

    /**
     * The gradient of `1/2 sum_q w_q d_q^2` with respect to each model's
     * degrees of freedom, for a given mismatch @p d: `E^T W d` and
     * `-P^T W d`.
     */
    void
    mismatch_gradient(const Vector<double> &d,
                      Vector<double>       &gradient_nonlocal,
                      Vector<double>       &gradient_local) const;

    /** The number of controls of both models. */
    types::global_dof_index
    n_controls() const;

    std::array<const DiscreteModel *, 2> models;
    std::array<ModelUnknowns, 2>         unknowns;
    const OverlapQuadrature<dim>        &overlap;
    const double                         alpha;
  };

  /** A solution of the optimality system, with the solver's statistics. */
  struct CouplingSolution
  {
    /** Each model's field on all its degrees of freedom. */
    std::array<Vector<double>, 2> fields;
    unsigned int                  iterations = 0;
    /** The relative residual the solver reached. */
    double residual = 0;
  };
} // namespace ltn

#include <ltn/coupling/deflated_cg.h>

namespace ltn
{
  NormalEquations::Observation
  NormalEquations::observe_controls(const BlockVectorType &x) const
  {
    return observe(
      {{forward(0, x.block(0), nullptr), forward(1, x.block(1), nullptr)}});
  }



  NormalEquations::BlockVectorType
  NormalEquations::gradient(const Observation &d) const
  {
    return adjoint(observe_transpose(d));
  }



  DeflationSpace::DeflationSpace(std::vector<Column>    Z_,
                                 const NormalEquations &equations)
    : equations(equations)
    , Z(std::move(Z_))
  {
    const unsigned int m = Z.size();
    for (auto &z : Z)
      {
        states.push_back(
          equations.forward(z.model,
                            z.controls,
                            z.state_guess.size() ? &z.state_guess : nullptr));
        z.state_guess.clear(); // the state itself is kept
      }
    // E(i, j) = (V z_i)^T B^T W B (V z_j) + alpha z_i . z_j, a column at a
    // time from the states' gradient of column j's observation.
    coarse_matrix.reinit(m, m);
    for (unsigned int j = 0; j < m; ++j)
      {
        NormalEquations::States column{
          {equations.new_state(0), equations.new_state(1)}};
        column[Z[j].model] = states[j];
        const NormalEquations::States gradient =
          equations.observe_transpose(equations.observe(column));
        for (unsigned int i = 0; i < m; ++i)
          coarse_matrix(i, j) =
            states[i] * gradient[Z[i].model] +
            (equations.alpha != 0 && Z[i].model == Z[j].model ?
               equations.alpha * (Z[i].controls * Z[j].controls) :
               0.);
      }
    // Symmetric but for round-off.
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < i; ++j)
        coarse_matrix(i, j) = coarse_matrix(j, i) =
          0.5 * (coarse_matrix(i, j) + coarse_matrix(j, i));
    coarse_matrix.set_property(LAPACKSupport::symmetric);
    if (m > 0)
      coarse_matrix.compute_cholesky_factorization();
  }



  void
  DeflationSpace::coarse_solve(Vector<double> &y) const
  {
    if (y.size() > 0)
      coarse_matrix.solve(y);
  }



  Vector<double>
  DeflationSpace::solve(const BlockVectorType &b) const
  {
    Vector<double> y(Z.size());
    for (std::size_t j = 0; j < Z.size(); ++j)
      y(j) = dot(Z[j], b);
    coarse_solve(y);
    return y;
  }



  Vector<double>
  DeflationSpace::solve_product(const BlockVectorType &v,
                                const Observation     &observed) const
  {
    Vector<double> y(Z.size());
    if (Z.empty())
      return y;
    const NormalEquations::States gradient =
      equations.observe_transpose(observed);
    for (std::size_t j = 0; j < Z.size(); ++j)
      y(j) = states[j] * gradient[Z[j].model] +
             (equations.alpha != 0 ? equations.alpha * dot(Z[j], v) : 0.);
    coarse_solve(y);
    return y;
  }



  void
  DeflationSpace::add(const Vector<double> &c,
                      BlockVectorType      &v,
                      Observation          &observed) const
  {
    if (Z.empty())
      return;
    NormalEquations::States combined{
      {equations.new_state(0), equations.new_state(1)}};
    for (std::size_t j = 0; j < Z.size(); ++j)
      {
        v.block(Z[j].model).add(c(j), Z[j].controls);
        combined[Z[j].model].add(c(j), states[j]);
      }
    const Observation added = equations.observe(combined);
    for (std::size_t q = 0; q < observed.size(); ++q)
      observed[q] += added[q];
  }



  double
  DeflationSpace::dot(const Column &z, const BlockVectorType &v) const
  {
    return z.controls * v.block(z.model);
  }



  unsigned int
  DeflationSpace::size() const
  {
    return Z.size();
  }



  void
  solve_deflated_cg(
    const NormalEquations &equations,
    const DeflationSpace  &coarse,
    const std::function<void(NormalEquations::BlockVectorType &,
                             const NormalEquations::BlockVectorType &)>
                                                    &precondition,
    const NormalEquations::BlockVectorType          &b,
    NormalEquations::BlockVectorType                &x,
    SolverControl                                   &control,
    const std::function<void(double residual_norm)> &before_products)
  {
    using BlockVectorType = NormalEquations::BlockVectorType;
    using Observation     = NormalEquations::Observation;
    const double alpha    = equations.alpha;
    const auto   product  = [&](const BlockVectorType &v,
                             const Observation     &observed) {
      BlockVectorType Av = equations.gradient(observed);
      Av.add(alpha, v);
      return Av;
    };

    // Start from the coarse solution x = Z E^{-1} Z^T b, so that the
    // residual is orthogonal to Z.
    x                 = 0.;
    BlockVectorType r = b;
    if (coarse.size() > 0)
      {
        Observation observed_x =
          equations.observe({{equations.new_state(0), equations.new_state(1)}});
        coarse.add(coarse.solve(b), x, observed_x);
        r -= product(x, observed_x);
      }
    double       residual = r.l2_norm();
    unsigned int step     = 0;
    if (control.check(step, residual) == SolverControl::success)
      return;

    // The direction p = z - Z E^{-1} Z^T A z is A-orthogonal to Z; its
    // observation F p follows from F z by the same combination.
    BlockVectorType z                       = b;
    const auto      preconditioned_residual = [&]() {
      before_products(residual);
      precondition(z, r);
      return equations.observe_controls(z);
    };
    Observation    observed_z = preconditioned_residual();
    Vector<double> c          = coarse.solve_product(z, observed_z);
    c *= -1.;
    BlockVectorType p          = z;
    Observation     observed_p = observed_z;
    coarse.add(c, p, observed_p);
    double rz = r * z;

    while (true)
      {
        const BlockVectorType q  = product(p, observed_p);
        const double          pq = p * q;
        if (!(pq > 0))
          throw SolverControl::NoConvergence(step, residual);
        const double step_length = rz / pq;
        x.add(step_length, p);
        r.add(-step_length, q);
        residual                         = r.l2_norm();
        const SolverControl::State state = control.check(++step, residual);
        if (state == SolverControl::success)
          return;
        if (state == SolverControl::failure)
          throw SolverControl::NoConvergence(step, residual);

        observed_z          = preconditioned_residual();
        const double rz_new = r * z;
        const double beta   = rz_new / rz;
        rz                  = rz_new;
        c                   = coarse.solve_product(z, observed_z);
        c *= -1.;
        p.sadd(beta, 1., z);
        for (std::size_t i = 0; i < observed_p.size(); ++i)
          observed_p[i] = beta * observed_p[i] + observed_z[i];
        coarse.add(c, p, observed_p);
      }
  }
} // namespace ltn

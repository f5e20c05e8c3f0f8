#include <ltn/coupling/solvers/deflated_cg.h>

#include <algorithm>
#include <utility>

namespace ltn
{
  void
  solve_deflated_cg(
    const NormalEquations &equations,
    const DeflationSpace  &coarse,
    const std::function<void(NormalEquations::BlockVectorType &,
                             const NormalEquations::BlockVectorType &)>
                                                    &precondition,
    const NormalEquations::Observation              &data,
    NormalEquations::BlockVectorType                &x,
    SolverControl                                   &control,
    const std::function<void(double residual_norm)> &before_products,
    NormalEquations::States                         *states,
    RitzValues                                      *ritz_values)
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

    // Where the columns span a model's controls (every local control is a
    // column of the reduced space's coarse space), the residual, orthogonal
    // to Z, is zero there; it is set so exactly, and so is the
    // preconditioned residual: the directions' parts there are coarse
    // corrections alone, and the iterations need no forward solve of that
    // model.
    const auto zero_spanned = [&](BlockVectorType &v) {
      for (const unsigned int k : {0u, 1u})
        if (coarse.spans(k))
          v.block(k) = 0.;
    };

    // Start from the coarse solution x = Z E^{-1} Z^T b, so that the
    // residual is orthogonal to Z. With b = -F^T W d, Z^T b = -(F Z)^T W d
    // needs no adjoint solve, and r = b - A x = -(F^T W (d + F x) + alpha x)
    // only one: b itself is never formed.
    //
    // The states V x, where they are wanted, are tracked as V y + V Z c_x
    // with the coarse coefficients c_x apart (and V p as V y_p + V Z c_p),
    // so that V Z is combined once, at the end, not in every iteration.
    const unsigned int m = coarse.size();
    Vector<double>     coarse_x(m), coarse_p(m);
    const auto         finish = [&]() {
      if (states)
        coarse.add_states(coarse_x, *states);
    };
    x                      = 0.;
    Observation observed_x = equations.observe(NormalEquations::States());
    if (m > 0)
      {
        coarse_x = coarse.solve_product(x, data);
        coarse_x *= -1.;
        coarse.add(coarse_x, x, observed_x);
      }
    for (std::size_t q = 0; q < observed_x.size(); ++q)
      observed_x[q] += data[q];
    BlockVectorType r = product(x, observed_x);
    r *= -1.;
    zero_spanned(r);
    double       residual = r.l2_norm();
    unsigned int step     = 0;
    if (control.check(step, residual) == SolverControl::success)
      return finish();

    // The direction p = z - Z E^{-1} Z^T A z is A-orthogonal to Z; its
    // observation F p, and its states V p where they are wanted, follow from
    // those of z by the same combination.
    BlockVectorType         z = r;
    NormalEquations::States states_z;
    const auto              preconditioned_residual = [&]() {
      before_products(residual);
      precondition(z, r);
      zero_spanned(z);
      NormalEquations::States u;
      for (const unsigned int k : {0u, 1u})
        if (coarse.spans(k))
          u[k] = equations.new_state(k); // z is zero there
        else
          u[k] = equations.forward(k, z.block(k), nullptr);
      const Observation observed = equations.observe(u);
      if (states)
        states_z = std::move(u); // kept only to form V p
      return observed;
    };
    Observation    observed_z = preconditioned_residual();
    Vector<double> c          = coarse.solve_product(z, observed_z);
    c *= -1.;
    BlockVectorType         p          = z;
    Observation             observed_p = observed_z;
    NormalEquations::States states_p;
    if (states)
      states_p = std::move(states_z); // formed anew in each iteration
    coarse.add(c, p, observed_p);
    coarse_p  = c;
    double rz = r * z;

    while (true)
      {
        const BlockVectorType q  = product(p, observed_p);
        const double          pq = p * q;
        if (!(pq > 0))
          throw SolverControl::NoConvergence(step, residual);
        const double step_length = rz / pq;
        if (ritz_values)
          ritz_values->add_step_length(step_length);
        x.add(step_length, p);
        if (states)
          {
            for (const unsigned int k : {0u, 1u})
              (*states)[k].add(step_length, states_p[k]);
            coarse_x.add(step_length, coarse_p);
          }
        r.add(-step_length, q);
        zero_spanned(r);
        residual                         = r.l2_norm();
        const SolverControl::State state = control.check(++step, residual);
        if (state == SolverControl::success)
          return finish();
        if (state == SolverControl::failure)
          throw SolverControl::NoConvergence(step, residual);

        observed_z          = preconditioned_residual();
        const double rz_new = r * z;
        const double beta   = rz_new / rz;
        if (ritz_values)
          ritz_values->add_direction_coefficient(beta);
        rz = rz_new;
        c  = coarse.solve_product(z, observed_z);
        c *= -1.;
        p.sadd(beta, 1., z);
        for (std::size_t i = 0; i < observed_p.size(); ++i)
          observed_p[i] = beta * observed_p[i] + observed_z[i];
        if (states)
          for (const unsigned int k : {0u, 1u})
            states_p[k].sadd(beta, 1., states_z[k]);
        coarse.add(c, p, observed_p);
        coarse_p.sadd(beta, 1., c);
      }
  }
} // namespace ltn

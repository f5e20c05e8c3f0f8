#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <ltn/base/input_error.h>
#include <ltn/coupling/model_solver.h>
#include <ltn/coupling/reduced_space_solver.h>

namespace ltn
{
  namespace
  {
    /** The reduced Hessian `V^T B^T W B V + alpha I` as an operator. */
    template <int dim>
    class ReducedHessian
    {
    public:
      ReducedHessian(const CouplingSystem<dim>          &system,
                     const std::array<ModelSolver *, 2> &solvers)
        : system(system)
        , solvers(solvers)
        , n_nonlocal(system.unknowns[nonlocal_model].control.size())
      {}

      /** Split controls into the two models' parts. */
      std::array<Vector<double>, 2>
      split(const Vector<double> &theta) const
      {
        std::array<Vector<double>, 2> parts{
          {Vector<double>(n_nonlocal),
           Vector<double>(theta.size() - n_nonlocal)}};
        for (std::size_t i = 0; i < theta.size(); ++i)
          (i < n_nonlocal ? parts[0][i] : parts[1][i - n_nonlocal]) = theta[i];
        return parts;
      }

      /** `V^T B^T W d` for a mismatch @p d. */
      Vector<double>
      reduced_gradient(const Vector<double> &d) const
      {
        Vector<double> z_nonlocal, z_local;
        system.mismatch_gradient(d, z_nonlocal, z_local);
        const Vector<double> g_nonlocal = solvers[0]->adjoint(z_nonlocal);
        const Vector<double> g_local    = solvers[1]->adjoint(z_local);
        Vector<double>       g(g_nonlocal.size() + g_local.size());
        for (std::size_t i = 0; i < g.size(); ++i)
          g[i] = (i < n_nonlocal) ? g_nonlocal[i] : g_local[i - n_nonlocal];
        return g;
      }

      void
      vmult(Vector<double> &dst, const Vector<double> &theta) const
      {
        const auto parts = split(theta);
        dst              = reduced_gradient(
          system.mismatch(solvers[0]->forward(parts[0], false),
                          solvers[1]->forward(parts[1], false)));
        dst.add(system.alpha, theta);
      }

    private:
      const CouplingSystem<dim>         &system;
      const std::array<ModelSolver *, 2> solvers;
      const std::size_t                  n_nonlocal;
    };
  } // namespace



  template <int dim>
  CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<dim> &system,
                         const double               relative_tolerance,
                         const unsigned int         max_iterations)
  {
    ModelSolver               nonlocal_solver(*system.models[nonlocal_model],
                                system.unknowns[nonlocal_model]);
    ModelSolver               local_solver(*system.models[local_model],
                             system.unknowns[local_model]);
    const ReducedHessian<dim> hessian(system,
                                      {{&nonlocal_solver, &local_solver}});

    Vector<double> theta(system.n_controls());
    const auto     zero = hessian.split(theta);
    Vector<double> rhs  = hessian.reduced_gradient(
      system.mismatch(nonlocal_solver.forward(zero[0], true),
                      local_solver.forward(zero[1], true)));
    rhs *= -1.;

    CouplingSolution solution;
    if (rhs.l2_norm() > 0)
      {
        ReductionControl control(max_iterations, 0., relative_tolerance);
        SolverCG<Vector<double>> cg(control);
        try
          {
            cg.solve(hessian, theta, rhs, PreconditionIdentity());
          }
        catch (const SolverControl::NoConvergence &)
          {
            throw std::runtime_error(
              "the reduced-space CG did not reduce the residual by "
              "Coupling/Relative tolerance = " +
              to_string(relative_tolerance) +
              " within Coupling/Maximum iterations = " +
              std::to_string(max_iterations) + " (relative residual " +
              to_string(control.last_value() / rhs.l2_norm()) + ")");
          }
        solution.iterations = control.last_step();
        solution.residual   = control.last_value() / rhs.l2_norm();
      }
    const auto parts                = hessian.split(theta);
    solution.fields[nonlocal_model] = nonlocal_solver.forward(parts[0], true);
    solution.fields[local_model]    = local_solver.forward(parts[1], true);
    return solution;
  }

  template CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<1> &, double, unsigned int);
  template CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<2> &, double, unsigned int);
  template CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<3> &, double, unsigned int);
} // namespace ltn

#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ltn/base/input_error.h>
#include <ltn/coupling/model_solver.h>
#include <ltn/coupling/reduced_space_solver.h>

namespace ltn
{
  namespace
  {
    using BlockVectorType = TrilinosWrappers::MPI::BlockVector;

    /**
     * The reduced Hessian `V^T B^T W B V + alpha I` as an operator on the
     * controls `[theta_n; theta_l]`, one block per model.
     */
    template <int dim>
    class ReducedHessian
    {
    public:
      ReducedHessian(const CouplingSystem<dim>          &system,
                     const std::array<ModelSolver *, 2> &solvers)
        : system(system)
        , solvers(solvers)
      {}

      BlockVectorType
      new_control_vector() const
      {
        BlockVectorType theta(2);
        for (const unsigned int k : {0u, 1u})
          theta.block(k) = solvers[k]->new_control_vector();
        theta.collect_sizes();
        return theta;
      }

      /** `V^T B^T W d` for a mismatch @p d at this rank's points. */
      BlockVectorType
      reduced_gradient(const std::vector<double> &d) const
      {
        std::array<TrilinosWrappers::MPI::Vector, 2> z;
        system.mismatch_gradient(d, z[0], z[1]);
        BlockVectorType g(2);
        for (const unsigned int k : {0u, 1u})
          g.block(k) = solvers[k]->adjoint(z[k]);
        g.collect_sizes();
        return g;
      }

      /** The mismatch of the fields for controls @p theta. */
      std::vector<double>
      mismatch(const BlockVectorType &theta, const bool with_data) const
      {
        return system.mismatch(solvers[0]->forward(theta.block(0), with_data),
                               solvers[1]->forward(theta.block(1), with_data));
      }

      void
      vmult(BlockVectorType &dst, const BlockVectorType &theta) const
      {
        dst = reduced_gradient(mismatch(theta, false));
        dst.add(system.alpha, theta);
      }

    private:
      const CouplingSystem<dim>         &system;
      const std::array<ModelSolver *, 2> solvers;
    };
  } // namespace



  template <int dim>
  CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<dim> &system,
                         const double               relative_tolerance,
                         const unsigned int         max_iterations,
                         const ModelSolverSettings &model_solvers)
  {
    ModelSolver nonlocal_solver(*system.models[nonlocal_model],
                                true,
                                model_solvers);
    ModelSolver local_solver(*system.models[local_model], true, model_solvers);
    const ReducedHessian<dim> hessian(system,
                                      {{&nonlocal_solver, &local_solver}});

    BlockVectorType theta = hessian.new_control_vector();
    BlockVectorType rhs =
      hessian.reduced_gradient(hessian.mismatch(theta, true));
    rhs *= -1.;

    CouplingSolution solution;
    const double     rhs_norm = rhs.l2_norm();
    if (rhs_norm > 0)
      {
        ReductionControl control(max_iterations, 0., relative_tolerance);
        SolverCG<BlockVectorType> cg(control);
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
              to_string(control.last_value() / rhs_norm) + ")");
          }
        solution.iterations = control.last_step();
        solution.residual   = control.last_value() / rhs_norm;
      }
    solution.fields[nonlocal_model] =
      nonlocal_solver.forward(theta.block(0), true);
    solution.fields[local_model] = local_solver.forward(theta.block(1), true);
    solution.model_solvers       = {
      {nonlocal_solver.statistics(), local_solver.statistics()}};
    return solution;
  }

  template CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<1> &,
                         double,
                         unsigned int,
                         const ModelSolverSettings &);
  template CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<2> &,
                         double,
                         unsigned int,
                         const ModelSolverSettings &);
  template CouplingSolution
  solve_reduced_space_cg(const CouplingSystem<3> &,
                         double,
                         unsigned int,
                         const ModelSolverSettings &);
} // namespace ltn

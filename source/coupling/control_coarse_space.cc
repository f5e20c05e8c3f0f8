#include <deal.II/base/mpi.h>

#include <ltn/coupling/control_coarse_space.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ltn
{
  ControlCoarseSpace::ControlCoarseSpace(std::vector<BlockVectorType> Z_,
                                         const Operator              &H)
    : Z(std::move(Z_))
  {
    const unsigned int m = Z.size();
    for (const auto &z : Z)
      {
        BlockVectorType hz(z);
        H(hz, z);
        HZ.push_back(hz);
      }
    // H's products are exact only to the inner solvers' tolerance.
    coarse_matrix.reinit(m, m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        coarse_matrix(i, j) = 0.5 * (Z[i] * HZ[j] + Z[j] * HZ[i]);
    coarse_matrix.set_property(LAPACKSupport::symmetric);
    if (m > 0)
      coarse_matrix.compute_cholesky_factorization();
  }



  Vector<double>
  ControlCoarseSpace::coarse_solve(const std::vector<BlockVectorType> &Y,
                                   const BlockVectorType              &v) const
  {
    Vector<double> c(Y.size());
    for (std::size_t j = 0; j < Y.size(); ++j)
      c(j) = Y[j] * v;
    if (c.size() > 0)
      coarse_matrix.solve(c);
    return c;
  }



  void
  ControlCoarseSpace::balance(BlockVectorType       &dst,
                              const BlockVectorType &src,
                              const Operator        &smooth) const
  {
    // c = E^{-1} Z^T r: the coarse part Z c, and the rest r - H Z c.
    const Vector<double> c    = coarse_solve(Z, src);
    BlockVectorType      rest = src;
    for (unsigned int j = 0; j < Z.size(); ++j)
      rest.add(-c(j), HZ[j]);
    smooth(dst, rest);
    // (I - Z E^{-1} (H Z)^T) on the smoothed rest, plus the coarse part.
    const Vector<double> d = coarse_solve(HZ, dst);
    for (unsigned int j = 0; j < Z.size(); ++j)
      dst.add(c(j) - d(j), Z[j]);
  }



  unsigned int
  ControlCoarseSpace::size() const
  {
    return Z.size();
  }



  namespace
  {
    /** The exponents of the monomials in @p dim variables up to @p degree. */
    std::vector<std::array<unsigned int, 3>>
    monomials(const unsigned int dim, const unsigned int degree)
    {
      std::vector<std::array<unsigned int, 3>> result;
      for (unsigned int a = 0; a <= degree; ++a)
        for (unsigned int b = 0; b <= (dim > 1 ? degree - a : 0); ++b)
          for (unsigned int c = 0; c <= (dim > 2 ? degree - a - b : 0); ++c)
            result.push_back({{a, b, c}});
      return result;
    }
  } // namespace



  template <int dim>
  std::vector<TrilinosWrappers::MPI::BlockVector>
  polynomial_control_fields(const ReducedHessian<dim>       &hessian,
                            const unsigned int               degree,
                            const std::vector<unsigned int> &models)
  {
    std::vector<TrilinosWrappers::MPI::BlockVector> Z;
    const MPI_Comm communicator = hessian.system.communicator();
    for (const unsigned int k : models)
      {
        const DiscreteModel  &model = *hessian.system.models[k];
        const auto           &x     = model.control_positions;
        std::array<double, 3> low, high;
        for (unsigned int d = 0; d < 3; ++d)
          {
            low[d]  = std::numeric_limits<double>::max();
            high[d] = -std::numeric_limits<double>::max();
            for (const auto &p : x)
              {
                low[d]  = std::min(low[d], p[d]);
                high[d] = std::max(high[d], p[d]);
              }
            low[d]  = -Utilities::MPI::max(-low[d], communicator);
            high[d] = Utilities::MPI::max(high[d], communicator);
          }
        double half_width = 0;
        for (unsigned int d = 0; d < dim; ++d)
          half_width = std::max(half_width, 0.5 * (high[d] - low[d]));
        if (!(half_width > 0))
          continue; // no controls, or one point
        const unsigned int n_components = Utilities::MPI::max(
          x.empty() ? 0u :
                      1u + *std::max_element(model.control_components.begin(),
                                             model.control_components.end()),
          communicator);

        const IndexSet owned =
          hessian.solvers[k]->new_control_vector().locally_owned_elements();
        const types::global_dof_index first =
          owned.is_empty() ? 0 : owned.nth_index_in_set(0);
        for (const auto &exponents : monomials(dim, degree))
          for (unsigned int c = 0; c < n_components; ++c)
            {
              auto z = hessian.new_control_vector();
              for (std::size_t i = 0; i < x.size(); ++i)
                if (model.control_components[i] == c)
                  {
                    double value = 1;
                    for (unsigned int d = 0; d < dim; ++d)
                      value *= std::pow((x[i][d] - 0.5 * (low[d] + high[d])) /
                                          half_width,
                                        exponents[d]);
                    z.block(k)(first + i) = value;
                  }
              z.compress(VectorOperation::insert);
              // Gram-Schmidt, twice; a column the others span is dropped
              // (on controls in a plane, x and 1 are the same field).
              const double norm = z.l2_norm();
              for (unsigned int pass = 0; pass < 2; ++pass)
                for (const auto &q : Z)
                  z.add(-(z * q), q);
              const double remaining = z.l2_norm();
              if (remaining > 1e-8 * norm)
                {
                  z /= remaining;
                  Z.push_back(z);
                }
            }
      }
    return Z;
  }

  template <int dim>
  std::vector<TrilinosWrappers::MPI::Vector>
  unit_control_fields(const ReducedHessian<dim> &hessian, const unsigned int k)
  {
    std::vector<TrilinosWrappers::MPI::Vector> Z;
    const unsigned int n = hessian.solvers[k]->new_control_vector().size();
    for (unsigned int j = 0; j < n; ++j)
      {
        auto z = hessian.solvers[k]->new_control_vector();
        if (z.in_local_range(j))
          z(j) = 1.;
        z.compress(VectorOperation::insert);
        Z.push_back(z);
      }
    return Z;
  }

#define LTN_INSTANTIATE(dim)                                               \
  template std::vector<TrilinosWrappers::MPI::BlockVector>                 \
  polynomial_control_fields(const ReducedHessian<dim> &,                   \
                            unsigned int,                                  \
                            const std::vector<unsigned int> &);            \
  template std::vector<TrilinosWrappers::MPI::Vector> unit_control_fields( \
    const ReducedHessian<dim> &, unsigned int);
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

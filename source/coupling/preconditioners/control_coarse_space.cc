#include <deal.II/base/mpi.h>

#include <ltn/coupling/preconditioners/control_coarse_space.h>

#include <algorithm>
#include <array>
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

    /**
     * A basis of the fields with @p n_components components whose every
     * component is a polynomial in @p dim variables of degree up to
     * @p degree, as sums of terms: the constants first, then the linear
     * fields, then the rest. Where the field is a displacement (@p dim
     * components, dim > 1), the linear fields are the rigid rotations and
     * then the symmetric strains: elasticity models reproduce rotations
     * exactly, so the coarse states of these start from their exact values.
     */
    std::vector<std::vector<MonomialTerm>>
    polynomial_fields(const unsigned int dim,
                      const unsigned int degree,
                      const unsigned int n_components)
    {
      std::vector<std::vector<MonomialTerm>> fields;
      const auto degree_of = [](const auto &exponents) {
        return exponents[0] + exponents[1] + exponents[2];
      };
      const bool displacement = n_components == dim && dim > 1;
      for (const unsigned int wanted : {0u, 1u, 2u})
        for (const auto &exponents : monomials(dim, degree))
          if (wanted == 2 ? degree_of(exponents) >= 2 :
                            degree_of(exponents) == wanted)
            for (unsigned int c = 0; c < n_components; ++c)
              if (!(displacement && wanted == 1))
                fields.push_back({{c, exponents, 1.}});
      if (displacement && degree >= 1)
        {
          const auto x = [](const unsigned int d) {
            std::array<unsigned int, 3> exponents = {{0, 0, 0}};
            exponents[d]                          = 1;
            return exponents;
          };
          std::vector<std::vector<MonomialTerm>> linear;
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int d = c + 1; d < dim; ++d)
              linear.push_back({{c, x(d), 1.}, {d, x(c), -1.}});
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int d = c; d < dim; ++d)
              linear.push_back(
                c == d ?
                  std::vector<MonomialTerm>{{c, x(c), 1.}} :
                  std::vector<MonomialTerm>{{c, x(d), 1.}, {d, x(c), 1.}});
          fields.insert(fields.begin() + n_components,
                        linear.begin(),
                        linear.end());
        }
      return fields;
    }
  } // namespace



  template <int dim>
  std::vector<PolynomialControlField>
  polynomial_control_fields(const ReducedHessian<dim>             &hessian,
                            const unsigned int                     degree,
                            const std::vector<unsigned int>       &models,
                            const std::vector<AffineProductField> &fields)
  {
    std::vector<PolynomialControlField> Z;
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
        const bool extended =
          Utilities::MPI::min(model.lattice ? 1u : 0u, communicator) > 0;

        const auto monomial =
          [&](const std::array<double, 3>       &p,
              const std::array<unsigned int, 3> &exponents) {
            double value = 1;
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int e = 0; e < exponents[d]; ++e)
                value *= (p[d] - 0.5 * (low[d] + high[d])) / half_width;
            return value;
          };
        // Each kept column as coefficients of the monomials per component
        // (`c n_monomials + m`), updated along with its controls by
        // Gram-Schmidt: the extensions are evaluated from these once, at the
        // end, instead of being updated at every projection, a pass over all
        // of the model's unknowns each.
        std::vector<std::vector<MonomialTerm>> columns =
          polynomial_fields(dim, degree, n_components);
        const std::size_t n_monomial_fields = columns.size();
        // The given fields, displacements, after the monomials: expanded in
        // the monomials' coordinates, to the degree of their products.
        unsigned int highest_degree = degree;
        if (n_components == dim && dim > 1)
          {
            std::array<double, 3> centre = {{0, 0, 0}};
            for (unsigned int d = 0; d < dim; ++d)
              centre[d] = 0.5 * (low[d] + high[d]);
            for (const AffineProductField &field : fields)
              {
                columns.push_back(
                  expand_in_frame(field, centre, half_width, dim));
                highest_degree =
                  std::max<unsigned int>(highest_degree, field.factors.size());
              }
          }
        const auto        exponents      = monomials(dim, highest_degree);
        const std::size_t n_monomials    = exponents.size();
        const std::size_t first_of_model = Z.size();
        std::vector<std::vector<double>> coefficients;
        for (std::size_t f = 0; f < columns.size(); ++f)
          {
            const std::vector<MonomialTerm> &field = columns[f];
            // The given fields come after the monomial ones.
            PolynomialControlField z{k,
                                     f >= n_monomial_fields,
                                     hessian.new_control_vector(),
                                     {}};
            std::vector<double>    column(n_components * n_monomials, 0.);
            // This rank's controls in the order of its control positions.
            TrilinosWrappers::MPI::Vector &controls = z.controls.block(k);
            for (const MonomialTerm &term : field)
              {
                for (std::size_t i = 0; i < x.size(); ++i)
                  if (model.control_components[i] == term.component)
                    controls.begin()[i] +=
                      term.coefficient * monomial(x[i], term.exponents);
                column[term.component * n_monomials +
                       (std::find(
                          exponents.begin(), exponents.end(), term.exponents) -
                        exponents.begin())] += term.coefficient;
              }
            // Gram-Schmidt, twice, against this model's fields (the other
            // models' are orthogonal to them); a column the others span is
            // dropped (on controls in a plane, x and 1 are the same field).
            const double norm = z.controls.l2_norm();
            for (unsigned int pass = 0; pass < 2; ++pass)
              for (std::size_t j = first_of_model; j < Z.size(); ++j)
                {
                  const double projection = z.controls * Z[j].controls;
                  z.controls.add(-projection, Z[j].controls);
                  for (std::size_t a = 0; a < column.size(); ++a)
                    column[a] -=
                      projection * coefficients[j - first_of_model][a];
                }
            const double remaining = z.controls.l2_norm();
            if (remaining > 1e-8 * norm)
              {
                z.controls /= remaining;
                for (double &c : column)
                  c /= remaining;
                coefficients.push_back(std::move(column));
                Z.push_back(std::move(z));
              }
          }

        std::vector<double> monomial_values(n_monomials);
        for (std::size_t j = first_of_model; extended && j < Z.size(); ++j)
          {
            const std::vector<double> &column =
              coefficients[j - first_of_model];
            Z[j].extension = model.new_vector();
            // A node's entries lie at node_dofs * node + c in the order of
            // `owned`.
            double             *entries = Z[j].extension.begin();
            const ModelLattice &lattice = *model.lattice;
            for (std::size_t n = 0; n < lattice.node_positions.size(); ++n)
              {
                for (std::size_t m = 0; m < n_monomials; ++m)
                  monomial_values[m] =
                    monomial(lattice.node_positions[n], exponents[m]);
                for (unsigned int c = 0; c < n_components; ++c)
                  {
                    double value = 0;
                    for (std::size_t m = 0; m < n_monomials; ++m)
                      value += column[c * n_monomials + m] * monomial_values[m];
                    entries[lattice.node_dofs * n + c] = value;
                  }
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
  template std::vector<PolynomialControlField> polynomial_control_fields(  \
    const ReducedHessian<dim> &,                                           \
    unsigned int,                                                          \
    const std::vector<unsigned int> &,                                     \
    const std::vector<AffineProductField> &);                              \
  template std::vector<TrilinosWrappers::MPI::Vector> unit_control_fields( \
    const ReducedHessian<dim> &, unsigned int);
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

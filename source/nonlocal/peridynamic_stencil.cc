#include <deal.II/base/exceptions.h>

#include <ltn/nonlocal/lattice_stencil.h>
#include <ltn/nonlocal/peridynamic_stencil.h>

#include <set>

namespace ltn
{
  template <int dim>
  PeridynamicStencil<dim>::PeridynamicStencil(const Kernel &influence,
                                              const double  spacing)
  {
    AssertThrow(dim > 1, ExcNotImplemented());
    std::vector<double> base;
    kernel_weighted_cell_volumes<dim>(influence, spacing, bond_offsets, base);
    const double eps = influence.horizon();
    for (const auto &o : bond_offsets)
      {
        Tensor<1, dim> xi;
        for (unsigned int d = 0; d < dim; ++d)
          xi[d] = o[d] * spacing;
        bond_vectors.push_back(xi);
      }

    // The anisotropy of the fourth moment, per bond (in units of eps^2):
    // g = (sum_a xi_a^4 - 3/(dim-1) sum_{a != b} xi_a^2 xi_b^2) / |xi|^2,
    // invariant under the lattice's symmetries, so the corrected weights
    // keep them. Minimize sum (c - c0)^2 / c0 subject to sum c g = 0.
    std::vector<double> g(base.size());
    double              c0_g = 0, c0_gg = 0;
    for (std::size_t j = 0; j < base.size(); ++j)
      {
        const Tensor<1, dim> xi     = bond_vectors[j] / eps;
        double               fourth = 0, mixed = 0;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            (a == b ? fourth : mixed) += xi[a] * xi[a] * xi[b] * xi[b];
        g[j] = (fourth - 3. / (dim - 1) * mixed) / xi.norm_square();
        c0_g += base[j] * g[j];
        c0_gg += base[j] * g[j] * g[j];
      }
    const double lambda = (c0_gg > 0) ? -c0_g / c0_gg : 0;
    for (std::size_t j = 0; j < base.size(); ++j)
      {
        bond_weights.push_back(base[j] * (1 + lambda * g[j]));
        AssertThrow(bond_weights.back() > 0,
                    ExcMessage("The LPS quadrature has a non-positive bond "
                               "weight: the horizon is too small for the "
                               "particle spacing."));
        m += bond_weights.back() * bond_vectors[j].norm_square();
      }
  }



  template <int dim>
  const std::vector<std::array<int, dim>> &
  PeridynamicStencil<dim>::offsets() const
  {
    return bond_offsets;
  }



  template <int dim>
  const std::vector<Tensor<1, dim>> &
  PeridynamicStencil<dim>::bonds() const
  {
    return bond_vectors;
  }



  template <int dim>
  const std::vector<double> &
  PeridynamicStencil<dim>::weights() const
  {
    return bond_weights;
  }



  template <int dim>
  double
  PeridynamicStencil<dim>::weighted_volume() const
  {
    return m;
  }



  template <int dim>
  std::vector<std::array<int, dim>>
  PeridynamicStencil<dim>::two_bond_reach() const
  {
    std::set<std::array<int, dim>> reach(bond_offsets.begin(),
                                         bond_offsets.end());
    for (const auto &a : bond_offsets)
      for (const auto &b : bond_offsets)
        {
          std::array<int, dim> sum;
          bool                 zero = true;
          for (unsigned int d = 0; d < dim; ++d)
            {
              sum[d] = a[d] + b[d];
              zero   = zero && sum[d] == 0;
            }
          if (!zero)
            reach.insert(sum);
        }
    return {reach.begin(), reach.end()};
  }

  template class PeridynamicStencil<2>;
  template class PeridynamicStencil<3>;
} // namespace ltn

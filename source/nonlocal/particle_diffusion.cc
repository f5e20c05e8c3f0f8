#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <ltn/nonlocal/particle_diffusion.h>

#include <cmath>
#include <set>

namespace ltn
{
  template <int dim>
  ParticleDiffusion<dim>::ParticleDiffusion(const Geometry<dim> &geometry,
                                            const Kernel        &kernel,
                                            const double         spacing)
    : geometry(geometry)
    , kernel(kernel)
    , spacing(spacing)
    , stencil(kernel, spacing)
  {
    // Lattice cells of Omega_n are 0 <= i_d < n_d; the collar extends them
    // by the stencil's radius, keeping the cells some particle of Omega_n
    // reaches: those whose offset from the nearest cell of Omega_n is a
    // stencil offset.
    const std::set<std::array<int, dim>> reach(stencil.offsets().begin(),
                                               stencil.offsets().end());
    const int                            R = stencil.radius();
    std::array<int, dim>                 n, extent;
    unsigned int                         n_candidates = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n[d] = static_cast<int>(std::round((geometry.nonlocal_region.upper[d] -
                                            geometry.nonlocal_region.lower[d]) /
                                           spacing));
        extent[d] = n[d] + 2 * R;
        n_candidates *= extent[d];
      }

    const double tol = geometry.tolerance();
    for (unsigned int c = 0; c < n_candidates; ++c)
      {
        std::array<int, dim> index, offset;
        unsigned int         rest   = c;
        bool                 inside = true;
        for (unsigned int d = 0; d < dim; ++d)
          {
            index[d] = static_cast<int>(rest % extent[d]) - R;
            rest /= extent[d];
            offset[d] = index[d] - std::clamp(index[d], 0, n[d] - 1);
            inside &= (offset[d] == 0);
          }
        if (!inside && reach.count(offset) == 0)
          continue;
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = geometry.nonlocal_region.lower[d] + (index[d] + 0.5) * spacing;
        positions.push_back(x);
        indices.push_back(index);
        model.roles.push_back(inside ? DofRole::free :
                              geometry.body.contains(x, tol) ?
                                       DofRole::control :
                                       DofRole::fixed);
      }
  }



  template <int dim>
  void
  ParticleDiffusion<dim>::assemble(const Function<dim> &rhs,
                                   const Function<dim> &volume_data)
  {
    // Particle number of each lattice index (dense over the extended box).
    const int            R = stencil.radius();
    std::array<int, dim> lo, extent;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lo[d] = -R, extent[d] = 2 * R + 1;
        for (const auto &index : indices)
          extent[d] = std::max(extent[d], index[d] + R + 1);
      }
    const auto linear = [&](const std::array<int, dim> &index) {
      std::size_t position = 0;
      for (int d = dim - 1; d >= 0; --d)
        position = position * extent[d] + (index[d] - lo[d]);
      return position;
    };
    std::size_t n_cells = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_cells *= extent[d];
    std::vector<types::global_dof_index> particle_at(
      n_cells, numbers::invalid_dof_index);
    for (types::global_dof_index i = 0; i < indices.size(); ++i)
      particle_at[linear(indices[i])] = i;

    const auto neighbour = [&](const types::global_dof_index i,
                               const std::array<int, dim>   &offset) {
      std::array<int, dim> index = indices[i];
      for (unsigned int d = 0; d < dim; ++d)
        index[d] += offset[d];
      const auto j = particle_at[linear(index)];
      Assert(j != numbers::invalid_dof_index, ExcInternalError());
      return j;
    };

    const auto                   &offsets      = stencil.offsets();
    const auto                   &coefficients = stencil.coefficients();
    const types::global_dof_index n            = positions.size();
    DynamicSparsityPattern        dsp(n);
    for (types::global_dof_index i = 0; i < n; ++i)
      if (model.roles[i] == DofRole::free)
        {
          dsp.add(i, i);
          for (const auto &offset : offsets)
            dsp.add(i, neighbour(i, offset));
        }
    model.sparsity.copy_from(dsp);
    model.matrix.reinit(model.sparsity);
    model.rhs.reinit(n);
    model.fixed_values.reinit(n);

    for (types::global_dof_index i = 0; i < n; ++i)
      if (model.roles[i] == DofRole::free)
        {
          for (std::size_t k = 0; k < offsets.size(); ++k)
            {
              model.matrix.add(i, i, 2 * coefficients[k]);
              model.matrix.add(i,
                               neighbour(i, offsets[k]),
                               -2 * coefficients[k]);
            }
          model.rhs[i] = rhs.value(positions[i]);
        }
      else if (model.roles[i] == DofRole::fixed)
        model.fixed_values[i] = volume_data.value(positions[i]);
  }



  template <int dim>
  const DiscreteModel &
  ParticleDiffusion<dim>::get_model() const
  {
    return model;
  }



  template <int dim>
  const std::vector<Point<dim>> &
  ParticleDiffusion<dim>::get_positions() const
  {
    return positions;
  }



  template <int dim>
  double
  ParticleDiffusion<dim>::particle_volume() const
  {
    return std::pow(spacing, dim);
  }



  template <int dim>
  std::vector<Region>
  ParticleDiffusion<dim>::regions() const
  {
    std::vector<Region> result;
    for (const auto &x : positions)
      result.push_back(geometry.nonlocal_region_of(x, kernel.horizon()));
    return result;
  }



  template <int dim>
  ErrorNorms
  ParticleDiffusion<dim>::errors(const Vector<double> &field,
                                 const Function<dim>  &exact) const
  {
    ErrorNorms errors;
    for (std::size_t i = 0; i < positions.size(); ++i)
      if (model.roles[i] == DofRole::free)
        {
          const double e = field[i] - exact.value(positions[i]);
          errors.l2_squared += particle_volume() * e * e;
          errors.add_pointwise(e);
        }
    return errors;
  }



  template class ParticleDiffusion<2>;
  template class ParticleDiffusion<3>;
} // namespace ltn

#include <deal.II/base/exceptions.h>

#include <ltn/nonlocal/particle_lattice.h>

#include <algorithm>
#include <set>

namespace ltn
{
  template <int dim>
  ParticleLattice<dim>::ParticleLattice(const Box<dim> &region,
                                        const double    spacing,
                                        const std::vector<LatticeIndex> &reach)
    : origin(region.lower)
    , spacing(spacing)
    , radius(0)
  {
    for (const auto &offset : reach)
      for (unsigned int d = 0; d < dim; ++d)
        radius = std::max(radius, std::abs(offset[d]));
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = static_cast<int>(
        std::round((region.upper[d] - region.lower[d]) / spacing));

    const std::set<LatticeIndex> reached(reach.begin(), reach.end());
    const auto                   is_reached = [&](const LatticeIndex &offset) {
      return reached.count(offset) == 1 ||
             std::all_of(offset.begin(), offset.end(), [](const int o) {
               return o == 0;
             });
    };

    std::size_t n_lines = 1;
    for (unsigned int d = 1; d < dim; ++d)
      n_lines *= n[d] + 2 * radius;
    line_start.assign(1, 0);
    for (std::size_t line = 0; line < n_lines; ++line)
      {
        // The offset of the line from Omega_n in the directions 1..dim-1.
        LatticeIndex offset;
        std::size_t  rest = line;
        for (unsigned int d = 1; d < dim; ++d)
          {
            const int i = static_cast<int>(rest % (n[d] + 2 * radius)) - radius;
            rest /= n[d] + 2 * radius;
            offset[d] = i - std::clamp(i, 0, n[d] - 1);
          }
        // The largest offset along x that is reached; all smaller ones must
        // be too, or numbering by lines would not work.
        int reach_x = -1;
        for (int o = 0; o <= radius; ++o)
          {
            offset[0] = o;
            if (!is_reached(offset))
              break;
            reach_x = o;
          }
        for (int o = reach_x + 1; o <= radius; ++o)
          {
            offset[0] = o;
            AssertThrow(!is_reached(offset),
                        ExcMessage("the stencil is not convex along x"));
          }
        first_x.push_back(reach_x < 0 ? 0 : -reach_x);
        end_x.push_back(reach_x < 0 ? 0 : n[0] + reach_x);
        line_start.push_back(line_start.back() +
                             (end_x.back() - first_x.back()));
      }
  }



  template <int dim>
  types::global_dof_index
  ParticleLattice<dim>::n_particles() const
  {
    return line_start.back();
  }



  template <int dim>
  std::size_t
  ParticleLattice<dim>::line_of(const LatticeIndex &index) const
  {
    std::size_t line = 0;
    for (int d = dim - 1; d >= 1; --d)
      {
        const int i = index[d] + radius;
        if (i < 0 || i >= n[d] + 2 * radius)
          return invalid;
        line = line * (n[d] + 2 * radius) + i;
      }
    return line;
  }



  template <int dim>
  types::global_dof_index
  ParticleLattice<dim>::number(const LatticeIndex &index) const
  {
    const std::size_t line = line_of(index);
    if (line == invalid || index[0] < first_x[line] || index[0] >= end_x[line])
      return invalid;
    return line_start[line] + (index[0] - first_x[line]);
  }



  template <int dim>
  typename ParticleLattice<dim>::Line
  ParticleLattice<dim>::line(const LatticeIndex &index) const
  {
    const std::size_t l = line_of(index);
    if (l == invalid)
      return {};
    return {static_cast<std::int64_t>(line_start[l]) - first_x[l],
            line_start[l],
            line_start[l + 1]};
  }



  template <int dim>
  typename ParticleLattice<dim>::LatticeIndex
  ParticleLattice<dim>::index(const types::global_dof_index number) const
  {
    AssertIndexRange(number, n_particles());
    const std::size_t line =
      std::upper_bound(line_start.begin(), line_start.end(), number) -
      line_start.begin() - 1;
    LatticeIndex result;
    result[0] = first_x[line] + static_cast<int>(number - line_start[line]);
    std::size_t rest = line;
    for (unsigned int d = 1; d < dim; ++d)
      {
        result[d] = static_cast<int>(rest % (n[d] + 2 * radius)) - radius;
        rest /= n[d] + 2 * radius;
      }
    return result;
  }



  template <int dim>
  Point<dim>
  ParticleLattice<dim>::position(const LatticeIndex &index) const
  {
    Point<dim> x;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] = origin[d] + (index[d] + 0.5) * spacing;
    return x;
  }



  template <int dim>
  bool
  ParticleLattice<dim>::inside(const LatticeIndex &index) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (index[d] < 0 || index[d] >= n[d])
        return false;
    return true;
  }



  template <int dim>
  types::global_dof_index
  ParticleLattice<dim>::n_inside() const
  {
    types::global_dof_index count = 1;
    for (unsigned int d = 0; d < dim; ++d)
      count *= n[d];
    return count;
  }



  template <int dim>
  types::global_dof_index
  ParticleLattice<dim>::inside_number(const LatticeIndex &index) const
  {
    Assert(inside(index), ExcInternalError());
    types::global_dof_index number = 0;
    for (int d = dim - 1; d >= 0; --d)
      number = number * n[d] + index[d];
    return number;
  }



  template <int dim>
  DofRole
  ParticleLattice<dim>::role(const LatticeIndex  &index,
                             const Geometry<dim> &geometry) const
  {
    return inside(index) ? DofRole::free :
           geometry.body.contains(position(index), geometry.tolerance()) ?
                           DofRole::control :
                           DofRole::fixed;
  }

  template class ParticleLattice<2>;
  template class ParticleLattice<3>;
} // namespace ltn

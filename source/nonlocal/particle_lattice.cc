#include <deal.II/base/exceptions.h>

#include <ltn/nonlocal/particle_lattice.h>

#include <algorithm>
#include <set>

namespace ltn
{
  template <int dim>
  std::size_t
  ParticleLattice<dim>::Intervals::find(const std::size_t l, const int x) const
  {
    return std::upper_bound(end.begin() + line_begin[l],
                            end.begin() + line_begin[l + 1],
                            x) -
           end.begin();
  }



  template <int dim>
  types::global_dof_index
  ParticleLattice<dim>::Intervals::total() const
  {
    return start.empty() ? 0 : start.back() + (end.back() - first.back());
  }



  template <int dim>
  ParticleLattice<dim>::ParticleLattice(const NonlocalRegion<dim> &region,
                                        const double               spacing,
                                        const std::vector<LatticeIndex> &reach)
    : origin(region.bounding_box().lower)
    , spacing(spacing)
    , radius(0)
  {
    for (const auto &offset : reach)
      for (unsigned int d = 0; d < dim; ++d)
        radius = std::max(radius, std::abs(offset[d]));
    const Box<dim> bounds = region.bounding_box();
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = static_cast<int>(
        std::round((bounds.upper[d] - bounds.lower[d]) / spacing));
    // Each box's cells [lo_d, hi_d) in lattice indices.
    std::vector<std::pair<LatticeIndex, LatticeIndex>> boxes;
    for (const auto &box : region.boxes())
      {
        LatticeIndex lo, hi;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lo[d] = static_cast<int>(
              std::round((box.lower[d] - origin[d]) / spacing));
            hi[d] = static_cast<int>(
              std::round((box.upper[d] - origin[d]) / spacing));
          }
        boxes.emplace_back(lo, hi);
      }

    const std::set<LatticeIndex> reached(reach.begin(), reach.end());
    const auto                   is_reached = [&](const LatticeIndex &offset) {
      return reached.count(offset) == 1 ||
             std::all_of(offset.begin(), offset.end(), [](const int o) {
               return o == 0;
             });
    };
    // Sorted, touching or overlapping intervals merged, appended as the
    // intervals of the next line.
    const auto append = [](Intervals                        &intervals,
                           std::vector<std::pair<int, int>> &line,
                           const std::size_t                 line_number) {
      std::sort(line.begin(), line.end());
      for (std::size_t k = 0; k < line.size(); ++k)
        if (k > 0 && line[k].first <= intervals.end.back() &&
            intervals.line_begin.back() < intervals.first.size())
          intervals.end.back() = std::max(intervals.end.back(), line[k].second);
        else
          {
            intervals.start.push_back(intervals.total());
            intervals.first.push_back(line[k].first);
            intervals.end.push_back(line[k].second);
            intervals.line.push_back(line_number);
          }
      intervals.line_begin.push_back(intervals.first.size());
    };

    std::size_t n_lines = 1;
    for (unsigned int d = 1; d < dim; ++d)
      n_lines *= n[d] + 2 * radius;
    runs.line_begin        = {0};
    inside_runs.line_begin = {0};
    std::vector<std::pair<int, int>> present, inside_line;
    for (std::size_t line = 0; line < n_lines; ++line)
      {
        LatticeIndex i;
        std::size_t  rest = line;
        for (unsigned int d = 1; d < dim; ++d)
          {
            i[d] = static_cast<int>(rest % (n[d] + 2 * radius)) - radius;
            rest /= n[d] + 2 * radius;
          }
        present.clear();
        inside_line.clear();
        for (const auto &[lo, hi] : boxes)
          {
            // The offset of the line from the box in the directions
            // 1..dim-1.
            LatticeIndex offset;
            bool         through_box = true;
            for (unsigned int d = 1; d < dim; ++d)
              {
                offset[d]   = i[d] - std::clamp(i[d], lo[d], hi[d] - 1);
                through_box = through_box && offset[d] == 0;
              }
            if (through_box)
              inside_line.emplace_back(lo[0], hi[0]);
            // The largest offset along x that is reached; all smaller ones
            // must be too, or the box's particles on the line would not be
            // one run.
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
            if (reach_x >= 0)
              present.emplace_back(lo[0] - reach_x, hi[0] + reach_x);
          }
        append(runs, present, line);
        append(inside_runs, inside_line, line);
      }
  }



  template <int dim>
  types::global_dof_index
  ParticleLattice<dim>::n_particles() const
  {
    return runs.total();
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
    if (line == invalid)
      return invalid;
    const std::size_t r = runs.find(line, index[0]);
    if (r == runs.line_begin[line + 1] || runs.first[r] > index[0])
      return invalid;
    return runs.start[r] + (index[0] - runs.first[r]);
  }



  template <int dim>
  typename ParticleLattice<dim>::Line
  ParticleLattice<dim>::line(const LatticeIndex &index) const
  {
    const std::size_t l = line_of(index);
    if (l == invalid)
      return {};
    const std::size_t r = runs.find(l, index[0]);
    if (r == runs.line_begin[l + 1])
      return {};
    Line result;
    result.origin = static_cast<std::int64_t>(runs.start[r]) - runs.first[r];
    result.begin  = runs.start[r];
    result.end    = runs.start[r] + (runs.end[r] - runs.first[r]);
    if (r + 1 < runs.line_begin[l + 1])
      result.next_first = runs.first[r + 1];
    return result;
  }



  template <int dim>
  typename ParticleLattice<dim>::LatticeIndex
  ParticleLattice<dim>::index(const types::global_dof_index number) const
  {
    AssertIndexRange(number, n_particles());
    const std::size_t r =
      std::upper_bound(runs.start.begin(), runs.start.end(), number) -
      runs.start.begin() - 1;
    LatticeIndex result;
    result[0]        = runs.first[r] + static_cast<int>(number - runs.start[r]);
    std::size_t rest = runs.line[r];
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
    const std::size_t line = line_of(index);
    if (line == invalid)
      return false;
    const std::size_t r = inside_runs.find(line, index[0]);
    return r < inside_runs.line_begin[line + 1] &&
           inside_runs.first[r] <= index[0];
  }



  template <int dim>
  types::global_dof_index
  ParticleLattice<dim>::n_inside() const
  {
    return inside_runs.total();
  }



  template <int dim>
  types::global_dof_index
  ParticleLattice<dim>::inside_number(const LatticeIndex &index) const
  {
    Assert(inside(index), ExcInternalError());
    const std::size_t r = inside_runs.find(line_of(index), index[0]);
    return inside_runs.start[r] + (index[0] - inside_runs.first[r]);
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

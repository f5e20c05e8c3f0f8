#include <deal.II/base/exceptions.h>

#include <ltn/problem/nonlocal_region.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ltn
{
  template <int dim>
  std::size_t
  NonlocalRegion<dim>::CellGrid::n_cells() const
  {
    std::size_t n = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n *= planes[d].size() - 1;
    return n;
  }



  template <int dim>
  std::size_t
  NonlocalRegion<dim>::CellGrid::cell(
    const std::array<unsigned int, dim> &i) const
  {
    std::size_t index = 0;
    for (int d = dim - 1; d >= 0; --d)
      index = index * (planes[d].size() - 1) + i[d];
    return index;
  }



  template <int dim>
  Box<dim>
  NonlocalRegion<dim>::CellGrid::box(
    const std::array<unsigned int, dim> &i) const
  {
    Box<dim> result;
    for (unsigned int d = 0; d < dim; ++d)
      {
        result.lower[d] = planes[d][i[d]];
        result.upper[d] = planes[d][i[d] + 1];
      }
    return result;
  }



  template <int dim>
  template <typename F>
  void
  NonlocalRegion<dim>::CellGrid::for_each_cell(const F &f) const
  {
    std::array<unsigned int, dim> i{};
    for (std::size_t c = 0; c < n_cells(); ++c)
      {
        f(i);
        for (unsigned int d = 0; d < dim; ++d)
          if (++i[d] + 1 < planes[d].size())
            break;
          else
            i[d] = 0;
      }
  }



  template <int dim>
  template <typename Flag>
  typename NonlocalRegion<dim>::CellGrid
  NonlocalRegion<dim>::make_grid(std::array<std::vector<double>, dim> planes,
                                 const double                         tolerance,
                                 const Flag                          &flag)
  {
    CellGrid grid;
    for (unsigned int d = 0; d < dim; ++d)
      {
        // Planes closer than the tolerance are one: no cell is thinner.
        std::sort(planes[d].begin(), planes[d].end());
        std::vector<double> merged;
        for (const double x : planes[d])
          if (merged.empty() || x > merged.back() + tolerance)
            merged.push_back(x);
        grid.planes[d] = merged;
      }
    grid.flag.resize(grid.n_cells());
    grid.for_each_cell([&](const std::array<unsigned int, dim> &i) {
      const Box<dim> cell = grid.box(i);
      grid.flag[grid.cell(i)] =
        flag(Point<dim>(0.5 * (cell.lower + cell.upper)));
    });
    return grid;
  }



  template <int dim>
  NonlocalRegion<dim>::NonlocalRegion(const Box<dim>              &body,
                                      const std::vector<Box<dim>> &boxes,
                                      const double overlap_width,
                                      const double tolerance)
    : body(body)
    , region_boxes(boxes)
    , overlap_width(overlap_width)
    , tolerance(tolerance)
  {
    // The body's grid: its faces and the boxes' faces inside it.
    std::array<std::vector<double>, dim> planes;
    const auto add_plane = [&](const unsigned int d, const double x) {
      if (x >= body.lower[d] - tolerance && x <= body.upper[d] + tolerance)
        planes[d].push_back(std::clamp(x, body.lower[d], body.upper[d]));
    };
    for (unsigned int d = 0; d < dim; ++d)
      {
        add_plane(d, body.lower[d]);
        add_plane(d, body.upper[d]);
        for (const auto &box : boxes)
          {
            add_plane(d, box.lower[d]);
            add_plane(d, box.upper[d]);
          }
      }
    region_cells = make_grid(planes, tolerance, [&](const Point<dim> &centre) {
      return std::any_of(boxes.begin(), boxes.end(), [&](const auto &box) {
        return box.contains(centre);
      });
    });

    // S is bounded by the planes of D \ U moved by delta (its max-norm
    // neighbourhood), so it is a union of the cells of the grid on those
    // planes too; no cell is cut by its boundary, and the depth at a
    // cell's centre decides.
    for (unsigned int d = 0; d < dim; ++d)
      for (const double x : region_cells.planes[d])
        {
          add_plane(d, x - overlap_width);
          add_plane(d, x + overlap_width);
        }
    shrunk_cells = make_grid(planes, tolerance, [&](const Point<dim> &centre) {
      return contains(centre, 0) &&
             depth(centre, 2 * overlap_width) >= overlap_width;
    });
  }



  template <int dim>
  const std::vector<Box<dim>> &
  NonlocalRegion<dim>::boxes() const
  {
    return region_boxes;
  }



  template <int dim>
  Box<dim>
  NonlocalRegion<dim>::bounding_box() const
  {
    AssertThrow(!region_boxes.empty(), ExcInternalError());
    Box<dim> result = region_boxes.front();
    for (const auto &box : region_boxes)
      for (unsigned int d = 0; d < dim; ++d)
        {
          result.lower[d] = std::min(result.lower[d], box.lower[d]);
          result.upper[d] = std::max(result.upper[d], box.upper[d]);
        }
    return result;
  }



  template <int dim>
  bool
  NonlocalRegion<dim>::contains(const Point<dim> &p,
                                const double      tolerance) const
  {
    return std::any_of(region_boxes.begin(),
                       region_boxes.end(),
                       [&](const auto &box) {
                         return box.contains(p, tolerance);
                       });
  }



  template <int dim>
  bool
  NonlocalRegion<dim>::contains_strictly(const Point<dim> &p,
                                         const double      tolerance) const
  {
    for (const auto &box : region_boxes)
      if (box.contains_strictly(p, tolerance))
        return true;
    // On a face where boxes touch, or off the region.
    if (region_boxes.size() == 1 || !contains(p, 0))
      return false;
    double to_outside = depth(p, 2 * tolerance + this->tolerance);
    for (unsigned int d = 0; d < dim; ++d)
      to_outside =
        std::min({to_outside, p[d] - body.lower[d], body.upper[d] - p[d]});
    return to_outside > tolerance;
  }



  template <int dim>
  double
  NonlocalRegion<dim>::distance(const Point<dim> &p) const
  {
    double result = std::numeric_limits<double>::infinity();
    for (const auto &box : region_boxes)
      result = std::min(result, box.distance(p));
    return result;
  }



  template <int dim>
  double
  NonlocalRegion<dim>::depth(const Point<dim> &p, const double cap) const
  {
    // The cells of D \ U within cap of p in the max-norm: per axis, those
    // between the planes around [p - cap, p + cap].
    std::array<unsigned int, dim> first, last;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const auto &planes = region_cells.planes[d];
        const auto  below =
          std::upper_bound(planes.begin(), planes.end(), p[d] - cap);
        const auto above =
          std::lower_bound(planes.begin(), planes.end(), p[d] + cap);
        first[d] = below == planes.begin() ? 0 : below - planes.begin() - 1;
        last[d] =
          std::min<unsigned int>(above - planes.begin(), planes.size() - 1);
        if (last[d] <= first[d])
          return cap;
      }
    double                        result = cap;
    std::array<unsigned int, dim> i      = first;
    while (true)
      {
        if (!region_cells.flag[region_cells.cell(i)])
          result = std::min(result, region_cells.box(i).max_norm_distance(p));
        unsigned int d = 0;
        for (; d < dim; ++d)
          if (++i[d] < last[d])
            break;
          else
            i[d] = first[d];
        if (d == dim)
          return result;
      }
  }



  template <int dim>
  bool
  NonlocalRegion<dim>::in_local_part(const Point<dim> &p) const
  {
    return depth(p, overlap_width + 2 * tolerance) <= overlap_width + tolerance;
  }



  template <int dim>
  bool
  NonlocalRegion<dim>::touches_body_face(const unsigned int face) const
  {
    const unsigned int d     = face / 2;
    const double       plane = face % 2 == 0 ? body.lower[d] : body.upper[d];
    return std::any_of(
      region_boxes.begin(), region_boxes.end(), [&](const auto &box) {
        return std::abs((face % 2 == 0 ? box.lower[d] : box.upper[d]) -
                        plane) <= tolerance;
      });
  }



  template <int dim>
  bool
  NonlocalRegion<dim>::covers_body() const
  {
    return std::all_of(region_cells.flag.begin(),
                       region_cells.flag.end(),
                       [](const bool in_region) { return in_region; });
  }



  template <int dim>
  bool
  NonlocalRegion<dim>::face_is_exposed(const Box<dim>    &box,
                                       const unsigned int face) const
  {
    const unsigned int d     = face / 2;
    const double       plane = face % 2 == 0 ? box.lower[d] : box.upper[d];
    const auto        &axis  = region_cells.planes[d];
    // The cells of the grid's layer beyond the face that face it.
    const auto at =
      std::lower_bound(axis.begin(), axis.end(), plane - tolerance);
    if (at == axis.end() || std::abs(*at - plane) > tolerance)
      return false;
    const std::size_t plane_index = at - axis.begin();
    if ((face % 2 == 0 && plane_index == 0) ||
        (face % 2 == 1 && plane_index + 1 == axis.size()))
      return false;
    const unsigned int layer   = face % 2 == 0 ? plane_index - 1 : plane_index;
    bool               exposed = false;
    region_cells.for_each_cell([&](const std::array<unsigned int, dim> &i) {
      if (i[d] != layer || region_cells.flag[region_cells.cell(i)])
        return;
      const Box<dim> cell   = region_cells.box(i);
      bool           facing = true;
      for (unsigned int e = 0; e < dim; ++e)
        if (e != d)
          facing = facing && cell.lower[e] < box.upper[e] - tolerance &&
                   box.lower[e] < cell.upper[e] - tolerance;
      exposed = exposed || facing;
    });
    return exposed;
  }



  template <int dim>
  bool
  NonlocalRegion<dim>::every_piece_has_shrunk_part() const
  {
    // Label the region's cells by pieces connected through faces.
    const std::size_t unlabelled = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> label(region_cells.n_cells(), unlabelled);
    std::vector<std::array<unsigned int, dim>> cells(region_cells.n_cells());
    region_cells.for_each_cell([&](const std::array<unsigned int, dim> &i) {
      cells[region_cells.cell(i)] = i;
    });
    std::size_t n_pieces = 0;
    for (std::size_t start = 0; start < cells.size(); ++start)
      if (region_cells.flag[start] && label[start] == unlabelled)
        {
          std::vector<std::size_t> stack = {start};
          label[start]                   = n_pieces;
          while (!stack.empty())
            {
              const auto i = cells[stack.back()];
              stack.pop_back();
              for (unsigned int d = 0; d < dim; ++d)
                for (const int step : {-1, 1})
                  {
                    auto j = i;
                    if ((step < 0 && j[d] == 0) ||
                        (step > 0 && j[d] + 2 >= region_cells.planes[d].size()))
                      continue;
                    j[d] += step;
                    const std::size_t c = region_cells.cell(j);
                    if (region_cells.flag[c] && label[c] == unlabelled)
                      {
                        label[c] = n_pieces;
                        stack.push_back(c);
                      }
                  }
            }
          ++n_pieces;
        }

    // Each cell of S lies in one cell of the region's grid.
    std::vector<bool> has_shrunk_part(n_pieces, false);
    shrunk_cells.for_each_cell([&](const std::array<unsigned int, dim> &i) {
      if (!shrunk_cells.flag[shrunk_cells.cell(i)])
        return;
      const Box<dim>                cell = shrunk_cells.box(i);
      std::array<unsigned int, dim> j;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const auto &planes = region_cells.planes[d];
          j[d]               = std::upper_bound(planes.begin(),
                                  planes.end(),
                                  0.5 * (cell.lower[d] + cell.upper[d])) -
                 planes.begin() - 1;
        }
      const std::size_t piece = label[region_cells.cell(j)];
      AssertThrow(piece != unlabelled, ExcInternalError());
      has_shrunk_part[piece] = true;
    });
    return std::all_of(has_shrunk_part.begin(),
                       has_shrunk_part.end(),
                       [](const bool has) { return has; });
  }



  template <int dim>
  bool
  NonlocalRegion<dim>::shrunk_region_contains(const Box<dim> &box) const
  {
    // The box cut by the grid's planes into pieces, each inside one cell
    // or on a plane between cells; the closure of S holds the box if it
    // holds a point of each piece's relative interior (S is a union of
    // closed cells, so membership is the same all over such an interior).
    std::array<std::vector<double>, dim> points;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::vector<double> cuts = {box.lower[d]};
        for (const double x : shrunk_cells.planes[d])
          if (x > box.lower[d] + tolerance && x < box.upper[d] - tolerance)
            cuts.push_back(x);
        cuts.push_back(std::max(box.upper[d], box.lower[d]));
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
          points[d].push_back(0.5 * (cuts[k] + cuts[k + 1]));
      }
    std::array<std::size_t, dim> k{};
    while (true)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = points[d][k[d]];
        if (!contains(p, tolerance) ||
            depth(p, 2 * overlap_width) < overlap_width - tolerance)
          return false;
        unsigned int d = 0;
        for (; d < dim; ++d)
          if (++k[d] < points[d].size())
            break;
          else
            k[d] = 0;
        if (d == dim)
          return true;
      }
  }



  template <int dim>
  std::vector<double>
  NonlocalRegion<dim>::shrunk_face_coordinates(const unsigned int d) const
  {
    std::vector<double> result;
    shrunk_cells.for_each_cell([&](const std::array<unsigned int, dim> &i) {
      if (i[d] + 2 >= shrunk_cells.planes[d].size())
        return;
      auto next = i;
      ++next[d];
      if (shrunk_cells.flag[shrunk_cells.cell(i)] !=
          shrunk_cells.flag[shrunk_cells.cell(next)])
        result.push_back(shrunk_cells.planes[d][next[d]]);
    });
    // Faces of S on the body's faces.
    shrunk_cells.for_each_cell([&](const std::array<unsigned int, dim> &i) {
      if (shrunk_cells.flag[shrunk_cells.cell(i)])
        {
          if (i[d] == 0)
            result.push_back(shrunk_cells.planes[d].front());
          if (i[d] + 2 == shrunk_cells.planes[d].size())
            result.push_back(shrunk_cells.planes[d].back());
        }
    });
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }



  template <int dim>
  bool
  NonlocalRegion<dim>::shrunk_region_crosses(const unsigned int d,
                                             const double       plane) const
  {
    // Through a cell of S, or along a plane of the grid between two.
    const auto &planes  = shrunk_cells.planes[d];
    bool        crosses = false;
    shrunk_cells.for_each_cell([&](const std::array<unsigned int, dim> &i) {
      if (!shrunk_cells.flag[shrunk_cells.cell(i)])
        return;
      const bool through = planes[i[d]] < plane - tolerance &&
                           planes[i[d] + 1] > plane + tolerance;
      bool along = false;
      if (std::abs(planes[i[d] + 1] - plane) <= tolerance &&
          i[d] + 2 < planes.size())
        {
          auto next = i;
          ++next[d];
          along = shrunk_cells.flag[shrunk_cells.cell(next)];
        }
      crosses = crosses || through || along;
    });
    return crosses;
  }



  template <int dim>
  std::vector<std::pair<double, double>>
  NonlocalRegion<dim>::shrunk_extent(const unsigned int d) const
  {
    const auto       &planes = shrunk_cells.planes[d];
    std::vector<bool> covered(planes.size() - 1, false);
    shrunk_cells.for_each_cell([&](const std::array<unsigned int, dim> &i) {
      if (shrunk_cells.flag[shrunk_cells.cell(i)])
        covered[i[d]] = true;
    });
    std::vector<std::pair<double, double>> result;
    for (std::size_t k = 0; k < covered.size(); ++k)
      if (covered[k])
        {
          if (!result.empty() && result.back().second == planes[k])
            result.back().second = planes[k + 1];
          else
            result.emplace_back(planes[k], planes[k + 1]);
        }
    return result;
  }

  template class NonlocalRegion<1>;
  template class NonlocalRegion<2>;
  template class NonlocalRegion<3>;
} // namespace ltn

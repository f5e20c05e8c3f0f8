#include <deal.II/base/tensor.h>

#include <ltn/base/input_error.h>
#include <ltn/problem/crack.h>

#include <algorithm>
#include <cmath>

namespace ltn
{
  namespace
  {
    template <int dim>
    Tensor<1, dim>
    edge(const Crack<dim> &crack, const unsigned int k)
    {
      return crack.corners[k + 1] - crack.corners[0];
    }

    /** A normal (not normalized) of the crack's line or plane. */
    template <int dim>
    Tensor<1, dim>
    raw_normal(const Crack<dim> &crack)
    {
      if constexpr (dim == 2)
        return cross_product_2d(edge(crack, 0));
      else
        return cross_product_3d(edge(crack, 0), edge(crack, 1));
    }
  } // namespace



  template <int dim>
  Tensor<1, dim>
  Crack<dim>::normal() const
  {
    const Tensor<1, dim> n = raw_normal(*this);
    return n / n.norm();
  }



  template <int dim>
  double
  Crack<dim>::signed_distance(const Point<dim> &p) const
  {
    return normal() * (p - corners[0]);
  }



  template <int dim>
  std::array<double, dim - 1>
  Crack<dim>::edge_coordinates(const Point<dim> &p) const
  {
    // Solve the Gram system of the edges for the in-plane coordinates.
    const Tensor<1, dim>        r = p - corners[0];
    std::array<double, dim - 1> result;
    if constexpr (dim == 2)
      result[0] = (r * edge(*this, 0)) / edge(*this, 0).norm_square();
    else
      {
        const auto   e0 = edge(*this, 0), e1 = edge(*this, 1);
        const double g00 = e0 * e0, g01 = e0 * e1, g11 = e1 * e1;
        const double b0 = r * e0, b1 = r * e1;
        const double det = g00 * g11 - g01 * g01;
        result[0]        = (g11 * b0 - g01 * b1) / det;
        result[1]        = (g00 * b1 - g01 * b0) / det;
      }
    return result;
  }



  template <int dim>
  bool
  Crack<dim>::cuts(const Point<dim> &x,
                   const Point<dim> &y,
                   const double      tolerance) const
  {
    // Order the end points so that the test is symmetric to the last bit.
    bool swap = false;
    for (unsigned int d = 0; d < dim; ++d)
      if (x[d] != y[d])
        {
          swap = y[d] < x[d];
          break;
        }
    const Point<dim> &a = swap ? y : x;
    const Point<dim> &b = swap ? x : y;

    const Tensor<1, dim> n  = raw_normal(*this);
    const double         sa = n * (a - corners[0]), sb = n * (b - corners[0]);
    if (!((sa > 0 && sb < 0) || (sa < 0 && sb > 0)))
      return false;
    const Point<dim> crossing = a + (sa / (sa - sb)) * (b - a);
    const double     length =
      (dim == 2) ? edge(*this, 0).norm() : std::sqrt(measure());
    const double slack = tolerance / length;
    for (const double s : edge_coordinates(crossing))
      if (s < -slack || s > 1 + slack)
        return false;
    return true;
  }



  template <int dim>
  Box<dim>
  Crack<dim>::bounding_box() const
  {
    Box<dim> box{corners[0], corners[0]};
    // The corners and, in 3D, the fourth corner of the parallelogram.
    std::vector<Point<dim>> points(corners.begin(), corners.end());
    if constexpr (dim == 3)
      points.push_back(corners[1] + edge(*this, 1));
    for (const auto &p : points)
      for (unsigned int d = 0; d < dim; ++d)
        {
          box.lower[d] = std::min(box.lower[d], p[d]);
          box.upper[d] = std::max(box.upper[d], p[d]);
        }
    return box;
  }



  template <int dim>
  double
  Crack<dim>::measure() const
  {
    return raw_normal(*this).norm();
  }



  template <int dim>
  void
  CrackSet<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Cracks");
    {
      prm.declare_entry(
        "Corners",
        "",
        Patterns::Anything(),
        "Elasticity scenes: the cracks of the nonlocal region, separated by "
        "';'. A 2D crack is a segment given by its two end points "
        "`x0, y0, x1, y1`; a 3D crack a planar parallelogram given by three "
        "corners `x0, y0, z0, x1, y1, z1, x2, y2, z2` (the fourth is "
        "corner1 + corner2 - corner0; perpendicular edges make a rectangle). "
        "Every bond that crosses a crack is removed. Each crack must lie in "
        "the nonlocal region, and no particle may lie on one: put cracks on "
        "faces of the particle lattice (e.g. at multiples of the mesh size "
        "from the region's corner). Empty: no crack.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  CrackSet<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Cracks");
    const std::string text = prm.get("Corners");
    prm.leave_subsection();
    cracks.clear();
    for (const std::string &item : Utilities::split_string_list(text, ';'))
      {
        if (item.empty())
          continue;
        std::vector<double> values;
        bool                numbers = true;
        for (const std::string &entry : Utilities::split_string_list(item))
          {
            try
              {
                std::size_t end = 0;
                values.push_back(std::stod(entry, &end));
                numbers = numbers && end == entry.size();
              }
            catch (const std::exception &)
              {
                numbers = false;
              }
          }
        check_input(numbers && values.size() == dim * dim,
                    "Cracks/Corners",
                    item,
                    "each crack as " + std::to_string(dim * dim) +
                      " comma-separated numbers: " +
                      (dim == 2 ? "the end points x0, y0, x1, y1" :
                                  "three corners x0, y0, z0, x1, y1, z1, x2, "
                                  "y2, z2") +
                      "; cracks separated by ';'");
        Crack<dim> crack;
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            crack.corners[k][d] = values[k * dim + d];
        cracks.push_back(crack);
      }
  }



  template <int dim>
  void
  CrackSet<dim>::validate(const Geometry<dim>       &geometry,
                          const std::vector<double> &spacings) const
  {
    const double tol = geometry.tolerance();
    for (const Crack<dim> &crack : cracks)
      {
        const Box<dim> box  = crack.bounding_box();
        const double   size = box.lower.distance(box.upper);
        check_input(crack.measure() > tol * size,
                    "Cracks/Corners",
                    "a crack with corners at " +
                      to_string(crack.corners[0][0]) + ", ...",
                    std::string("a crack of positive ") +
                      (dim == 2 ? "length" : "area (corners not in a line)"));
        const std::string extent =
          "a crack reaching from (" + to_string(box.lower[0]) + ", " +
          to_string(box.lower[1]) + ", ...) to (" + to_string(box.upper[0]) +
          ", " + to_string(box.upper[1]) + ", ...)";
        // The crack's corners (the fourth of a parallelogram too) in
        // Omega_n; the test against S below sees the rest of the crack.
        const NonlocalRegion<dim> &region = geometry.nonlocal_region();
        std::vector<Point<dim>>    ends(crack.corners.begin(),
                                     crack.corners.end());
        if (dim == 3)
          ends.push_back(crack.corners[1] +
                         (crack.corners[dim - 1] - crack.corners[0]));
        check_input(geometry.has_nonlocal_model() &&
                      std::all_of(ends.begin(),
                                  ends.end(),
                                  [&](const Point<dim> &p) {
                                    return region.contains(p, tol);
                                  }),
                    "Cracks/Corners",
                    extent,
                    "cracks inside the nonlocal region (Geometry/Nonlocal "
                    "regions, or its lower/upper corner): the local model "
                    "has none");
        // The local model covers the overlap, uncracked: a crack there
        // would have the coupling match a cracked field to an uncracked one.
        std::string within = "Geometry/Overlap width on its faces inside the "
                             "body";
        if (region.boxes().size() == 1)
          {
            // One box: S is a box, which the message names.
            const auto x = region.shrunk_extent(0), y = region.shrunk_extent(1);
            if (x.size() == 1 && y.size() == 1)
              within += ", from (" + to_string(x[0].first) + ", " +
                        to_string(y[0].first) + ", ...) to (" +
                        to_string(x[0].second) + ", " + to_string(y[0].second) +
                        ", ...)";
          }
        // An axis-parallel crack is its bounding box: exact. Another is
        // tested at points of a grid on it finer than a quarter of the
        // finest particle spacing (its box may reach out of an L's S).
        bool axis_parallel = false;
        for (unsigned int d = 0; d < dim; ++d)
          axis_parallel = axis_parallel || box.upper[d] - box.lower[d] <= tol;
        bool in_shrunk_region = true;
        if (geometry.has_local_model() && axis_parallel)
          in_shrunk_region = region.shrunk_region_contains(box);
        else if (geometry.has_local_model())
          {
            AssertThrow(!spacings.empty(), ExcInternalError());
            const double finest =
              *std::min_element(spacings.begin(), spacings.end());
            std::array<unsigned int, dim - 1> n;
            for (unsigned int e = 0; e + 1 < dim; ++e)
              n[e] = static_cast<unsigned int>(
                std::ceil(crack.corners[e + 1].distance(crack.corners[0]) /
                          (finest / 4)));
            for (unsigned int i = 0; i <= n[0] && in_shrunk_region; ++i)
              for (unsigned int j = 0;
                   j <= (dim == 3 ? n[dim - 2] : 0u) && in_shrunk_region;
                   ++j)
                {
                  Point<dim> p =
                    crack.corners[0] + (crack.corners[1] - crack.corners[0]) *
                                         (static_cast<double>(i) / n[0]);
                  if (dim == 3)
                    p += (crack.corners[dim - 1] - crack.corners[0]) *
                         (static_cast<double>(j) / n[dim - 2]);
                  in_shrunk_region = region.shrunk_region_contains({p, p});
                }
          }
        check_input(in_shrunk_region,
                    "Cracks/Corners",
                    extent,
                    "cracks outside the overlap, which the local model covers "
                    "uncracked: within the nonlocal region shrunk by " +
                      within);
        // The lattice points x = lower + (i + 1/2) h near the crack.
        for (const double h : spacings)
          {
            const Point<dim>     origin = region.bounding_box().lower;
            std::array<int, dim> lo, hi, i;
            for (unsigned int d = 0; d < dim; ++d)
              {
                lo[d] = std::floor((box.lower[d] - origin[d]) / h - 1);
                hi[d] = std::ceil((box.upper[d] - origin[d]) / h);
              }
            i = lo;
            while (true)
              {
                Point<dim> x;
                for (unsigned int d = 0; d < dim; ++d)
                  x[d] = origin[d] + (i[d] + 0.5) * h;
                bool on_crack = std::abs(crack.signed_distance(x)) <= 1e-6 * h;
                for (const double s : crack.edge_coordinates(x))
                  on_crack = on_crack && s >= 0 && s <= 1;
                check_input(!on_crack,
                            "Cracks/Corners",
                            "a crack through the particle at (" +
                              to_string(x[0]) + ", " + to_string(x[1]) +
                              ", ...)",
                            "cracks off the particle lattice (spacing " +
                              to_string(h) +
                              "), e.g. on the faces between particles");
                unsigned int d = 0;
                for (; d < dim; ++d)
                  {
                    if (++i[d] <= hi[d])
                      break;
                    i[d] = lo[d];
                  }
                if (d == dim)
                  break;
              }
          }
      }
  }

  template struct Crack<2>;
  template struct Crack<3>;
  template struct CrackSet<2>;
  template struct CrackSet<3>;
} // namespace ltn

// Nonlocal regions made of boxes (doc/model_adaptivity.md, 'Regions made of
// blocks'): one box gives the sets of the single-box layout; an L-shape has
// max-norm bands at its concave corner and none where its boxes touch; the
// collar and the pieces of a union; the checks of a list of boxes.

#include <ltn/base/input_error.h>
#include <ltn/problem/geometry.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "box_layout.h"

using namespace ltn;

namespace
{
  /**
   * The local region of the single-box layout as it was defined before
   * regions were made of boxes: the body minus the box shrunk by the
   * overlap width on its faces inside the body, open on those faces.
   */
  template <int dim>
  bool
  single_box_local_region(const Box<dim>   &body,
                          const Box<dim>   &region,
                          const double      width,
                          const double      tol,
                          const Point<dim> &p)
  {
    Box<dim> removed = region;
    for (unsigned int d = 0; d < dim; ++d)
      {
        if (std::abs(region.lower[d] - body.lower[d]) > tol)
          removed.lower[d] += width;
        else
          removed.lower[d] -= 10;
        if (std::abs(region.upper[d] - body.upper[d]) > tol)
          removed.upper[d] -= width;
        else
          removed.upper[d] += 10;
      }
    return body.contains(p, tol) && !removed.contains_strictly(p, tol);
  }

  template <int dim>
  void
  check_single_box(const Box<dim> &region, const double width)
  {
    Geometry<dim> g;
    for (unsigned int d = 0; d < dim; ++d)
      g.body.upper[d] = 2;
    g.overlap_width = width;
    g.set_nonlocal_boxes({region});
    const double tol = g.tolerance();
    // Points on a grid of 1/16, faces and tolerance offsets included.
    unsigned int n_points = 0;
    for (int i = 0; i <= 32; ++i)
      for (int j = 0; j <= 32; ++j)
        for (int k = 0; k <= (dim == 3 ? 32 : 0); ++k)
          for (const double shift : {0., 0.5 * tol, -0.5 * tol, 3 * tol})
            {
              Point<dim> p;
              p[0] = i / 16. + shift;
              p[1] = j / 16. - shift;
              if (dim == 3)
                p[dim - 1] = k / 16. + shift;
              INFO("point " << p);
              CHECK(g.in_local_region(p) ==
                    single_box_local_region(g.body, region, width, tol, p));
              CHECK(g.nonlocal_region().contains_strictly(p, tol) ==
                    region.contains_strictly(p, tol));
              ++n_points;
            }
    CHECK(n_points > 1000);
  }
} // namespace



TEST_CASE("one box: the single-box layout's sets", "[geometry]")
{
  check_single_box<2>({Point<2>(0.5, 0.75), Point<2>(1.5, 1.25)}, 0.125);
  check_single_box<2>({Point<2>(0, 0.5), Point<2>(1, 2)}, 0.25);
  check_single_box<3>({Point<3>(0.5, 0.5, 0), Point<3>(1.5, 1.25, 2)}, 0.25);
}



TEST_CASE("L-shape: max-norm band at the concave corner, none where boxes "
          "touch",
          "[geometry]")
{
  const Geometry<2>        g = l_shape_layout();
  const NonlocalRegion<2> &u = g.nonlocal_region();

  // The depth is the max-norm distance to the body outside the region.
  CHECK(u.depth(Point<2>(0.9, 0.9), 1) == Approx(0.1));
  CHECK(u.depth(Point<2>(0.85, 0.85), 1) == Approx(0.15));
  CHECK(u.depth(Point<2>(0.75, 1), 1) == Approx(0.25));
  CHECK(u.depth(Point<2>(1.2, 1.2), 1) == 0);
  // At the concave corner the band is a square: (0.9, 0.9) is 0.141 from
  // it in the Euclidean norm, more than the width, and in the band.
  CHECK(g.in_local_region(Point<2>(0.9, 0.9)));
  CHECK_FALSE(g.in_local_region(Point<2>(0.85, 0.85)));
  // No band on the face where the boxes touch.
  CHECK_FALSE(g.in_local_region(Point<2>(0.75, 1)));
  CHECK(u.contains_strictly(Point<2>(0.75, 1), g.tolerance()));
  CHECK_FALSE(u.contains_strictly(Point<2>(1.25, 1), g.tolerance()));

  // The collar is the union's: at the concave corner, outside both boxes.
  const double range = 0.1;
  CHECK(g.nonlocal_region_of(Point<2>(1.05, 1.05), range) ==
        Region::control_collar);
  CHECK(g.nonlocal_region_of(Point<2>(0.75, 1.05), range) == Region::nonlocal);
  CHECK(g.nonlocal_region_of(Point<2>(0.95, 1.05), range) == Region::overlap);
  CHECK(g.in_overlap(Point<2>(1.05, 1.05), range));
  CHECK_FALSE(g.in_overlap(Point<2>(1.2, 1.2), range));

  // S: the L shrunk by 0.125 against the rest of the body.
  const std::vector<double> x_faces = {0.625, 0.875, 1.375};
  const std::vector<double> y_faces = {0.625, 0.875, 1.375};
  CHECK(u.shrunk_face_coordinates(0) == x_faces);
  CHECK(u.shrunk_face_coordinates(1) == y_faces);
  CHECK(u.shrunk_region_contains({Point<2>(0.625, 0.7), Point<2>(1.375, 0.7)}));
  CHECK(
    u.shrunk_region_contains({Point<2>(0.75, 0.625), Point<2>(0.75, 1.375)}));
  CHECK_FALSE(
    u.shrunk_region_contains({Point<2>(0.75, 0.7), Point<2>(0.95, 0.95)}));
  CHECK(u.every_piece_has_shrunk_part());
  CHECK_FALSE(u.covers_body());
  // Planes through S (a section plane there would miss the hole's force):
  // through its cells, and along the grid plane y = 0.875 between its
  // arms' cells; not along its faces nor outside it.
  CHECK(u.shrunk_region_crosses(0, 1));
  CHECK(u.shrunk_region_crosses(1, 0.875));
  CHECK_FALSE(u.shrunk_region_crosses(0, 1.375));
  CHECK_FALSE(u.shrunk_region_crosses(1, 1.5));

  // Faces with body outside the region beyond them: all but the glued
  // parts; the upper face of the first box is exposed right of x = 1.
  const auto &boxes = u.boxes();
  CHECK(u.face_is_exposed(boxes[0], 3));
  CHECK_FALSE(u.face_is_exposed(boxes[1], 2));
  CHECK(u.face_is_exposed(boxes[1], 1));
}



TEST_CASE("pieces of a union: each needs a part of its own", "[geometry]")
{
  Geometry<2> g;
  g.body.upper    = Point<2>(4, 2);
  g.overlap_width = 0.25;
  // Two boxes apart; the second all band (0.5 wide, bands on both sides).
  g.set_nonlocal_boxes({{Point<2>(0.5, 0.5), Point<2>(1.5, 1.5)},
                        {Point<2>(2.5, 0.5), Point<2>(3, 1.5)}});
  CHECK_FALSE(g.nonlocal_region().every_piece_has_shrunk_part());
  g.set_nonlocal_boxes({{Point<2>(0.5, 0.5), Point<2>(1.5, 1.5)},
                        {Point<2>(2.5, 0.5), Point<2>(3.25, 1.5)}});
  CHECK(g.nonlocal_region().every_piece_has_shrunk_part());
  // The projections of S onto the axes: two intervals along x.
  const auto x = g.nonlocal_region().shrunk_extent(0);
  REQUIRE(x.size() == 2);
  CHECK(x[0].first == Approx(0.75));
  CHECK(x[1].second == Approx(3));
  // The same second box glued to the first along x = 1.5 by a third.
  g.set_nonlocal_boxes({{Point<2>(0.5, 0.5), Point<2>(1.5, 1.5)},
                        {Point<2>(1.5, 0.5), Point<2>(2.5, 1)},
                        {Point<2>(2.5, 0.5), Point<2>(3, 1.5)}});
  CHECK(g.nonlocal_region().every_piece_has_shrunk_part());
}



TEST_CASE("checks of a list of boxes", "[geometry]")
{
  // A parse error leaves the handler in its subsection: a new one each time.
  std::string corners  = "0, 0";
  const auto  error_of = [&](const std::string &boxes,
                            const double       h     = 0.125,
                            const double       range = 0.25) -> std::string {
    ParameterHandler prm;
    Geometry<2>::declare_parameters(prm);
    prm.enter_subsection("Geometry");
    prm.set("Nonlocal region lower corner", corners);
    prm.set("Nonlocal region upper corner", corners);
    prm.set("Body lower corner", "0, 0");
    prm.set("Body upper corner", "4, 2");
    prm.set("Overlap width", "0.25");
    prm.set("Nonlocal regions", boxes);
    prm.leave_subsection();
    try
      {
        Geometry<2> g;
        g.parse_parameters(prm);
        g.validate(h, range, range);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  };
  CHECK(error_of("1,0.5,2,1.5; 2,0.5,3,1") == "");
  CHECK_THAT(error_of("1,0.5,2"),
             Catch::Contains("Geometry/Nonlocal regions") &&
               Catch::Contains("4 comma-separated numbers"));
  CHECK_THAT(error_of("1,0.5,2,x"), Catch::Contains("boxes of numbers"));
  CHECK_THAT(error_of("2,0.5,1,1.5"), Catch::Contains("upper corner above"));
  CHECK_THAT(error_of("1,0.5,2,1.5; 3,0.5,5,1"),
             Catch::Contains("inside the body"));
  CHECK_THAT(error_of("1,0.5,2,1.5; 1.5,0.5,3,1"),
             Catch::Contains("interiors do not overlap"));
  CHECK_THAT(error_of("1,0.5,2,1.5; 2,0.5,3,0.625"),
             Catch::Contains("at least as thick"));
  CHECK_THAT(error_of("1,0.5,2,1.5; 2.125,0.5,3,1.25"),
             Catch::Contains("face each other"));
  CHECK_THAT(error_of("1,0.5,2,1.5; 2,0.5,3,1", 0.2),
             Catch::Contains("Discretization/Mesh size"));
  CHECK_THAT(error_of("1,0.5,2,1.5; 2,0.5,3,1", 0.125, 0.75),
             Catch::Contains("Nonlocal model/Horizon"));
  CHECK_THAT(error_of("0,0,4,1; 0,1,4,2"), Catch::Contains("whole body"));
  // The list replaces the corners.
  corners = "5, 5";
  CHECK(error_of("1,0.5,2,1.5") == "");
}

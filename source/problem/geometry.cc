#include <ltn/base/input_error.h>
#include <ltn/problem/geometry.h>

#include <cmath>
#include <sstream>

namespace ltn
{
  template <int dim>
  bool
  Box<dim>::contains(const Point<dim> &p, const double tolerance) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (p[d] < lower[d] - tolerance || p[d] > upper[d] + tolerance)
        return false;
    return true;
  }



  template <int dim>
  bool
  Box<dim>::contains_strictly(const Point<dim> &p, const double tolerance) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (p[d] <= lower[d] + tolerance || p[d] >= upper[d] - tolerance)
        return false;
    return true;
  }



  template <int dim>
  double
  Box<dim>::distance(const Point<dim> &p) const
  {
    double squared = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double outside = std::max({lower[d] - p[d], p[d] - upper[d], 0.});
        squared += outside * outside;
      }
    return std::sqrt(squared);
  }



  namespace
  {
    template <int dim>
    Point<dim>
    parse_point(const ParameterHandler &prm,
                const std::string      &name,
                const std::string      &section)
    {
      const std::string         text = prm.get(name);
      const std::vector<double> values =
        Utilities::string_to_double(Utilities::split_string_list(text));
      check_input(values.size() == dim,
                  section + "/" + name,
                  text,
                  "a point of " + std::to_string(dim) +
                    " comma-separated coordinates (the scene's Dimension)");
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = values[d];
      return p;
    }

    std::string
    point_to_string(const double *coordinates, const unsigned int dim)
    {
      std::string s;
      for (unsigned int d = 0; d < dim; ++d)
        s += (d ? ", " : "") + to_string(coordinates[d]);
      return s;
    }

    template <int dim>
    std::string
    box_to_string(const Box<dim> &box)
    {
      std::string s;
      for (unsigned int d = 0; d < dim; ++d)
        s += (d ? " x " : "") + std::string("[") + to_string(box.lower[d]) +
             ", " + to_string(box.upper[d]) + "]";
      return s;
    }

    bool
    is_multiple(const double length, const double h)
    {
      const double n = length / h;
      return std::abs(n - std::round(n)) < 1e-8 * std::max(1., n);
    }
  } // namespace



  template <int dim>
  void
  Geometry<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Body lower corner",
                        "0",
                        Patterns::List(Patterns::Double(), 1, 3),
                        "Lower corner of the body D, a box (one coordinate "
                        "per dimension, comma-separated; length units).");
      prm.declare_entry("Body upper corner",
                        "1.75",
                        Patterns::List(Patterns::Double(), 1, 3),
                        "Upper corner of the body D.");
      prm.declare_entry("Nonlocal region lower corner",
                        "0",
                        Patterns::List(Patterns::Double(), 1, 3),
                        "Lower corner of the nonlocal region Omega_n, a box "
                        "inside the body. Its faces on the body's boundary "
                        "get a physical collar (volume constraint), its faces "
                        "inside the body a control collar.");
      prm.declare_entry("Nonlocal region upper corner",
                        "1",
                        Patterns::List(Patterns::Double(), 1, 3),
                        "Upper corner of the nonlocal region Omega_n.");
      prm.declare_entry("Models",
                        "coupled",
                        Patterns::Selection("coupled|nonlocal only|local only"),
                        "`coupled`: the nonlocal model on the nonlocal region, "
                        "the local model on the rest, coupled on the overlap. "
                        "`nonlocal only` / `local only`: one model on the "
                        "whole body (the nonlocal region's corners and the "
                        "overlap width are then ignored), to compare a "
                        "coupled result with.");
      prm.declare_entry("Overlap width",
                        "0.25",
                        Patterns::Double(),
                        "Width of the band of Omega_n that the local region "
                        "also covers (length units). The local region is the "
                        "body minus Omega_n shrunk by this width on its faces "
                        "inside the body. Must be at least the mesh size.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  Geometry<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      body.lower = parse_point<dim>(prm, "Body lower corner", "Geometry");
      body.upper = parse_point<dim>(prm, "Body upper corner", "Geometry");
      nonlocal_region.lower =
        parse_point<dim>(prm, "Nonlocal region lower corner", "Geometry");
      nonlocal_region.upper =
        parse_point<dim>(prm, "Nonlocal region upper corner", "Geometry");
      overlap_width            = prm.get_double("Overlap width");
      const std::string choice = prm.get("Models");
      models = (choice == "nonlocal only") ? Models::nonlocal_only :
               (choice == "local only")    ? Models::local_only :
                                             Models::coupled;
      if (models == Models::nonlocal_only)
        nonlocal_region = body;
    }
    prm.leave_subsection();
  }



  template <int dim>
  double
  Geometry<dim>::tolerance() const
  {
    return 1e-10 * body.lower.distance(body.upper);
  }



  template <int dim>
  void
  Geometry<dim>::validate(const double h,
                          const double interaction_range,
                          const double horizon) const
  {
    const double tol = tolerance();
    for (unsigned int d = 0; d < dim; ++d)
      check_input(body.upper[d] > body.lower[d],
                  "Geometry/Body upper corner",
                  point_to_string(&body.upper[0], dim),
                  "every coordinate must exceed the body lower corner's (" +
                    point_to_string(&body.lower[0], dim) + ")");
    for (unsigned int d = 0; d < dim; ++d)
      check_input(nonlocal_region.upper[d] > nonlocal_region.lower[d],
                  "Geometry/Nonlocal region upper corner",
                  point_to_string(&nonlocal_region.upper[0], dim),
                  "every coordinate must exceed the nonlocal region lower "
                  "corner's");
    check_input(body.contains(nonlocal_region.lower, tol),
                "Geometry/Nonlocal region lower corner",
                point_to_string(&nonlocal_region.lower[0], dim),
                "the nonlocal region must lie inside the body " +
                  box_to_string(body));
    check_input(body.contains(nonlocal_region.upper, tol),
                "Geometry/Nonlocal region upper corner",
                point_to_string(&nonlocal_region.upper[0], dim),
                "the nonlocal region must lie inside the body " +
                  box_to_string(body));

    if (models != Models::coupled)
      {
        for (unsigned int d = 0; d < dim; ++d)
          check_input(is_multiple(body.upper[d] - body.lower[d], h),
                      "Discretization/Mesh size",
                      to_string(h),
                      "the mesh size must divide the body's extent (" +
                        to_string(body.upper[d] - body.lower[d]) +
                        ") a whole number of times");
        return;
      }

    bool has_interior_face = false;
    for (unsigned int f = 0; f < 2 * dim; ++f)
      has_interior_face |= !nonlocal_face_on_body_boundary(f);
    check_input(has_interior_face,
                "Geometry/Nonlocal region upper corner",
                point_to_string(&nonlocal_region.upper[0], dim),
                "the nonlocal region covers the whole body, which leaves no "
                "local region to couple to; it needs a face inside the body "
                "(or set Geometry/Models = nonlocal only)");

    check_input(overlap_width > 0,
                "Geometry/Overlap width",
                to_string(overlap_width),
                "the overlap must not be empty: give a positive width, at "
                "least the mesh size " +
                  to_string(h));
    check_input(overlap_width >= h - tol,
                "Geometry/Overlap width",
                to_string(overlap_width),
                "the overlap must be at least one mesh size wide (mesh size "
                "of the coarsest level: " +
                  to_string(h) + ")");

    const Box<dim> shrunk = shrunk_nonlocal_region();
    for (unsigned int d = 0; d < dim; ++d)
      check_input(shrunk.upper[d] - shrunk.lower[d] > tol,
                  "Geometry/Overlap width",
                  to_string(overlap_width),
                  "the overlap bands inside the nonlocal region's faces must "
                  "leave part of it to the nonlocal model alone: the width "
                  "must be less than the region's extent " +
                    to_string(nonlocal_region.upper[d] -
                              nonlocal_region.lower[d]) +
                    " (half of it where both faces lie inside the body)");
    for (unsigned int f = 0; f < 2 * dim; ++f)
      if (!nonlocal_face_on_body_boundary(f))
        {
          const unsigned int d = f / 2;
          // The control collar (and the nonlocal mesh covering it) must stay
          // inside the body: it is where the local model observes u_n.
          const double room = (f % 2 == 0) ?
                                nonlocal_region.lower[d] - body.lower[d] :
                                body.upper[d] - nonlocal_region.upper[d];
          check_input(interaction_range <= room + tol,
                      "Nonlocal model/Horizon",
                      to_string(horizon),
                      "the collar beyond face " + face_name(f) +
                        " of the nonlocal region must fit inside the body: "
                        "it is " +
                        to_string(interaction_range) +
                        " deep for this horizon (on the coarsest level), "
                        "the room there is " +
                        to_string(room) +
                        " (set by `Horizon`, or by `Horizon to mesh size "
                        "ratio` times the mesh size)");
        }

    // Meshes of size h must resolve every interface of the layout.
    const auto check_multiple = [&](const double       length,
                                    const std::string &what) {
      check_input(is_multiple(length, h),
                  "Discretization/Mesh size",
                  to_string(h),
                  "the mesh size must divide " + what + " (" +
                    to_string(length) + ") a whole number of times");
    };
    for (unsigned int d = 0; d < dim; ++d)
      {
        check_multiple(body.upper[d] - body.lower[d], "the body's extent");
        check_multiple(nonlocal_region.lower[d] - body.lower[d],
                       "the offset of the nonlocal region in the body");
        check_multiple(nonlocal_region.upper[d] - body.lower[d],
                       "the offset of the nonlocal region in the body");
      }
    check_multiple(overlap_width, "the overlap width");
  }



  template <int dim>
  bool
  Geometry<dim>::nonlocal_face_on_body_boundary(const unsigned int face) const
  {
    const unsigned int d = face / 2;
    return (face % 2 == 0) ?
             std::abs(nonlocal_region.lower[d] - body.lower[d]) <= tolerance() :
             std::abs(nonlocal_region.upper[d] - body.upper[d]) <= tolerance();
  }



  template <int dim>
  Box<dim>
  Geometry<dim>::shrunk_nonlocal_region() const
  {
    Box<dim> shrunk = nonlocal_region;
    for (unsigned int f = 0; f < 2 * dim; ++f)
      if (!nonlocal_face_on_body_boundary(f))
        {
          const unsigned int d = f / 2;
          if (f % 2 == 0)
            shrunk.lower[d] += overlap_width;
          else
            shrunk.upper[d] -= overlap_width;
        }
    return shrunk;
  }



  template <int dim>
  bool
  Geometry<dim>::in_local_region(const Point<dim> &p) const
  {
    // The removed part is the shrunk Omega_n, open on its interior faces and
    // extended beyond the body on faces that lie on the body's boundary (so
    // that a point of such a face is not a degenerate piece of Omega_l).
    const double diameter = body.lower.distance(body.upper);
    Box<dim>     removed  = shrunk_nonlocal_region();
    for (unsigned int f = 0; f < 2 * dim; ++f)
      if (nonlocal_face_on_body_boundary(f))
        {
          if (f % 2 == 0)
            removed.lower[f / 2] -= diameter;
          else
            removed.upper[f / 2] += diameter;
        }
    const double tol = tolerance();
    if (models != Models::coupled)
      return models == Models::local_only && body.contains(p, tol);
    return body.contains(p, tol) && !removed.contains_strictly(p, tol);
  }



  template <int dim>
  bool
  Geometry<dim>::in_overlap(const Point<dim> &p, const double range) const
  {
    return in_local_region(p) &&
           nonlocal_region.distance(p) <= range + tolerance();
  }



  template <int dim>
  Region
  Geometry<dim>::nonlocal_region_of(const Point<dim> &p,
                                    const double      range) const
  {
    // Collar tags first: they show the nonlocal model's own roles (volume
    // constraint, control); inside Omega_n the overlap band is marked.
    const double tol = tolerance();
    if (nonlocal_region.contains_strictly(p, tol))
      return in_overlap(p, range) ? Region::overlap : Region::nonlocal;
    // A collar point is physical when it lies beyond a face of Omega_n that
    // sits on the body's boundary.
    for (unsigned int f = 0; f < 2 * dim; ++f)
      if (nonlocal_face_on_body_boundary(f))
        {
          const unsigned int d = f / 2;
          if ((f % 2 == 0 && p[d] <= nonlocal_region.lower[d] + tol) ||
              (f % 2 == 1 && p[d] >= nonlocal_region.upper[d] - tol))
            return Region::physical_collar;
        }
    return Region::control_collar;
  }



  template <int dim>
  Region
  Geometry<dim>::local_region_of(const Point<dim> &p, const double range) const
  {
    return in_overlap(p, range) ? Region::overlap : Region::local;
  }



  template <int dim>
  bool
  Geometry<dim>::has_nonlocal_model() const
  {
    return models != Models::local_only;
  }



  template <int dim>
  bool
  Geometry<dim>::has_local_model() const
  {
    return models != Models::nonlocal_only;
  }



  template <int dim>
  std::string
  Geometry<dim>::face_name(const unsigned int face)
  {
    static const char *names[] = {"x-", "x+", "y-", "y+", "z-", "z+"};
    return names[face];
  }



  template <int dim>
  unsigned int
  Geometry<dim>::face_number(const std::string &name,
                             const std::string &parameter)
  {
    for (unsigned int f = 0; f < 2 * dim; ++f)
      if (face_name(f) == name)
        return f;
    std::string allowed =
      "face names of the body in " + std::to_string(dim) + "D, from:";
    for (unsigned int f = 0; f < 2 * dim; ++f)
      allowed += " " + face_name(f);
    throw InputError(parameter, name, allowed);
  }

  template struct Box<1>;
  template struct Box<2>;
  template struct Box<3>;
  template class Geometry<1>;
  template class Geometry<2>;
  template class Geometry<3>;
} // namespace ltn

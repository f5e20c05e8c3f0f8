#include <ltn/base/input_error.h>
#include <ltn/problem/geometry.h>

#include <cmath>
#include <sstream>

namespace ltn
{
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
      prm.declare_entry(
        "Nonlocal regions",
        "",
        Patterns::Anything(),
        "The nonlocal region Omega_n as a union of boxes, `;`-separated, "
        "each its lower corner then its upper corner (2D: `x0,y0,x1,y1`; "
        "3D: `x0,y0,z0,x1,y1,z1`). The boxes' interiors must be disjoint; "
        "they may touch (L- and T-shapes): no overlap band lies where they "
        "do. Not empty, it replaces the one box of `Nonlocal region "
        "lower/upper corner` (so a scene file's box can be changed from the "
        "command line). 1D: one box. `auto` (2D, 3D, a coupled scene): LtN "
        "chooses the region, a union of blocks of the coarse mesh, starting "
        "from each crack's box (without cracks: from the local model alone, "
        "then the blocks around the largest estimate) and adding, cycle by "
        "cycle, the fewest blocks of largest model-error estimate that could "
        "bring it below `Model error tolerance` (doc/model_adaptivity.md).");
      prm.declare_entry("Model error tolerance",
                        "1e-4",
                        Patterns::Double(),
                        "With `Nonlocal regions = auto`: the modeling error "
                        "to reach, relative to the energy norm of the "
                        "solution; the loop stops when the estimate is "
                        "below it. Positive.");
      prm.declare_entry("Model adaptivity cycles",
                        "6",
                        Patterns::Integer(),
                        "With `Nonlocal regions = auto`: the most regions the "
                        "loop solves on (the first is the cracks' boxes). At "
                        "least 1.");
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



  namespace
  {
    /** The boxes of `Geometry/Nonlocal regions` (V1 of the derivation). */
    template <int dim>
    std::vector<Box<dim>>
    parse_boxes(const std::string &text)
    {
      const std::string     parameter = "Geometry/Nonlocal regions";
      std::vector<Box<dim>> boxes;
      for (const std::string &item : Utilities::split_string_list(text, ';'))
        {
          const std::vector<std::string> numbers =
            Utilities::split_string_list(item, ',');
          check_input(numbers.size() == 2 * dim,
                      parameter,
                      item,
                      "boxes of " + std::to_string(2 * dim) +
                        " comma-separated numbers each (the lower corner, "
                        "then the upper corner), separated by `;`");
          Box<dim> box;
          for (unsigned int d = 0; d < 2 * dim; ++d)
            {
              double value = 0;
              try
                {
                  std::size_t end = 0;
                  value           = std::stod(numbers[d], &end);
                  check_input(end == numbers[d].size(), parameter, item, "");
                }
              catch (const std::exception &)
                {
                  throw InputError(parameter,
                                   item,
                                   "boxes of numbers (the lower corner, then "
                                   "the upper corner)");
                }
              (d < dim ? box.lower[d] : box.upper[d - dim]) = value;
            }
          for (unsigned int d = 0; d < dim; ++d)
            check_input(box.upper[d] > box.lower[d],
                        parameter,
                        item,
                        "each box's upper corner above its lower corner in "
                        "every coordinate");
          boxes.push_back(box);
        }
      check_input(dim > 1 || boxes.size() == 1,
                  parameter,
                  text,
                  "one box in 1D");
      return boxes;
    }
  } // namespace



  template <int dim>
  void
  Geometry<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      body.lower    = parse_point<dim>(prm, "Body lower corner", "Geometry");
      body.upper    = parse_point<dim>(prm, "Body upper corner", "Geometry");
      overlap_width = prm.get_double("Overlap width");
      const std::string choice = prm.get("Models");
      models = (choice == "nonlocal only") ? Models::nonlocal_only :
               (choice == "local only")    ? Models::local_only :
                                             Models::coupled;
      const std::string     list = prm.get("Nonlocal regions");
      std::vector<Box<dim>> boxes;
      automatic_region      = Utilities::trim(list) == "auto";
      model_error_tolerance = prm.get_double("Model error tolerance");
      check_input(model_error_tolerance > 0,
                  "Geometry/Model error tolerance",
                  prm.get("Model error tolerance"),
                  "a positive number (relative to the solution's energy "
                  "norm)");
      const long cycles_given = prm.get_integer("Model adaptivity cycles");
      check_input(cycles_given >= 1,
                  "Geometry/Model adaptivity cycles",
                  prm.get("Model adaptivity cycles"),
                  "at least 1");
      model_adaptivity_cycles = static_cast<unsigned int>(cycles_given);
      if (automatic_region)
        {
          // The model-adaptivity loop sets the boxes (ModelAdaptivity).
          given_as_list = true;
          check_input(dim > 1,
                      "Geometry/Nonlocal regions",
                      list,
                      "boxes; `auto` needs 2D or 3D");
          check_input(models == Models::coupled,
                      "Geometry/Models",
                      choice,
                      "coupled, with Geometry/Nonlocal regions = auto (a "
                      "nonlocal region is chosen only for a coupled scene)");
        }
      else if (Utilities::trim(list).empty())
        {
          Box<dim> box;
          box.lower =
            parse_point<dim>(prm, "Nonlocal region lower corner", "Geometry");
          box.upper =
            parse_point<dim>(prm, "Nonlocal region upper corner", "Geometry");
          boxes = {box};
        }
      else
        {
          boxes         = parse_boxes<dim>(list);
          given_as_list = true;
        }
      if (models == Models::nonlocal_only)
        boxes = {body};
      if (!automatic_region)
        set_nonlocal_boxes(boxes);
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  Geometry<dim>::set_nonlocal_boxes(const std::vector<Box<dim>> &boxes)
  {
    region = NonlocalRegion<dim>(body, boxes, overlap_width, tolerance());
  }



  template <int dim>
  const NonlocalRegion<dim> &
  Geometry<dim>::nonlocal_region() const
  {
    return region;
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
    const std::vector<Box<dim>> &boxes = region.boxes();
    // Errors name the parameter the user wrote: the list, or a corner.
    const auto parameter = [&](const std::string &corner) {
      return given_as_list ? std::string("Geometry/Nonlocal regions") :
                             "Geometry/Nonlocal region " + corner + " corner";
    };
    const auto box_text = [&](const Box<dim> &box, const std::string &corner) {
      return given_as_list ? box_to_string(box) :
                             point_to_string(corner == "lower" ? &box.lower[0] :
                                                                 &box.upper[0],
                                             dim);
    };
    for (const auto &box : boxes)
      {
        for (unsigned int d = 0; d < dim; ++d)
          check_input(box.upper[d] > box.lower[d],
                      parameter("upper"),
                      box_text(box, "upper"),
                      "every coordinate must exceed the nonlocal region lower "
                      "corner's");
        for (const std::string corner : {"lower", "upper"})
          check_input(body.contains(corner == "lower" ? box.lower : box.upper,
                                    tol),
                      parameter(corner),
                      box_text(box, corner),
                      "the nonlocal region must lie inside the body " +
                        box_to_string(body));
      }

    if (models != Models::coupled)
      {
        for (unsigned int d = 0; d < dim; ++d)
          check_input(is_whole_multiple(body.upper[d] - body.lower[d], h),
                      "Discretization/Mesh size",
                      to_string(h),
                      "the mesh size must divide the body's extent (" +
                        to_string(body.upper[d] - body.lower[d]) +
                        ") a whole number of times");
        return;
      }

    // Interiors pairwise disjoint: a box overlapping another would count
    // its particles twice.
    for (std::size_t a = 0; a < boxes.size(); ++a)
      for (std::size_t b = a + 1; b < boxes.size(); ++b)
        {
          bool apart = false;
          for (unsigned int d = 0; d < dim; ++d)
            apart = apart || boxes[a].upper[d] <= boxes[b].lower[d] + tol ||
                    boxes[b].upper[d] <= boxes[a].lower[d] + tol;
          check_input(apart,
                      "Geometry/Nonlocal regions",
                      box_to_string(boxes[a]) + " and " +
                        box_to_string(boxes[b]),
                      "boxes whose interiors do not overlap (they may touch)");
        }

    check_input(!region.covers_body(),
                parameter("upper"),
                box_text(boxes.back(), "upper"),
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

    if (!given_as_list)
      {
        const Box<dim> &box = boxes.front();
        for (unsigned int d = 0; d < dim; ++d)
          {
            unsigned int bands = 0;
            for (const unsigned int f : {2 * d, 2 * d + 1})
              bands += !region.touches_body_face(f);
            check_input(box.upper[d] - box.lower[d] - bands * overlap_width >
                          tol,
                        "Geometry/Overlap width",
                        to_string(overlap_width),
                        "the overlap bands inside the nonlocal region's "
                        "faces must leave part of it to the nonlocal model "
                        "alone: the width must be less than the region's "
                        "extent " +
                          to_string(box.upper[d] - box.lower[d]) +
                          " (half of it where both faces lie inside the "
                          "body)");
          }
      }
    else
      {
        // A box thinner than the band is all band on its own: the user
        // meant to move a face of its neighbour instead.
        for (const auto &box : boxes)
          for (unsigned int d = 0; d < dim; ++d)
            check_input(box.upper[d] - box.lower[d] >= overlap_width - tol ||
                          (std::abs(box.lower[d] - body.lower[d]) <= tol &&
                           std::abs(box.upper[d] - body.upper[d]) <= tol),
                        "Geometry/Nonlocal regions",
                        box_to_string(box),
                        "boxes at least as thick as Geometry/Overlap width (" +
                          to_string(overlap_width) + ") in every direction");
        check_input(region.every_piece_has_shrunk_part(),
                    "Geometry/Overlap width",
                    to_string(overlap_width),
                    "the overlap bands must leave part of every connected "
                    "piece of the nonlocal region to the nonlocal model "
                    "alone: a narrower band, or larger boxes");
      }

    // The control collar (and the nonlocal model covering it) must stay
    // inside the body beyond every face of Omega_n with part of the body
    // outside Omega_n beyond it: it is where the local model observes u_n.
    for (const auto &box : boxes)
      for (unsigned int f = 0; f < 2 * dim; ++f)
        if (region.face_is_exposed(box, f))
          {
            const unsigned int d = f / 2;
            const double room    = (f % 2 == 0) ? box.lower[d] - body.lower[d] :
                                                  body.upper[d] - box.upper[d];
            check_input(interaction_range <= room + tol,
                        "Nonlocal model/Horizon",
                        to_string(horizon),
                        "the collar beyond face " + face_name(f) +
                          " of the nonlocal region" +
                          (boxes.size() > 1 ?
                             " (box " + box_to_string(box) + ")" :
                             std::string()) +
                          " must fit inside the body: it is " +
                          to_string(interaction_range) +
                          " deep for this horizon (on the coarsest level), "
                          "the room there is " +
                          to_string(room) +
                          " (set by `Horizon`, or by `Horizon to mesh size "
                          "ratio` times the mesh size)");
          }

    // Along an axis, the body between two boxes is as wide as the collar
    // at least: the collar's layers beyond a face (the surrogate of the
    // control block walks them) do not re-enter Omega_n.
    for (std::size_t a = 0; a < boxes.size(); ++a)
      for (std::size_t b = 0; b < boxes.size(); ++b)
        for (unsigned int d = 0; d < dim; ++d)
          {
            bool facing = true;
            for (unsigned int e = 0; e < dim; ++e)
              if (e != d)
                facing = facing &&
                         boxes[a].lower[e] < boxes[b].upper[e] - tol &&
                         boxes[b].lower[e] < boxes[a].upper[e] - tol;
            const double gap = boxes[b].lower[d] - boxes[a].upper[d];
            check_input(!facing || gap <= tol || gap >= interaction_range - tol,
                        "Geometry/Nonlocal regions",
                        box_to_string(boxes[a]) + " and " +
                          box_to_string(boxes[b]),
                        "boxes that face each other across the body at "
                        "least as far apart as the nonlocal collar is deep (" +
                          to_string(interaction_range) +
                          " on the coarsest level), or touching; here " +
                          to_string(gap) + " along " + "xyz"[d]);
          }

    // Meshes of size h must resolve every interface of the layout.
    const auto check_multiple = [&](const double       length,
                                    const std::string &what) {
      check_input(is_whole_multiple(length, h),
                  "Discretization/Mesh size",
                  to_string(h),
                  "the mesh size must divide " + what + " (" +
                    to_string(length) + ") a whole number of times");
    };
    for (unsigned int d = 0; d < dim; ++d)
      {
        check_multiple(body.upper[d] - body.lower[d], "the body's extent");
        for (const auto &box : boxes)
          {
            check_multiple(box.lower[d] - body.lower[d],
                           "the offset of the nonlocal region in the body");
            check_multiple(box.upper[d] - body.lower[d],
                           "the offset of the nonlocal region in the body");
          }
      }
    check_multiple(overlap_width, "the overlap width");
  }



  template <int dim>
  bool
  Geometry<dim>::nonlocal_face_on_body_boundary(const unsigned int face) const
  {
    return region.touches_body_face(face);
  }



  template <int dim>
  bool
  Geometry<dim>::in_local_region(const Point<dim> &p) const
  {
    const double tol = tolerance();
    if (models != Models::coupled)
      return models == Models::local_only && body.contains(p, tol);
    return body.contains(p, tol) && region.in_local_part(p);
  }



  template <int dim>
  bool
  Geometry<dim>::in_overlap(const Point<dim> &p, const double range) const
  {
    return in_local_region(p) && region.distance(p) <= range + tolerance();
  }



  template <int dim>
  Region
  Geometry<dim>::nonlocal_region_of(const Point<dim> &p,
                                    const double      range) const
  {
    // Collar tags first: they show the nonlocal model's own roles (volume
    // constraint, control); inside Omega_n the overlap band is marked.
    const double tol = tolerance();
    if (region.contains_strictly(p, tol))
      return in_overlap(p, range) ? Region::overlap : Region::nonlocal;
    // A collar point is physical when it lies on or beyond a face of the
    // body that Omega_n touches.
    for (unsigned int f = 0; f < 2 * dim; ++f)
      if (region.touches_body_face(f))
        {
          const unsigned int d = f / 2;
          if ((f % 2 == 0 && p[d] <= body.lower[d] + tol) ||
              (f % 2 == 1 && p[d] >= body.upper[d] - tol))
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

  template class Geometry<1>;
  template class Geometry<2>;
  template class Geometry<3>;
} // namespace ltn

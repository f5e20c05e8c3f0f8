#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ltn/problem/box.h>
#include <ltn/problem/nonlocal_region.h>

#include <string>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The tag of a point in a scene, written into the output so that ParaView
   * shows the regions: the nonlocal region `Omega_n`, its physical collar
   * (outside the body, volume constraint), its control collar (inside the
   * body, virtual control `theta_n`), the overlap `Omega_b` where the mismatch
   * is measured, and the rest of the local region.
   */
  enum class Region : unsigned int
  {
    nonlocal        = 0,
    physical_collar = 1,
    control_collar  = 2,
    overlap         = 3,
    local           = 4
  };

  /**
   * The layout of a scene (section 3 of the design): the body `D`, the
   * nonlocal region `Omega_n` (a union of boxes inside `D`, see
   * NonlocalRegion), and the overlap width. The rest is derived: the local
   * region `Omega_l` is `D` minus the interior of `Omega_n` shrunk by the
   * overlap width against the part of `D` outside it (faces on the body's
   * boundary and faces where boxes touch are not shrunk); the collar of
   * `Omega_n` (points within the interaction range) is physical outside `D`
   * and a control collar inside; `Omega_b` is `Omega_l` intersected with
   * `Omega_n` and its control collar; `Gamma_c` is the part of the boundary
   * of `Omega_l` inside `Omega_n`.
   *
   * Faces of a box are numbered as in deal.II's colorized meshes: `2 d` is the
   * lower face in direction `d`, `2 d + 1` the upper one; users name them
   * `x-`, `x+`, `y-`, `y+`, `z-`, `z+`.
   */
  template <int dim>
  class Geometry
  {
  public:
    /**
     * Which models a scene runs: both, coupled; or one of them on the whole
     * body, the reference a coupled result is compared with.
     */
    enum class Models
    {
      coupled,
      nonlocal_only,
      local_only
    };

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Check that the layout can be discretized with mesh size @p h (the
     * coarsest of a study) and a nonlocal model of horizon @p horizon whose
     * collar is @p interaction_range deep (the horizon for diffusion, two
     * for LPS), both of the coarsest level: an InputError names the
     * parameter at fault otherwise.
     */
    void
    validate(const double h,
             const double interaction_range,
             const double horizon) const;

    /** Does `Omega_n` touch face @p face of the body (with some area)? */
    bool
    nonlocal_face_on_body_boundary(const unsigned int face) const;

    /**
     * Make `Omega_n` the union of @p boxes, in the current `body` with the
     * current `overlap_width` (set those first).
     */
    void
    set_nonlocal_boxes(const std::vector<Box<dim>> &boxes);

    /** `Omega_n` and the sets derived from it; the body itself in a
     * `nonlocal only` scene. */
    const NonlocalRegion<dim> &
    nonlocal_region() const;

    /** Is @p p in the (closed) local region `Omega_l`? */
    bool
    in_local_region(const Point<dim> &p) const;

    /**
     * Is @p p in the overlap `Omega_b = Omega_l ∩ (Omega_n ∪ control
     * collar)`, for interaction range @p range?
     */
    bool
    in_overlap(const Point<dim> &p, const double range) const;

    /**
     * The region tag of a point of the nonlocal discretization: a collar tag
     * outside `Omega_n`, `overlap` or `nonlocal` inside.
     */
    Region
    nonlocal_region_of(const Point<dim> &p, const double range) const;

    /** The region tag of a point of the local discretization. */
    Region
    local_region_of(const Point<dim> &p, const double range) const;

    /** "x-", "x+", ... for face numbers 0, 1, ... */
    static std::string
    face_name(const unsigned int face);

    /** The face number of a name "x-", "x+", ...; throws on others. */
    static unsigned int
    face_number(const std::string &name, const std::string &parameter);

    /** A tolerance for geometric comparisons, relative to the body size. */
    double
    tolerance() const;

    /** Does the scene have a nonlocal model? */
    bool
    has_nonlocal_model() const;

    /** Does the scene have a local model? */
    bool
    has_local_model() const;

    Models   models = Models::coupled;
    Box<dim> body;
    double   overlap_width = 0;
    /**
     * `Nonlocal regions = auto`: the model-adaptivity loop sets the boxes
     * (set_nonlocal_boxes()), within `Model adaptivity cycles` regions, to
     * `Model error tolerance`.
     */
    bool         automatic_region        = false;
    double       model_error_tolerance   = 1e-4;
    unsigned int model_adaptivity_cycles = 6;

  private:
    /**
     * Was `Omega_n` given as a list (`Nonlocal regions`) rather than by the
     * two corners? Input errors name the parameter the user wrote.
     */
    bool                given_as_list = false;
    NonlocalRegion<dim> region;
  };
} // namespace ltn

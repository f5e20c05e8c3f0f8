// The graded local mesh: cells of the mesh size near the nonlocal region,
// each coarser cell at least `Graded mesh layers` of its own half-sizes away
// from it, as symmetric as the layout, fewer cells than the uniform mesh; no
// grading without a nonlocal model.

#include <ltn/base/input_error.h>
#include <ltn/local/local_mesh.h>
#include <ltn/local/local_parameters.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "box_layout.h"

using namespace ltn;

namespace
{
  /**
   * The body (0,2)^dim around Omega_n = (0.5,1.5) x (0.75,1.25)^(dim-1);
   * in 2D the cracked plate's layout (`lps_plate_2d_crack.prm`).
   */
  template <int dim>
  Geometry<dim>
  plate_geometry()
  {
    return box_layout<dim>(slab<dim>(0, 2, 0, 2),
                           {slab<dim>(0.5, 1.5, 0.75, 1.25)},
                           (dim == 2) ? 0.1 : 0.125);
  }

  /** The distance from the centre of a cell of size @p size to the box. */
  template <int dim>
  double
  cell_distance(const Point<dim> &center, const double size, const Box<dim> &b)
  {
    double square = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double gap = std::max({0.,
                                     b.lower[d] - (center[d] + size / 2),
                                     (center[d] - size / 2) - b.upper[d]});
        square += gap * gap;
      }
    return std::sqrt(square);
  }

  template <int dim>
  void
  check_graded_mesh(const unsigned int layers)
  {
    const Geometry<dim>  geometry = plate_geometry<dim>();
    const double         h        = (dim == 2) ? 1. / 40 : 1. / 16;
    const LocalMesh<dim> uniform(geometry, h, 0, MPI_COMM_WORLD);
    const LocalMesh<dim> graded(geometry, h, layers, MPI_COMM_WORLD);

    double       coarsest = 0;
    unsigned int n_fine   = 0;
    // The layout is symmetric about x = 1, y = 1 (and z = 1): so must the
    // mesh be. The cells below and above each plane, by their sizes.
    std::vector<double> below(dim, 0.), above(dim, 0.);
    for (const auto &cell : graded.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double size = cell->extent_in_direction(0);
          const double distance =
            cell_distance(cell->center(),
                          size,
                          geometry.nonlocal_region().boxes().front());
          INFO("cell at " << cell->center() << " of size " << size);
          // Cells of size h within `layers` h of Omega_n (all of the
          // overlap among them); coarser ones farther out.
          if (size > 1.5 * h)
            CHECK(distance >= layers * size / 2 - 1e-12);
          else
            ++n_fine;
          coarsest = std::max(coarsest, size);
          for (unsigned int d = 0; d < dim; ++d)
            (cell->center()[d] < 1 ? below : above)[d] += std::log2(size);
        }
    for (unsigned int d = 0; d < dim; ++d)
      CHECK(Utilities::MPI::sum(below[d], MPI_COMM_WORLD) ==
            Approx(Utilities::MPI::sum(above[d], MPI_COMM_WORLD)));
    coarsest = Utilities::MPI::max(coarsest, MPI_COMM_WORLD);
    n_fine   = Utilities::MPI::sum(n_fine, MPI_COMM_WORLD);
    // The far cells reach the coarsest size the layout allows, of which
    // Omega_n's shrunk corners are multiples: 1/20 (0.6, 0.85) in 2D, 1/8
    // (0.625, 0.875) in 3D.
    CHECK(coarsest == Approx((dim == 2) ? 1. / 20 : 1. / 8));
    CHECK(n_fine > 0);
    CHECK(graded.get_triangulation().n_global_active_cells() <
          uniform.get_triangulation().n_global_active_cells() / 2);
  }
} // namespace



TEST_CASE("a graded local mesh keeps cells of size h near the nonlocal region",
          "[local]")
{
  for (const unsigned int layers : {1u, 4u})
    {
      INFO("layers " << layers);
      check_graded_mesh<2>(layers);
      check_graded_mesh<3>(layers);
    }
}



TEST_CASE("grading a local mesh without a nonlocal model is an input error",
          "[local]")
{
  Geometry<2> geometry = plate_geometry<2>();
  geometry.models      = Geometry<2>::Models::local_only;
  LocalParameters<2> parameters;
  CHECK_NOTHROW(parameters.validate(geometry));
  parameters.graded_mesh_layers = 2;
  CHECK_THROWS_AS(parameters.validate(geometry), InputError);
  geometry.models = Geometry<2>::Models::coupled;
  CHECK_NOTHROW(parameters.validate(geometry));
}

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_refinement.h>

#include <deal.II/numerics/error_estimator.h>

#include <ltn/local/local_mesh.h>

#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace ltn
{
  namespace
  {
    /** A distributed mesh in 2D and 3D, a serial one in 1D. */
    template <int dim>
    std::unique_ptr<Triangulation<dim>>
    make_triangulation(const MPI_Comm communicator)
    {
      if constexpr (dim == 1)
        {
          AssertThrow(Utilities::MPI::n_mpi_processes(communicator) == 1,
                      ExcMessage("1D meshes are serial"));
          return std::make_unique<Triangulation<1>>();
        }
      else
        return std::make_unique<parallel::distributed::Triangulation<dim>>(
          communicator);
    }

    /**
     * The number of times a mesh of size @p h can be coarsened so that the
     * body and the local region stay unions of its cells.
     */
    template <int dim>
    unsigned int
    coarsening_steps(const Geometry<dim> &geometry, const double h)
    {
      // The planes the coarse mesh must resolve: the faces of the part of
      // Omega_n the local mesh leaves out.
      std::array<std::vector<double>, dim> hole_faces;
      if (geometry.has_nonlocal_model())
        for (unsigned int d = 0; d < dim; ++d)
          hole_faces[d] = geometry.nonlocal_region().shrunk_face_coordinates(d);
      unsigned int steps = 0;
      while (steps < 20)
        {
          const double size = h * (1 << (steps + 1));
          bool         fits = true;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double origin = geometry.body.lower[d];
              fits                = fits &&
                     is_whole_multiple(geometry.body.upper[d] - origin, size);
              for (const double face : hole_faces[d])
                fits = fits && is_whole_multiple(face - origin, size);
            }
          if (!fits)
            break;
          ++steps;
        }
      return steps;
    }

    /**
     * The distance from @p cell to the nearest box of @p region (0 if they
     * meet).
     */
    template <int dim>
    double
    distance_to(const typename Triangulation<dim>::cell_iterator &cell,
                const NonlocalRegion<dim>                        &region)
    {
      const auto [lower, upper] = cell->bounding_box().get_boundary_points();
      double nearest            = std::numeric_limits<double>::infinity();
      for (const auto &box : region.boxes())
        {
          double square = 0;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double gap = std::max(
                {0., box.lower[d] - upper[d], lower[d] - box.upper[d]});
              square += gap * gap;
            }
          nearest = std::min(nearest, std::sqrt(square));
        }
      return nearest;
    }
  } // namespace



  template <int dim>
  LocalMesh<dim>::LocalMesh(const Geometry<dim> &geometry,
                            const double         h,
                            const unsigned int   graded_layers,
                            const MPI_Comm       communicator)
    : triangulation(make_triangulation<dim>(communicator))
  {
    // LocalParameters::validate() tells the user.
    AssertThrow(graded_layers == 0 || geometry.has_nonlocal_model(),
                ExcMessage("a mesh is graded towards the nonlocal region"));
    // A coarse mesh of the body minus the cells of the shrunk nonlocal
    // region (the geometry is aligned with h, see Geometry::validate()),
    // then refined to h.
    const unsigned int        steps = coarsening_steps(geometry, h);
    const double              H     = h * (1 << steps);
    std::vector<unsigned int> repetitions(dim);
    for (unsigned int d = 0; d < dim; ++d)
      repetitions[d] = static_cast<unsigned int>(
        std::round((geometry.body.upper[d] - geometry.body.lower[d]) / H));
    Triangulation<dim> body_mesh;
    GridGenerator::subdivided_hyper_rectangle(body_mesh,
                                              repetitions,
                                              geometry.body.lower,
                                              geometry.body.upper);
    std::set<typename Triangulation<dim>::active_cell_iterator> removed;
    for (const auto &cell : body_mesh.active_cell_iterators())
      if (!geometry.in_local_region(cell->center()))
        removed.insert(cell);
    GridGenerator::create_triangulation_with_removed_cells(body_mesh,
                                                           removed,
                                                           *triangulation);

    // Set on the coarse mesh (all of it, on every rank), inherited by the
    // refined cells.
    const double tol = geometry.tolerance();
    for (const auto &cell : triangulation->cell_iterators_on_level(0))
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<dim>   center = cell->face(f)->center();
            types::boundary_id id     = control_boundary_id;
            for (unsigned int face = 0; face < 2 * dim; ++face)
              {
                const double body_coordinate = (face % 2 == 0) ?
                                                 geometry.body.lower[face / 2] :
                                                 geometry.body.upper[face / 2];
                if (std::abs(center[face / 2] - body_coordinate) <= tol)
                  id = face;
              }
            cell->face(f)->set_boundary_id(id);
          }
    if (graded_layers == 0)
      triangulation->refine_global(steps);
    else
      for (unsigned int step = 0; step < steps; ++step)
        {
          // A cell is split when its children would lie within
          // graded_layers of their own sizes of Omega_n; the cells just at
          // that distance are not (with a tolerance: round-off decided them
          // one by one).
          for (const auto &cell : triangulation->active_cell_iterators())
            if (cell->is_locally_owned() &&
                distance_to<dim>(cell, geometry.nonlocal_region()) <
                  graded_layers * 0.5 * cell->extent_in_direction(0) - tol)
              cell->set_refine_flag();
          triangulation->execute_coarsening_and_refinement();
        }
  }



  template <int dim>
  Triangulation<dim> &
  LocalMesh<dim>::get_triangulation()
  {
    return *triangulation;
  }



  template <int dim>
  const Triangulation<dim> &
  LocalMesh<dim>::get_triangulation() const
  {
    return *triangulation;
  }



  template <int dim>
  void
  LocalMesh<dim>::refine(
    const DoFHandler<dim>                                 &dof_handler,
    const TrilinosWrappers::MPI::Vector                   &ghosted_solution,
    const double                                           fraction,
    const std::function<bool(const Point<dim> &, double)> &may_refine)
  {
    Vector<float> indicators(triangulation->n_active_cells());
    KellyErrorEstimator<dim>::estimate(dof_handler,
                                       QGauss<dim - 1>(
                                         dof_handler.get_fe().degree + 1),
                                       {},
                                       ghosted_solution,
                                       indicators);
    // Spend the fraction on the cells that may be refined: where the largest
    // indicators lie in cells that may not (the overlap's), flagging first
    // and clearing after would refine nothing.
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned() &&
          !may_refine(cell->center(), cell->extent_in_direction(0)))
        indicators(cell->active_cell_index()) = 0;
    if constexpr (dim == 1)
      GridRefinement::refine_and_coarsen_fixed_number(*triangulation,
                                                      indicators,
                                                      fraction,
                                                      0);
    else
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        static_cast<parallel::distributed::Triangulation<dim> &>(
          *triangulation),
        indicators,
        fraction,
        0);
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned() && cell->refine_flag_set() &&
          !may_refine(cell->center(), cell->extent_in_direction(0)))
        cell->clear_refine_flag();
    triangulation->execute_coarsening_and_refinement();
  }



  template class LocalMesh<1>;
  template class LocalMesh<2>;
  template class LocalMesh<3>;
} // namespace ltn

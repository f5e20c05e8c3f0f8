#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/problem/geometry.h>

#include <functional>
#include <memory>

namespace ltn
{
  using namespace dealii;

  /**
   * The mesh of the local region `Omega_l`, shared by the local models: a
   * mesh of size `h` (uniform, or graded away from `Omega_n`) of the body
   * minus the cells outside `Omega_l`,
   * built from a coarse mesh as coarse as the layout allows (so that
   * p4est's replicated coarse forest stays small). Boundary faces on the
   * body keep deal.II's colorized ids `0 .. 2dim-1` (`x-`, `x+`, ...); all
   * other boundary faces form `Gamma_c`, id control_boundary_id.
   *
   * In 2D and 3D the mesh is a parallel::distributed::Triangulation over
   * the given communicator; in 1D (which p4est does not have) it is serial,
   * and the communicator must have one rank.
   */
  template <int dim>
  class LocalMesh
  {
  public:
    /** The boundary id of `Gamma_c`. */
    static constexpr types::boundary_id control_boundary_id = 2 * dim;

    /**
     * Mesh `Omega_l` of @p geometry with cells of size @p h: everywhere if
     * @p graded_layers is 0, else within @p graded_layers h of `Omega_n`,
     * and cells of size 2^k h at least 2^(k-1) @p graded_layers h from it.
     */
    LocalMesh(const Geometry<dim> &geometry,
              const double         h,
              const unsigned int   graded_layers,
              const MPI_Comm       communicator);

    LocalMesh(const LocalMesh &) = delete;
    LocalMesh &
    operator=(const LocalMesh &) = delete;

    Triangulation<dim> &
    get_triangulation();

    const Triangulation<dim> &
    get_triangulation() const;

    /**
     * Refine the cells with the largest Kelly error indicators of the field
     * @p ghosted_solution on @p dof_handler (a @p fraction of them, over all
     * ranks; all components of a vector field count), except those for
     * which @p may_refine (given the cell's centre and size) says no. The
     * degrees of freedom of @p dof_handler must be distributed anew after.
     */
    void
    refine(const DoFHandler<dim>               &dof_handler,
           const TrilinosWrappers::MPI::Vector &ghosted_solution,
           const double                         fraction,
           const std::function<bool(const Point<dim> &, double)> &may_refine);

  private:
    const std::unique_ptr<Triangulation<dim>> triangulation;
  };
} // namespace ltn

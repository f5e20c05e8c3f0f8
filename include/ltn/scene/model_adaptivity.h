#pragma once

#include <deal.II/base/mpi.h>

#include <ltn/output/run_summary.h>
#include <ltn/problem/block_grid.h>
#include <ltn/problem/geometry.h>
#include <ltn/scene/model_error.h>

#include <string>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * `Geometry/Nonlocal regions = auto` (doc/model_adaptivity.md, section 3):
   * the nonlocal region `U` as a set of blocks of the body, grown cycle by
   * cycle where the model-error estimate of the coupled solution exceeds
   * its share of `Geometry/Model error tolerance`.
   *
   * Blocks are `H_b` wide, `H_b` the smallest multiple of the coarse mesh
   * size at least the overlap width and the collar depth `R`: a gap
   * between two pieces is then never narrower than the collar. The region
   * grows from its faces, so each piece keeps the part of the region the
   * start gave it to the nonlocal model alone. Only blocks at least `R` from
   * every face of the body are added: their union is the largest admissible
   * region `U_max`, whose coupled solution is the reference of the region's
   * true modeling error.
   */
  template <int dim>
  class ModelAdaptivity
  {
  public:
    /**
     * The loop of @p geometry (its body, overlap width, tolerance and
     * cycle limit) on a coarse mesh of size @p h0, for a nonlocal model
     * whose collar is @p interaction_range deep, starting from @p starts
     * (each crack's bounding box): each grown by the overlap width and
     * @p margin, snapped outward to the blocks, kept in `U_max`.
     */
    ModelAdaptivity(const Geometry<dim>         &geometry,
                    const double                 h0,
                    const double                 interaction_range,
                    const std::vector<Box<dim>> &starts,
                    const double                 margin);

    /**
     * Never add the blocks within the overlap width of @p keep_out (closed
     * boxes, possibly flat: a section plane), so that the part of the
     * region left to the nonlocal model alone never reaches them. Blocks
     * already in the region stay.
     */
    void
    keep_away_from(const std::vector<Box<dim>> &keep_out);

    /** `U` as boxes (BlockGrid::boxes()). */
    std::vector<Box<dim>>
    region_boxes() const;

    /** `U_max` as boxes. */
    std::vector<Box<dim>>
    largest_boxes() const;

    double
    block_size() const
    {
      return size;
    }

    /** The block that holds @p p. */
    unsigned int
    block_of(const Point<dim> &p) const
    {
      return grid.block_of(p);
    }

    /**
     * The squared indicator of every block, `eta_K^2`: the sum of the
     * short-wave terms at the points of @p field in block `K` (the
     * Dirichlet strip's apart), and of its long-wave terms if positive,
     * over all ranks of @p comm.
     */
    std::vector<double>
    block_indicators(const ModelErrorField<dim> &field,
                     const MPI_Comm              comm) const;

    /**
     * One cycle's decision from its estimate @p estimate and block
     * indicators @p indicators (the same on every rank): stop, or mark and
     * grow `U`. Fills the cycle's entry of @p cycle but its boxes,
     * particles and errors; returns whether to run another cycle.
     */
    bool
    adapt(const ModelErrorRecord    &estimate,
          const std::vector<double> &indicators,
          const unsigned int         cycle_number,
          ModelCycleRecord          &cycle);

  private:
    /**
     * Add the marked blocks (each sharing a face with `U`) to `U`, and the
     * pockets of the body it then encloses. Returns the blocks added.
     */
    unsigned int
    grow(const typename BlockGrid<dim>::Set &marked);

    Box<dim>                     body;
    double                       overlap_width, tolerance;
    unsigned int                 cycles;
    double                       size;
    BlockGrid<dim>               grid;
    typename BlockGrid<dim>::Set region, largest;
  };
} // namespace ltn

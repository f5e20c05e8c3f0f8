#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <deal.II/dofs/dof_handler.h>

#include <ltn/base/discrete_model.h>
#include <ltn/problem/geometry.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The particles of a nonlocal region as an implicit lattice: the centres of
   * the cells of spacing `h` that fill the boxes of `Omega_n`, on the grid
   * anchored at the lower corner of their bounding box (`0 <= i_d < n_d`),
   * plus the collar cells some cell of `Omega_n` reaches, i.e. whose offset
   * from the nearest cell of some box is one of the stencil's offsets.
   *
   * Particles are numbered lexicographically, `i_0` fastest. Along each line
   * of fixed `(i_1, ..., i_{dim-1})` the particles present form runs of
   * consecutive `i_0` (one per line for a single box: the stencil is convex
   * along the axes; a line may pass several boxes, with gaps between them).
   * A table of runs maps lattice indices to numbers and back: memory
   * proportional to the number of lines, not of particles, on every rank.
   */
  template <int dim>
  class ParticleLattice
  {
  public:
    using LatticeIndex = std::array<int, dim>;

    static constexpr types::global_dof_index invalid =
      numbers::invalid_dof_index;

    ParticleLattice(const NonlocalRegion<dim>       &region,
                    const double                     spacing,
                    const std::vector<LatticeIndex> &reach);

    types::global_dof_index
    n_particles() const;

    /** The number of the particle at @p index, or `invalid`. */
    types::global_dof_index
    number(const LatticeIndex &index) const;

    /**
     * A run of a lattice line: its particles (fixed `i_1, ..., i_{dim-1}`)
     * have the consecutive numbers `[begin, end)`, and the one at `i_0` the
     * number `origin + i_0`. The line's next run starts at `i_0 =
     * next_first` (the largest int if none).
     */
    struct Line
    {
      std::int64_t            origin     = 0;
      types::global_dof_index begin      = 0;
      types::global_dof_index end        = 0;
      int                     next_first = std::numeric_limits<int>::max();
    };

    /**
     * The run of the line through @p index that holds its `i_0`, or else the
     * line's first run beyond it; empty if there is none.
     */
    Line
    line(const LatticeIndex &index) const;

    /** The lattice index of particle @p number. */
    LatticeIndex
    index(const types::global_dof_index number) const;

    Point<dim>
    position(const LatticeIndex &index) const;

    /** Is the particle in `Omega_n` (not in its collar)? */
    bool
    inside(const LatticeIndex &index) const;

    /** The number of particles in `Omega_n`. */
    types::global_dof_index
    n_inside() const;

    /**
     * The number of the particle at @p index among those of `Omega_n`,
     * lexicographic (`i_0` fastest), as `number` is among all: both orders
     * agree, so the particles of `Omega_n` in a contiguous range of numbers
     * have contiguous numbers here.
     */
    types::global_dof_index
    inside_number(const LatticeIndex &index) const;

    /**
     * The role of the particle at @p index in a nonlocal model on
     * @p geometry: free in `Omega_n`, a control in the collar inside the
     * body, fixed (volume constraint) outside it.
     */
    DofRole
    role(const LatticeIndex &index, const Geometry<dim> &geometry) const;

    /**
     * Call `f(index, number)` for every particle whose position lies in the
     * box `[lower, upper]` widened by @p tolerance.
     */
    template <typename F>
    void
    for_each_in_box(const Point<dim> &lower,
                    const Point<dim> &upper,
                    const double      tolerance,
                    const F          &f) const;

  private:
    /** The line of @p index, or `invalid` outside the lattice's box. */
    std::size_t
    line_of(const LatticeIndex &index) const;

    /**
     * Intervals `[first, end)` of `i_0` per line, in increasing order, with
     * the count of the intervals' points before each: the particles present
     * (runs), or those of `Omega_n`.
     */
    struct Intervals
    {
      /** Per line, its intervals are `[line_begin[l], line_begin[l + 1])`. */
      std::vector<std::size_t>             line_begin;
      std::vector<int>                     first, end;
      std::vector<types::global_dof_index> start;
      /** The line of each interval. */
      std::vector<std::size_t> line;

      /** The interval of line @p l holding @p x, or the next; may be past. */
      std::size_t
      find(const std::size_t l, const int x) const;
      types::global_dof_index
      total() const;
    };

    Point<dim>   origin;
    double       spacing;
    LatticeIndex n;
    int          radius;
    Intervals    runs;
    Intervals    inside_runs;
  };



  template <int dim>
  template <typename F>
  void
  ParticleLattice<dim>::for_each_in_box(const Point<dim> &lower,
                                        const Point<dim> &upper,
                                        const double      tolerance,
                                        const F          &f) const
  {
    LatticeIndex lo, hi;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lo[d] =
          std::max<int>(-radius,
                        std::ceil((lower[d] - tolerance - origin[d]) / spacing -
                                  0.5));
        hi[d] =
          std::min<int>(n[d] + radius - 1,
                        std::floor(
                          (upper[d] + tolerance - origin[d]) / spacing - 0.5));
        if (hi[d] < lo[d])
          return;
      }
    LatticeIndex index = lo;
    while (true)
      {
        const std::size_t line = line_of(index);
        for (std::size_t r = runs.line_begin[line];
             r < runs.line_begin[line + 1];
             ++r)
          for (int x = std::max(lo[0], runs.first[r]);
               x <= std::min(hi[0], runs.end[r] - 1);
               ++x)
            {
              index[0] = x;
              f(index, runs.start[r] + (x - runs.first[r]));
            }
        // Next line: increment (i_1, ..., i_{dim-1}) within the box.
        unsigned int d = 1;
        for (; d < dim; ++d)
          {
            if (++index[d] <= hi[d])
              break;
            index[d] = lo[d];
          }
        if (d == dim)
          return;
      }
  }



  /**
   * Call `f(cell, index, number, unit)` for every particle of @p lattice in
   * a locally owned cell of @p dofs' mesh (Cartesian: cells are
   * axis-parallel boxes), `unit` its position in the cell's unit
   * coordinates. Each particle is visited in the one cell that holds it in
   * `[lower - tolerance, upper - tolerance)`, closed on faces at the mesh's
   * boundary: every rank visits its own particles, once.
   */
  template <int dim, typename F>
  void
  for_each_in_owned_cells(const ParticleLattice<dim> &lattice,
                          const DoFHandler<dim>      &dofs,
                          const double                tolerance,
                          const F                    &f)
  {
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Point<dim> lower = cell->vertex(0);
          const Point<dim> upper =
            cell->vertex(GeometryInfo<dim>::vertices_per_cell - 1);
          lattice.for_each_in_box(
            lower,
            upper,
            tolerance,
            [&](const auto &index, const types::global_dof_index number) {
              const Point<dim> x = lattice.position(index);
              Point<dim>       unit;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  if (x[d] >= upper[d] - tolerance &&
                      !cell->face(2 * d + 1)->at_boundary())
                    return;
                  unit[d] = (x[d] - lower[d]) / (upper[d] - lower[d]);
                }
              f(cell, index, number, unit);
            });
        }
  }
} // namespace ltn

#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <ltn/base/discrete_model.h>
#include <ltn/problem/geometry.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The particles of a nonlocal region as an implicit lattice: the centres of
   * the cells of spacing `h` that fill the box `Omega_n`
   * (`0 <= i_d < n_d`), plus the collar cells some cell of `Omega_n`
   * reaches, i.e. whose offset from the nearest cell of `Omega_n` is one of
   * the stencil's offsets.
   *
   * Particles are numbered lexicographically, `i_0` fastest. Along each line
   * of fixed `(i_1, ..., i_{dim-1})` the particles present are contiguous
   * (the stencil is convex along the axes), so a table of one entry per line
   * maps lattice indices to numbers and back: memory proportional to the
   * number of lines, not of particles, on every rank.
   */
  template <int dim>
  class ParticleLattice
  {
  public:
    using LatticeIndex = std::array<int, dim>;

    static constexpr types::global_dof_index invalid =
      numbers::invalid_dof_index;

    ParticleLattice(const Box<dim>                  &region,
                    const double                     spacing,
                    const std::vector<LatticeIndex> &reach);

    types::global_dof_index
    n_particles() const;

    /** The number of the particle at @p index, or `invalid`. */
    types::global_dof_index
    number(const LatticeIndex &index) const;

    /**
     * A line of the lattice: its particles (fixed `i_1, ..., i_{dim-1}`)
     * have the consecutive numbers `[begin, end)`, and the one at `i_0` the
     * number `origin + i_0`.
     */
    struct Line
    {
      std::int64_t            origin = 0;
      types::global_dof_index begin  = 0;
      types::global_dof_index end    = 0;
    };

    /** The line through @p index (its `i_0` ignored); empty if absent. */
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
     * lexicographic in its box (`i_0` fastest), as `number` is among all:
     * both orders agree, so the particles of `Omega_n` in a contiguous
     * range of numbers have contiguous numbers here.
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

    Point<dim>   origin;
    double       spacing;
    LatticeIndex n;
    int          radius;
    /** Per line: the present `i_0` in `[first_x, end_x)`. */
    std::vector<int> first_x, end_x;
    /** Per line: the number of its first particle; one more at the end. */
    std::vector<types::global_dof_index> line_start;
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
        for (int x = std::max(lo[0], first_x[line]);
             x <= std::min(hi[0], end_x[line] - 1);
             ++x)
          {
            index[0] = x;
            f(index, line_start[line] + (x - first_x[line]));
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
} // namespace ltn

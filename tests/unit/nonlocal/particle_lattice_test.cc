// The particle lattice of a region made of boxes against brute force: the
// particles present are those some particle of a box reaches, numbered
// lexicographically; those of Omega_n are numbered in the same order.

#include <ltn/nonlocal/particle_lattice.h>

#include <catch2/catch.hpp>

#include <set>

#include "particle_layout.h"

using namespace ltn;

namespace
{
  /** The offsets of the lattice ball of radius @p r (the origin excluded). */
  template <int dim>
  std::vector<std::array<int, dim>>
  ball(const int r)
  {
    std::vector<std::array<int, dim>> offsets;
    std::array<int, dim>              o;
    for (o[0] = -r; o[0] <= r; ++o[0])
      for (o[1] = -r; o[1] <= r; ++o[1])
        for (int z = (dim == 3 ? -r : 0); z <= (dim == 3 ? r : 0); ++z)
          {
            o[dim - 1]  = dim == 3 ? z : o[dim - 1];
            int squared = 0;
            for (unsigned int d = 0; d < dim; ++d)
              squared += o[d] * o[d];
            if (squared > 0 && squared <= r * r)
              offsets.push_back(o);
          }
    return offsets;
  }

  template <int dim>
  void
  check_lattice(const Geometry<dim> &geometry,
                const double         spacing,
                const int            radius)
  {
    using Index                 = std::array<int, dim>;
    const auto           reach  = ball<dim>(radius);
    const auto          &region = geometry.nonlocal_region();
    const Box<dim>       bounds = region.bounding_box();
    ParticleLattice<dim> lattice(region, spacing, reach);

    // Brute force over the bounding box widened by the radius.
    Index n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = std::round((bounds.upper[d] - bounds.lower[d]) / spacing);
    const auto in_box = [&](const Index &i) {
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = bounds.lower[d] + (i[d] + 0.5) * spacing;
      return region.contains_strictly(x, 0);
    };
    std::set<Index> inside, present;
    Index           i;
    const auto      for_each = [&](const int widen, const auto &f) {
      for (i[0] = -widen; i[0] < n[0] + widen; ++i[0])
        for (i[1] = -widen; i[1] < n[1] + widen; ++i[1])
          for (int z = (dim == 3 ? -widen : 0);
               z < (dim == 3 ? n[dim - 1] + widen : 1);
               ++z)
            {
              if (dim == 3)
                i[dim - 1] = z;
              f(i);
            }
    };
    for_each(0, [&](const Index &i) {
      if (in_box(i))
        inside.insert(i);
    });
    for (const auto &p : inside)
      {
        present.insert(p);
        for (const auto &o : reach)
          {
            Index q = p;
            for (unsigned int d = 0; d < dim; ++d)
              q[d] += o[d];
            present.insert(q);
          }
      }

    CHECK(lattice.n_particles() == present.size());
    CHECK(lattice.n_inside() == inside.size());
    // Lexicographic, i_0 fastest: the order of the keys reversed.
    const auto before = [](const Index &a, const Index &b) {
      for (int d = dim - 1; d >= 0; --d)
        if (a[d] != b[d])
          return a[d] < b[d];
      return false;
    };
    std::vector<Index> order(present.begin(), present.end());
    std::sort(order.begin(), order.end(), before);
    types::global_dof_index inside_count = 0;
    unsigned int            mismatches   = 0;
    for (types::global_dof_index k = 0; k < order.size(); ++k)
      {
        mismatches += lattice.number(order[k]) != k;
        mismatches += lattice.index(k) != order[k];
        const bool is_inside = inside.count(order[k]) == 1;
        mismatches += lattice.inside(order[k]) != is_inside;
        if (is_inside)
          mismatches += lattice.inside_number(order[k]) != inside_count++;
      }
    CHECK(mismatches == 0);
    // Absent points have no number.
    unsigned int absent = 0;
    for_each(radius + 2, [&](const Index &i) {
      if (present.count(i) == 0)
        {
          ++absent;
          mismatches += lattice.number(i) != ParticleLattice<dim>::invalid;
          mismatches += lattice.inside(i);
        }
    });
    CHECK(absent > 0);
    CHECK(mismatches == 0);

    // A line's runs: the run of a present point holds its number.
    unsigned int multi_run_lines = 0;
    for (const auto &p : order)
      {
        const auto line = lattice.line(p);
        mismatches += lattice.number(p) != line.origin + p[0];
        mismatches += lattice.number(p) < line.begin;
        mismatches += lattice.number(p) >= line.end;
        if (line.next_first != std::numeric_limits<int>::max())
          {
            ++multi_run_lines;
            Index next = p;
            next[0]    = line.next_first;
            Index gap  = p;
            gap[0]     = line.next_first - 1;
            mismatches += lattice.number(next) == ParticleLattice<dim>::invalid;
            mismatches += lattice.number(gap) != ParticleLattice<dim>::invalid;
          }
      }
    CHECK(mismatches == 0);
    CHECK(multi_run_lines > 0);
  }
} // namespace



TEST_CASE("particle lattice of a union of boxes", "[particles][unit]")
{
  check_lattice<2>(union_layout<2>(), 1. / 32, 3);
  check_lattice<2>(union_layout<2>(), 1. / 32, 6);
  check_lattice<3>(union_layout<3>(), 1. / 16, 2);
}

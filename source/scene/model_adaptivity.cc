#include <deal.II/base/mpi.h>

#include <ltn/scene/model_adaptivity.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace ltn
{
  template <int dim>
  ModelAdaptivity<dim>::ModelAdaptivity(const Geometry<dim> &geometry,
                                        const double         h0,
                                        const double         interaction_range,
                                        const std::vector<Box<dim>> &starts,
                                        const double                 margin)
    : body(geometry.body)
    , overlap_width(geometry.overlap_width)
    , tolerance(geometry.model_error_tolerance)
    , cycles(geometry.model_adaptivity_cycles)
    , size(h0 *
           std::ceil(std::max(geometry.overlap_width, interaction_range) / h0 -
                     1e-9))
    , grid(geometry.body, size)
    , region(grid.n_blocks(), false)
    , largest(grid.inside(interaction_range))
  {
    const double grow = overlap_width + margin;
    for (const Box<dim> &start : starts)
      {
        Box<dim> grown = start;
        for (unsigned int d = 0; d < dim; ++d)
          {
            grown.lower[d] -= grow;
            grown.upper[d] += grow;
          }
        const auto covered = grid.covering(grown);
        for (unsigned int k = 0; k < grid.n_blocks(); ++k)
          region[k] = region[k] || (covered[k] && largest[k]);
      }
  }



  template <int dim>
  void
  ModelAdaptivity<dim>::keep_away_from(const std::vector<Box<dim>> &keep_out)
  {
    const double tol = 1e-9 * size;
    for (unsigned int k = 0; k < grid.n_blocks(); ++k)
      {
        const Box<dim> b = grid.block(k);
        for (const Box<dim> &box : keep_out)
          {
            // The max-norm distance between the two closed boxes.
            double gap = 0;
            for (unsigned int d = 0; d < dim; ++d)
              gap = std::max(
                {gap, box.lower[d] - b.upper[d], b.lower[d] - box.upper[d]});
            if (gap <= overlap_width + tol && !region[k])
              largest[k] = false;
          }
      }
  }



  template <int dim>
  std::vector<Box<dim>>
  ModelAdaptivity<dim>::region_boxes() const
  {
    return grid.boxes(region);
  }



  template <int dim>
  std::vector<Box<dim>>
  ModelAdaptivity<dim>::largest_boxes() const
  {
    return grid.boxes(largest);
  }



  template <int dim>
  std::vector<double>
  ModelAdaptivity<dim>::block_indicators(const ModelErrorField<dim> &field,
                                         const MPI_Comm              comm) const
  {
    // A term at a point of U (within the collar's reach of its faces) goes
    // with the nearest block beyond U's faces: adding that block takes the
    // point out of E.
    const auto block_for = [&](const Point<dim> &x) {
      const unsigned int k = grid.block_of(x);
      if (!region[k])
        return k;
      unsigned int beyond  = k;
      double       nearest = std::numeric_limits<double>::infinity();
      for (const unsigned int n : grid.face_neighbours(k))
        if (!region[n] && grid.block(n).max_norm_distance(x) < nearest)
          {
            nearest = grid.block(n).max_norm_distance(x);
            beyond  = n;
          }
      return beyond;
    };
    std::vector<double> indicators(grid.n_blocks(), 0.),
      long_waves(grid.n_blocks(), 0.);
    for (std::size_t i = 0; i < field.points.size(); ++i)
      if (field.boundary_layer[i] == 0)
        indicators[block_for(field.points[i])] += field.indicator[i];
    for (std::size_t i = 0; i < field.long_wave_points.size(); ++i)
      long_waves[block_for(field.long_wave_points[i])] +=
        field.long_wave_terms[i];
    Utilities::MPI::sum(indicators, comm, indicators);
    Utilities::MPI::sum(long_waves, comm, long_waves);
    // The long waves' terms of a block may sum to less than zero (its
    // residual works against the representer there): such a block adds
    // nothing.
    for (unsigned int k = 0; k < grid.n_blocks(); ++k)
      indicators[k] += std::max(long_waves[k], 0.);
    return indicators;
  }



  template <int dim>
  bool
  ModelAdaptivity<dim>::adapt(const ModelErrorRecord    &estimate,
                              const std::vector<double> &indicators,
                              const unsigned int         cycle_number,
                              ModelCycleRecord          &cycle)
  {
    // Comparisons carry a relative margin, so that sums whose order
    // differs between rank counts decide alike.
    constexpr double margin  = 1e-12;
    const double     allowed = tolerance * estimate.norm;
    const double     squared = estimate.estimate * estimate.estimate;
    cycle.cycle              = cycle_number;
    cycle.blocks             = BlockGrid<dim>::count(region);
    cycle.estimate           = estimate.relative;
    cycle.estimate_absolute  = estimate.estimate;
    double coupling          = 0;
    for (unsigned int k = 0; k < grid.n_blocks(); ++k)
      if (region[k])
        coupling += indicators[k];
    cycle.estimate_coupling = std::sqrt(coupling);
    if (estimate.estimate <= allowed * (1 + margin))
      {
        cycle.stopped = "tolerance";
        return false;
      }
    if (cycle_number + 1 >= cycles)
      {
        cycle.stopped = "cycle limit";
        return false;
      }

    if (BlockGrid<dim>::count(region) == 0)
      {
        // No crack to start from: the blocks around the one of largest
        // indicator, three wide (a piece with part of S), within U_max.
        unsigned int top = grid.n_blocks();
        for (unsigned int k = 0; k < grid.n_blocks(); ++k)
          if (largest[k] && (top == grid.n_blocks() ||
                             indicators[k] > indicators[top] * (1 + margin)))
            top = k;
        if (top == grid.n_blocks())
          {
            cycle.stopped = "nothing to mark";
            return false;
          }
        const auto seed = grid.window(top, 1, largest);
        cycle.marked    = BlockGrid<dim>::count(seed);
        cycle.added     = grow(seed);
        return true;
      }

    // Candidates: the blocks of U_max sharing a face with U (the region
    // grows from its faces, a layer of blocks per cycle at most), largest
    // indicator first (ties by number).
    std::vector<unsigned int> candidates;
    for (unsigned int k = 0; k < grid.n_blocks(); ++k)
      if (largest[k] && !region[k])
        {
          bool on_face = false;
          for (const unsigned int n : grid.face_neighbours(k))
            on_face = on_face || region[n];
          if (on_face)
            candidates.push_back(k);
        }
    if (candidates.empty())
      {
        cycle.stopped = "nothing to mark";
        return false;
      }
    std::stable_sort(candidates.begin(),
                     candidates.end(),
                     [&](const unsigned int a, const unsigned int b) {
                       return indicators[a] > indicators[b];
                     });
    // What no block of U_max removes: the terms in blocks along the body's
    // faces, and those left in U (at its concave corners). The terms of
    // blocks beyond the candidates wait for the region to reach them.
    double fixed = 0;
    for (unsigned int k = 0; k < grid.n_blocks(); ++k)
      if (region[k] || !largest[k])
        fixed += indicators[k];
    if (fixed >= allowed * allowed * (1 - margin))
      {
        cycle.stopped = "unreachable";
        return false;
      }
    // The fewest blocks of largest indicator whose terms make up the
    // excess over the tolerance (Doerfler marking on the excess): the least
    // region that could meet the tolerance, were the terms of the blocks
    // added the only change (the next cycle sees the terms that move out).
    const double                 needed = squared - allowed * allowed;
    typename BlockGrid<dim>::Set marked(grid.n_blocks(), false);
    unsigned int                 n_marked = 0;
    double                       sum      = 0;
    for (const unsigned int k : candidates)
      {
        if (sum >= needed * (1 - margin) || indicators[k] <= 0)
          break;
        sum += indicators[k];
        marked[k] = true;
        ++n_marked;
      }
    cycle.marked = n_marked;
    cycle.added  = grow(marked);
    if (cycle.added == 0)
      {
        cycle.stopped = "nothing to mark";
        return false;
      }
    return true;
  }



  template <int dim>
  unsigned int
  ModelAdaptivity<dim>::grow(const typename BlockGrid<dim>::Set &marked)
  {
    typename BlockGrid<dim>::Set grown = region;
    for (unsigned int k = 0; k < grid.n_blocks(); ++k)
      grown[k] = grown[k] || marked[k];
    // A pocket of the body enclosed by the region (no block of it beyond
    // U_max) joins it: a local model there would only add an overlap.
    typename BlockGrid<dim>::Set outside(grid.n_blocks(), false);
    for (unsigned int k = 0; k < grid.n_blocks(); ++k)
      outside[k] = !grown[k];
    for (const auto &pocket : grid.pieces(outside))
      {
        bool enclosed = true;
        for (const unsigned int k : pocket)
          enclosed = enclosed && largest[k];
        if (enclosed)
          for (const unsigned int k : pocket)
            grown[k] = true;
      }
    const unsigned int added =
      BlockGrid<dim>::count(grown) - BlockGrid<dim>::count(region);
    region = grown;
    return added;
  }



  template class ModelAdaptivity<1>;
  template class ModelAdaptivity<2>;
  template class ModelAdaptivity<3>;
} // namespace ltn

// The particle operators' vectorized loops: the shared-stencil product and
// the scaled rows' corrections, with the block size and the rows fixed at
// compile time. The one file of the operator that CMake compiles for the
// building machine's vector instructions (LTN_NATIVE_KERNELS).

#include <ltn/nonlocal/lattice_operator.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <type_traits>

namespace ltn
{
  namespace
  {
    /**
     * Call `f(n_c, a0, a1)` with compile-time constants: the runtime block
     * size @p n, and the components `[a0, a1)` of @p rows for @p n_e
     * eliminated last components.
     */
    template <typename F>
    void
    with_block_size(const unsigned int n,
                    const unsigned int n_e,
                    const RowSubset    rows,
                    const F           &f)
    {
      const auto with_rows = [&](auto n_c) {
        constexpr int size = decltype(n_c)::value;
        using Size         = std::integral_constant<int, size>;
        using Zero         = std::integral_constant<int, 0>;
        if (rows == RowSubset::all || n_e == 0)
          {
            if (rows != RowSubset::eliminated)
              f(n_c, Zero(), Size());
            return;
          }
        AssertThrow(n_e == 1, ExcNotImplemented());
        using Last = std::integral_constant<int, size - 1>;
        if (rows == RowSubset::kept)
          f(n_c, Zero(), Last());
        else
          f(n_c, Last(), Size());
      };
      switch (n)
        {
          case 1:
            with_rows(std::integral_constant<int, 1>());
            break;
          case 2:
            with_rows(std::integral_constant<int, 2>());
            break;
          case 3:
            with_rows(std::integral_constant<int, 3>());
            break;
          case 4:
            with_rows(std::integral_constant<int, 4>());
            break;
          default:
            AssertThrow(false, ExcNotImplemented());
        }
    }
  } // namespace



  template <int dim>
  template <int n_c, int a0, int a1>
  void
  LatticeOperator<dim>::apply_scaled_rows(
    const std::array<const double *, 3> &x,
    const std::array<std::int64_t, 3>   &x_first,
    const bool                           transpose,
    double                              *y) const
  {
    const unsigned int     n_offsets  = offsets.size();
    constexpr unsigned int block_size = n_c * n_c;
    // The values of particle i, for a row or column of @p segment.
    const auto values_in = [&](const std::size_t segment) {
      const unsigned int source = segment_source[segment];
      return [values = x[source], start = x_first[source]](
               const std::int64_t i) { return values + (i - start) * n_c; };
    };
    if (!transpose)
      {
        // Row a of particle i, a0 <= a < a1: C_i x_i, then over its intact
        // bonds q_i (O_k x_j) summed apart from q_j (P_k x_j).
        constexpr unsigned int subset = (1u << a1) - (1u << a0);
        for (const auto &[s, segment] : scaled_owned)
          {
            const unsigned int used = scaled[s].rows & subset;
            if (used == 0)
              continue;
            const auto         value  = values_in(segment);
            const std::int64_t i      = scaled[s].number;
            const double      *xi     = value(i);
            const double      *centre = &scaled_centres[s * block_size];
            // A running sum per entry of the block, as in apply_stencil():
            // summed over b per bond, the rows spent their time in vector
            // shuffles.
            std::array<std::array<double, n_c>, n_c> own{}, partner{};
            for (int a = a0; a < a1; ++a)
              for (int b = 0; b < n_c; ++b)
                partner[a][b] = centre[a * n_c + b] * xi[b];
            const std::int64_t *origin = &bond_origin[segment * n_offsets];
            for (unsigned int k = 0; k < n_offsets; ++k)
              if (intact(s, k))
                {
                  const std::int64_t j   = origin[k] + i;
                  const double      *xj  = value(j);
                  const double       q_j = q_of(j);
                  const double      *O   = &own_blocks[k * block_size];
                  const double      *P   = &partner_blocks[k * block_size];
                  for (int a = a0; a < a1; ++a)
                    for (int b = 0; b < n_c; ++b)
                      {
                        own[a][b] += O[a * n_c + b] * xj[b];
                        partner[a][b] += q_j * P[a * n_c + b] * xj[b];
                      }
                }
            double *yi = y + (i - std::int64_t(first)) * n_c;
            for (int a = a0; a < a1; ++a)
              if ((used >> a) & 1u)
                {
                  double total = 0;
                  for (int b = 0; b < n_c; ++b)
                    total += scaled[s].q * own[a][b] + partner[a][b];
                  yi[a] += total;
                }
          }
        return;
      }
    // Column b of particle j, a0 <= b < a1 (the caller reads no other):
    // C_j^T x_j and, from each partner i = j + o_k with scaled rows, its
    // bond -o_k back to j, q_i O^T x_i plus q_j P^T x_i.
    for (const auto &[j, segment] : touched)
      {
        const auto              value = values_in(segment);
        std::array<double, n_c> own{}, partner{};
        if (const int s = scaled_index[j - reach_first];
            s >= 0 && scaled[s].rows != 0)
          {
            const double *xj     = value(j);
            const double *centre = &scaled_centres[s * block_size];
            for (int a = 0; a < n_c; ++a)
              if ((scaled[s].rows >> a) & 1u)
                for (int b = a0; b < a1; ++b)
                  own[b] += centre[a * n_c + b] * xj[a];
          }
        const std::int64_t *origin = &bond_origin[segment * n_offsets];
        const std::int64_t *lo     = &bond_lo[segment * n_offsets];
        const std::int64_t *hi     = &bond_hi[segment * n_offsets];
        for (unsigned int k = 0; k < n_offsets; ++k)
          {
            const std::int64_t i = origin[k] + j;
            if (i < lo[k] || i >= hi[k])
              continue;
            const int s = scaled_index[i - reach_first];
            if (s < 0 || scaled[s].rows == 0 || !intact(s, reverse[k]))
              continue;
            const double *xi  = value(i);
            const double *O   = &own_blocks[reverse[k] * block_size];
            const double *P   = &partner_blocks[reverse[k] * block_size];
            const double  q_i = scaled[s].q;
            for (int a = 0; a < n_c; ++a)
              if ((scaled[s].rows >> a) & 1u)
                for (int b = a0; b < a1; ++b)
                  {
                    own[b] += q_i * O[a * n_c + b] * xi[a];
                    partner[b] += P[a * n_c + b] * xi[a];
                  }
          }
        const double q_j = q_of(j);
        double      *yj  = y + (j - std::int64_t(first)) * n_c;
        for (int b = a0; b < a1; ++b)
          yj[b] += own[b] + q_j * partner[b];
      }
  }



  template <int dim>
  template <int n_c, bool transpose, int a0, int a1>
  void
  LatticeOperator<dim>::apply_stencil(
    const std::array<const double *, 3> &sources,
    const std::array<std::int64_t, 3>   &sources_first,
    const ParticleRanges                *within,
    double                              *y) const
  {
    const unsigned int     n_offsets = offsets.size();
    const unsigned char   *mask      = shared.data();
    const std::int64_t     base      = reach_first;
    constexpr unsigned int full      = (1u << n_c) - 1;
    // The rows a forward product computes.
    constexpr unsigned int asked = ((1u << a1) - 1) & ~((1u << a0) - 1);
    // The entries (a, b) of the blocks a product needs: the rows a of the
    // subset forward (of B_k), its columns b transposed (of B_{-k}^T, read
    // from the row-major B_{-k} as (b, a)). Transposed, a subset of more
    // than one column takes all n_c: rows of full width vectorize better
    // than the saved operations pay (on the 3D LPS stencil, 3 of 4 columns
    // cost 1.25 times all 4).
    constexpr bool narrow = !transpose || a1 - a0 == 1;
    constexpr int  r0 = transpose ? 0 : a0, r1 = transpose ? n_c : a1;
    constexpr int  c0 = narrow ? (transpose ? a0 : 0) : 0;
    constexpr int  c1 = narrow ? (transpose ? a1 : n_c) : n_c;
    // Per entry of the block, its own running sum over the bonds: a single
    // sum per row would chain every bond's additions one after the other
    // (their latency, not the multiplications, bounds the product).
    std::array<std::array<double, n_c>, n_c> sum;
    const auto                               add =
      [&sum](const double *block, const double *xj, const unsigned int used) {
        for (int a = r0; a < r1; ++a)
          {
            // Most particles have all rows shared: a predictable branch.
            if (used != full && !((used >> a) & 1u))
              continue;
            for (int b = c0; b < c1; ++b)
              sum[a][b] += block[a * n_c + b] * xj[transpose ? a : b];
          }
      };
    // Forward, several consecutive particles of a line with the same shared
    // rows at once: their bonds use the same blocks, and their partners are
    // consecutive too, so a group's values at the partners along one offset
    // are `group n_c` contiguous numbers, `width` vectors of `lanes`. Row a
    // of the group's product is their lane-wise product with row a of the
    // block tiled over the group (`tiled_blocks`), summed: one vector
    // multiply-add per row and vector, whatever n_c, and `width` independent
    // chains per row. The sums over each particle's components follow after
    // the last bond.
    //
    // A group is two vectors' worth of particles where its sums then fit in
    // 12 registers (at most 6 sums for a group of one vector: the 2D
    // products, the 3D dilatation rows), else one: each tiled row vector is
    // then loaded once for two of the group's vectors, and each row has
    // twice the chains. Four vectors gain nothing over two.
    using Lanes = double __attribute__((vector_size(lanes * sizeof(double))));
    constexpr int          n_rows = a1 - a0;
    constexpr unsigned int group  = (n_rows * n_c <= 6 ? 2 : 1) * lanes;
    constexpr int          width  = group * n_c / lanes;
    // The vectors of a tiled row; beyond them it repeats.
    constexpr int period = std::lcm(n_c, int(lanes)) / int(lanes);
    const auto    load   = [](const double *values) {
      Lanes v;
      std::memcpy(&v, values, sizeof(v));
      return v;
    };
    std::array<std::array<Lanes, width>, n_rows> group_sum;
    const auto add_group = [&](const unsigned int k, const double *xj) {
      const double *row = &tiled_blocks[(k * n_c + a0) * period * lanes];
      for (int w = 0; w < width; ++w)
        {
          const Lanes xw = load(xj + w * lanes);
          for (int r = 0; r < n_rows; ++r)
            group_sum[r][w] +=
              load(row + (r * period + w % period) * lanes) * xw;
        }
    };
    // The range of within that the segment's particles reach.
    std::size_t range = 0;
    for (std::size_t s = 0; s + 1 < segment_start.size(); ++s)
      {
        const std::int64_t *origin = &bond_origin[s * n_offsets];
        const std::int64_t *lo     = &bond_lo[s * n_offsets];
        const std::int64_t *hi     = &bond_hi[s * n_offsets];
        // The values of particle i at x + (i - x_first) n_c.
        const double      *x           = sources[segment_source[s]];
        const std::int64_t x_first     = sources_first[segment_source[s]];
        const std::int64_t segment_end = segment_start[s + 1];
        // The segment's particles [from, to) within, zero before them.
        std::int64_t next = segment_start[s];
        while (next < segment_end)
          {
            std::int64_t from = next, to = segment_end;
            if (within)
              {
                while (range < within->size() &&
                       (*within)[range].second <= next)
                  ++range;
                from = range < within->size() ?
                         std::clamp((*within)[range].first, next, segment_end) :
                         segment_end;
                to   = range < within->size() ?
                         std::min((*within)[range].second, segment_end) :
                         segment_end;
                for (std::int64_t i = next; i < from; ++i)
                  for (int a = a0; a < a1; ++a)
                    y[(i - std::int64_t(first)) * n_c + a] = 0.;
              }
            for (std::int64_t p = from; p < to; ++p)
              {
                const std::int64_t i    = p;
                const double      *xi   = x + (i - x_first) * n_c;
                const unsigned int rows = mask[i - base];
                if (!transpose && (rows & asked) == 0)
                  {
                    // None of the rows asked for is shared (the collar's first
                    // horizon in the displacement rows' product): they are the
                    // stored rows' alone.
                    double *yi =
                      y + (i - static_cast<std::int64_t>(first)) * n_c;
                    for (int a = a0; a < a1; ++a)
                      yi[a] = 0.;
                    continue;
                  }
                if (!transpose)
                  {
                    // A particle with any shared row has all its bonds. The run
                    // of particles from i on with a shared row asked for goes
                    // in groups, whatever their masks. Groups of equal masks
                    // had left the particles at a line's ends one at a time: a
                    // quarter of a dilatation pass on the 1e5 bar. The last
                    // group ends with the run, overlapping the one before it:
                    // both write the same values there.
                    std::int64_t run_end = i + 1;
                    while (run_end < to && (mask[run_end - base] & asked) != 0)
                      ++run_end;
                    if (run_end - i >= std::int64_t(group))
                      {
                        for (std::int64_t q = i; q < run_end; q += group)
                          {
                            const std::int64_t i0 =
                              std::min(q, run_end - group);
                            for (auto &row : group_sum)
                              row.fill(Lanes{});
                            add_group(n_offsets, x + (i0 - x_first) * n_c);
                            for (unsigned int k = 0; k < n_offsets; ++k)
                              add_group(k,
                                        x + (origin[k] + i0 - x_first) * n_c);
                            double *y0 =
                              y + (i0 - static_cast<std::int64_t>(first)) * n_c;
                            for (unsigned int g = 0; g < group; ++g)
                              {
                                const unsigned int shared = mask[i0 + g - base];
                                for (int r = 0; r < n_rows; ++r)
                                  {
                                    double total = 0;
                                    for (int b = 0; b < n_c; ++b)
                                      {
                                        const int m = g * n_c + b;
                                        total +=
                                          group_sum[r][m / lanes][m % lanes];
                                      }
                                    // A row that is not shared is the stored
                                    // rows' alone.
                                    y0[g * n_c + a0 + r] =
                                      (shared >> (a0 + r)) & 1u ? total : 0.;
                                  }
                              }
                          }
                        p = run_end - 1;
                        continue;
                      }
                  }
                for (auto &row : sum)
                  row.fill(0.);
                // Read per particle: hoisted out of the loops, it made GCC 12
                // compile a slower transposed product.
                const double *centre = &blocks[n_offsets * n_c * n_c];
                if (!transpose)
                  {
                    if (rows != 0)
                      {
                        add(centre, xi, rows);
                        for (unsigned int k = 0; k < n_offsets; ++k)
                          add(&blocks[k * n_c * n_c],
                              x + (origin[k] + i - x_first) * n_c,
                              rows);
                      }
                  }
                else if (interior[i - static_cast<std::int64_t>(first)])
                  {
                    // Every bond partner's rows are the shared ones.
                    add(centre, xi, full);
                    for (unsigned int k = 0; k < n_offsets; ++k)
                      add(&blocks[reverse[k] * n_c * n_c],
                          x + (origin[k] + i - x_first) * n_c,
                          full);
                  }
                else
                  {
                    // The partners' shared rows are the rows i reads.
                    if (rows != 0)
                      add(centre, xi, rows);
                    for (unsigned int k = 0; k < n_offsets; ++k)
                      {
                        const std::int64_t j = origin[k] + i;
                        if (j < lo[k] || j >= hi[k] || mask[j - base] == 0)
                          continue;
                        add(&blocks[reverse[k] * n_c * n_c],
                            x + (j - x_first) * n_c,
                            mask[j - base]);
                      }
                  }
                double *yi = y + (i - static_cast<std::int64_t>(first)) * n_c;
                for (int a = a0; a < a1; ++a)
                  {
                    double total = 0;
                    for (int b = 0; b < n_c; ++b)
                      total += transpose ? sum[b][a] : sum[a][b];
                    yi[a] = total;
                  }
              }
            next = std::max(from, to);
          }
      }
  }



  template <int dim>
  void
  LatticeOperator<dim>::apply_kernels(
    const std::array<const double *, 3> &x,
    const std::array<std::int64_t, 3>   &x_first,
    const bool                           transpose,
    const RowSubset                      rows,
    const ParticleRanges                *within,
    double                              *y) const
  {
    with_block_size(n_components,
                    n_eliminated_components,
                    rows,
                    [&](auto n_c, auto a0, auto a1) {
                      constexpr int n  = decltype(n_c)::value;
                      constexpr int r0 = decltype(a0)::value;
                      constexpr int r1 = decltype(a1)::value;
                      if (transpose)
                        apply_stencil<n, true, r0, r1>(x, x_first, within, y);
                      else
                        apply_stencil<n, false, r0, r1>(x, x_first, within, y);
                      if (!scaled_owned.empty() || !touched.empty())
                        apply_scaled_rows<n, r0, r1>(x, x_first, transpose, y);
                    });
  }



  template void
  LatticeOperator<2>::apply_kernels(const std::array<const double *, 3> &,
                                    const std::array<std::int64_t, 3> &,
                                    bool,
                                    RowSubset,
                                    const ParticleRanges *,
                                    double *) const;
  template void
  LatticeOperator<3>::apply_kernels(const std::array<const double *, 3> &,
                                    const std::array<std::int64_t, 3> &,
                                    bool,
                                    RowSubset,
                                    const ParticleRanges *,
                                    double *) const;
} // namespace ltn

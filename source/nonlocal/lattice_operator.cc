#include <deal.II/base/mpi.h>

#include <ltn/nonlocal/lattice_operator.h>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>

namespace ltn
{


  template <int dim>
  LatticeOperator<dim>::LatticeOperator(
    const ParticleLattice<dim>      &lattice,
    const std::vector<LatticeIndex> &offsets,
    const unsigned int               n_components,
    const unsigned int               n_eliminated_components,
    const IndexSet                  &owned_particles,
    const std::function<unsigned int(const LatticeIndex &)>    &shared_rows_of,
    const std::function<void(types::global_dof_index, Rows &)> &rows_of,
    const MPI_Comm                                              communicator,
    const ScaledBondRows<dim>                                  &scaled_rows)
    : lattice(lattice)
    , offsets(offsets)
    , n_components(n_components)
    , n_eliminated_components(n_eliminated_components)
    , communicator(communicator)
  {
    AssertThrow(owned_particles.is_contiguous(), ExcNotImplemented());
    first = owned_particles.is_empty() ? 0 : *owned_particles.begin();
    end   = first + owned_particles.n_elements();

    std::map<LatticeIndex, unsigned int> offset_number;
    for (unsigned int k = 0; k < offsets.size(); ++k)
      offset_number[offsets[k]] = k;
    for (const auto &o : offsets)
      {
        LatticeIndex minus;
        for (unsigned int d = 0; d < dim; ++d)
          minus[d] = -o[d];
        const auto found = offset_number.find(minus);
        AssertThrow(found != offset_number.end(),
                    ExcMessage("the bond offsets are not symmetric"));
        reverse.push_back(found->second);
      }

    // The range of numbers the bonds of this rank's particles reach.
    reach_first = first;
    reach_end   = end;
    {
      std::vector<std::int64_t> origin(offsets.size());
      std::vector<std::int64_t> lo(offsets.size()), hi(offsets.size());
      for (auto p = first; p < end;)
        {
          const auto q = bond_lines(p, origin, lo, hi);
          // Particles p..q - 1 reach along offset k the numbers origin_k +
          // p..q - 1, clipped to [lo_k, hi_k).
          for (std::size_t k = 0; k < offsets.size(); ++k)
            {
              const std::int64_t from =
                std::max<std::int64_t>(origin[k] + std::int64_t(p), lo[k]);
              const std::int64_t to =
                std::min<std::int64_t>(origin[k] + std::int64_t(q), hi[k]);
              if (from < to)
                {
                  reach_first =
                    std::min<types::global_dof_index>(reach_first, from);
                  reach_end = std::max<types::global_dof_index>(reach_end, to);
                }
            }
          p = q;
        }
    }

    all_rows = (1u << n_components) - 1;
    shared.resize(reach_end - reach_first);
    for (auto p = reach_first; p < reach_end; ++p)
      shared[p - reach_first] = shared_rows_of(lattice.index(p)) & all_rows;

    // Each component's shared row, read from the first particle that has it.
    blocks.assign((offsets.size() + 1) * n_components * n_components, 0.);
    Rows rows(n_components);
    for (unsigned int a = 0; a < n_components; ++a)
      {
        const auto reference =
          std::find_if(shared.begin(), shared.end(), [a](const auto mask) {
            return (mask >> a) & 1u;
          });
        if (reference == shared.end())
          continue;
        const types::global_dof_index p =
          reach_first + (reference - shared.begin());
        const LatticeIndex index = lattice.index(p);
        rows_of(p, rows);
        {
          for (const auto &[column, value] : rows[a])
            {
              const LatticeIndex other = lattice.index(column / n_components);
              LatticeIndex       o;
              bool               centre = true;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  o[d]   = other[d] - index[d];
                  centre = centre && o[d] == 0;
                }
              const auto found = offset_number.find(o);
              AssertThrow(centre || found != offset_number.end(),
                          ExcMessage("a shared row reads a particle that is "
                                     "not one of its bonds"));
              const std::size_t k = centre ? offsets.size() : found->second;
              blocks[(k * n_components + a) * n_components +
                     column % n_components] += value;
            }
        }
      }

    // Each row of each block tiled over the values of a group of particles
    // (apply_stencil()): entry m of row a of block k is (B_k)_{a, m mod n_c},
    // up to lcm(n_c, lanes), after which the pattern repeats.
    const unsigned int tiled_length = std::lcm(n_components, lanes);
    tiled_blocks.resize((offsets.size() + 1) * n_components * tiled_length);
    for (unsigned int row = 0; row < (offsets.size() + 1) * n_components; ++row)
      for (unsigned int m = 0; m < tiled_length; ++m)
        tiled_blocks[row * tiled_length + m] =
          blocks[row * n_components + m % n_components];

    const std::size_t         n_offsets = offsets.size();
    std::vector<std::int64_t> origin(n_offsets);
    std::vector<std::int64_t> lo(n_offsets), hi(n_offsets);
    for (auto p = first; p < end;)
      {
        segment_start.push_back(p);
        p = bond_lines(p, origin, lo, hi);
        bond_origin.insert(bond_origin.end(), origin.begin(), origin.end());
        bond_lo.insert(bond_lo.end(), lo.begin(), lo.end());
        bond_hi.insert(bond_hi.end(), hi.begin(), hi.end());
      }
    segment_start.push_back(end);

    // Particles whose rows and whose bond partners' rows are all shared:
    // the transposed product needs no tests there.
    interior.assign(end - first, false);
    for (std::size_t s = 0; s + 1 < segment_start.size(); ++s)
      for (auto p = segment_start[s]; p < segment_start[s + 1]; ++p)
        {
          const std::int64_t *origin     = &bond_origin[s * n_offsets];
          const std::int64_t *lo         = &bond_lo[s * n_offsets];
          const std::int64_t *hi         = &bond_hi[s * n_offsets];
          const std::int64_t  i          = p;
          bool                all_shared = shared[i - reach_first] == all_rows;
          for (unsigned int k = 0; k < offsets.size() && all_shared; ++k)
            {
              const std::int64_t j = origin[k] + i;
              all_shared =
                j >= lo[k] && j < hi[k] && shared[j - reach_first] == all_rows;
            }
          interior[p - first] = all_shared;
        }

    find_scaled_rows(scaled_rows, rows_of);

    // The other rows, stored.
    const types::global_dof_index n_dofs = n_components * lattice.n_particles();
    owned_dofs                           = IndexSet(n_dofs);
    owned_dofs.add_range(n_components * first, n_components * end);
    relevant = IndexSet(n_dofs);
    relevant.add_range(n_components * reach_first, n_components * reach_end);
    // Apart by subset: applied whole, the eliminated rows would be
    // computed twice per Schur complement product and the kept rows twice
    // (the caller discards each subset's other rows).
    const unsigned int eliminated_rows =
      all_rows & ~((1u << (n_components - n_eliminated_components)) - 1);
    // The identity rows (the collar's displacements, the dilatations of
    // particles with bonds leaving the lattice) apart from the matrices:
    // a product with them is a copy of owned values, where a matrix
    // imported its columns, the collar's values, first. They and the
    // scaled rows are computed, not stored.
    std::vector<unsigned char> computed(end - first, 0);
    IndexSet                   stored(lattice.n_particles());
    ParticleRows               particle_rows;
    for (auto p = first; p < end; ++p)
      if (const unsigned int own = all_rows & ~shared[p - reach_first])
        {
          const int s         = scaled_index[p - reach_first];
          computed[p - first] = s < 0 ? 0 : scaled[s].rows;
          n_own_rows += std::bitset<8>(own).count();
          rows_of(p, particle_rows);
          for (unsigned int c = 0; c < n_components; ++c)
            if ((own & ~computed[p - first]) >> c & 1u &&
                particle_rows[c].size() == 1 &&
                particle_rows[c][0].first == n_components * p + c &&
                particle_rows[c][0].second == 1.)
              {
                computed[p - first] |= 1u << c;
                identity_rows[(eliminated_rows >> c) & 1u].push_back(
                  n_components * (p - first) + c);
              }
          if (own & ~computed[p - first])
            stored.add_index(p);
        }
    stored.compress();
    IndexSet read;
    assemble_rows(
      stored,
      n_components,
      rows_of,
      [this, &computed](const types::global_dof_index p) {
        return all_rows & ~static_cast<unsigned int>(shared[p - reach_first]) &
               ~static_cast<unsigned int>(computed[p - first]);
      },
      {all_rows & ~eliminated_rows, eliminated_rows},
      true,
      owned_dofs,
      communicator,
      {&own_rows[0], &own_rows[1]},
      read);
    // The number of entries over all ranks: every rank skips a part alike
    // (its product imports ghost values, a collective step).
    for (const unsigned int part : {0u, 1u})
      {
        has_own_rows[part]   = own_rows[part].n_nonzero_elements() > 0;
        const IndexSet &rows = own_rows[part].locally_owned_range_indices();
        own_rows_values[part].reinit(rows, communicator);
        own_rows_entries[part].clear();
        for (const auto row : rows)
          own_rows_entries[part].push_back(row - n_components * first);
      }
    own_rows_transposed.reinit(owned_dofs, communicator);

    read_edges();
  }



  template <int dim>
  void
  LatticeOperator<dim>::read_edges()
  {
    // The particles a segment's bonds reach: along each offset, those of
    // the segment's partner line, clipped to that line's particles (an
    // absent partner is never read). Clipped to the whole reached range
    // instead, an absent line (past the lattice's box) stretched a range
    // over all the rank's particles, and each product copied all owned
    // values into `edges`.
    const std::size_t n_offsets = offsets.size();
    const auto        reads     = [&](const std::size_t s) {
      std::int64_t lowest  = segment_start[s],
                   highest = segment_start[s + 1] - 1;
      for (std::size_t k = 0; k < n_offsets; ++k)
        {
          const std::int64_t o = bond_origin[s * n_offsets + k];
          const std::int64_t lo =
            std::max<std::int64_t>(o + std::int64_t(segment_start[s]),
                                   bond_lo[s * n_offsets + k]);
          const std::int64_t hi =
            std::min<std::int64_t>(o + std::int64_t(segment_start[s + 1]),
                                   bond_hi[s * n_offsets + k]);
          if (lo < hi)
            {
              lowest  = std::min(lowest, lo);
              highest = std::max(highest, hi - 1);
            }
        }
      return std::make_pair(lowest, highest + 1);
    };
    const std::int64_t own_first = first, own_end = end;
    edge_ranges = {{{reach_first, reach_first}, {reach_end, reach_end}}};
    segment_source.assign(segment_start.size() - 1, 0);
    bool one_range = false;
    for (std::size_t s = 0; s + 1 < segment_start.size(); ++s)
      {
        const auto [lowest, past] = reads(s);
        const bool below          = lowest < own_first;
        const bool above          = past > own_end;
        one_range                 = one_range || (below && above);
        if (below)
          {
            segment_source[s]     = 1;
            edge_ranges[0].second = std::max(edge_ranges[0].second, past);
          }
        else if (above)
          {
            segment_source[s]    = 2;
            edge_ranges[1].first = std::min(edge_ranges[1].first, lowest);
          }
      }
    // A range so short that a segment reads past both ends, or the two
    // ranges overlapping: one range over all the reached particles.
    if (one_range || edge_ranges[0].second > edge_ranges[1].first)
      {
        edge_ranges = {{{reach_first, reach_end}, {reach_end, reach_end}}};
        for (auto &source : segment_source)
          source = source == 0 ? 0 : 1;
      }

    // Per range, the values below this rank's, its own, those above, in
    // that order; the other ranks' come through `ghosts`.
    const types::global_dof_index n_dofs = n_components * lattice.n_particles();
    IndexSet                      remote(n_dofs);
    std::size_t                   to = 0, ghost = 0;
    edge_pieces.clear();
    const auto add_piece = [&](const std::int64_t from_particle,
                               const std::int64_t past_particle,
                               const bool         is_remote) {
      if (from_particle >= past_particle)
        return;
      const std::size_t count = n_components * (past_particle - from_particle);
      if (is_remote)
        {
          remote.add_range(n_components * from_particle,
                           n_components * past_particle);
          edge_pieces.push_back({to, ghost, count, true});
          ghost += count;
        }
      else
        edge_pieces.push_back(
          {to,
           n_components * std::size_t(from_particle - own_first),
           count,
           false});
      to += count;
    };
    for (const auto &[from, past] : edge_ranges)
      {
        add_piece(from, std::min(past, own_first), true);
        add_piece(std::max(from, own_first), std::min(past, own_end), false);
        add_piece(std::max(from, own_end), past, true);
      }
    remote.compress();
    edges.assign(to, 0.);
    ghosts = std::make_unique<Epetra_Vector>(
      remote.make_trilinos_map(communicator, true));
    importer = std::make_unique<Epetra_Import>(
      ghosts->Map(),
      TrilinosWrappers::MPI::Vector(owned_dofs, communicator)
        .trilinos_vector()
        .Map());
  }



  template <int dim>
  types::global_dof_index
  LatticeOperator<dim>::bond_lines(const types::global_dof_index p,
                                   std::vector<std::int64_t>    &origin,
                                   std::vector<std::int64_t>    &lo,
                                   std::vector<std::int64_t>    &hi) const
  {
    const LatticeIndex index = lattice.index(p);
    const auto         line  = lattice.line(index);
    // The segment ends with the run of p, or where a neighbour along some
    // offset would enter the next run of its line: beyond that point the
    // neighbours' numbers no longer follow origin_k + i.
    types::global_dof_index segment_end = std::min(line.end, end);
    for (unsigned int k = 0; k < offsets.size(); ++k)
      {
        LatticeIndex neighbour = index;
        for (unsigned int d = 0; d < dim; ++d)
          neighbour[d] += offsets[k][d];
        const auto other = lattice.line(neighbour);
        origin[k]        = other.origin + offsets[k][0] - line.origin;
        lo[k]            = other.begin;
        hi[k]            = other.end;
        if (other.next_first != std::numeric_limits<int>::max())
          segment_end = std::min<types::global_dof_index>(
            segment_end, line.origin + other.next_first - offsets[k][0]);
      }
    return segment_end;
  }



  template <int dim>
  std::pair<std::array<const double *, 3>, std::array<std::int64_t, 3>>
  LatticeOperator<dim>::gather(const TrilinosWrappers::MPI::Vector &src) const
  {
    // With the plan built once: an import into a new vector would build it
    // anew in every product (a few per cent of a solve).
    const int error = ghosts->Import(src.trilinos_vector(), *importer, Insert);
    AssertThrow(error == 0, ExcMessage("importing a vector of other layout"));
    for (const EdgePiece &piece : edge_pieces)
      std::copy_n((piece.from_ghosts ? ghosts->Values() : src.begin()) +
                    piece.from,
                  piece.count,
                  edges.begin() + piece.to);
    const double *edge_values = edges.data();
    return {
      {{src.trilinos_vector()[0],
        edge_values,
        edge_values +
          n_components * (edge_ranges[0].second - edge_ranges[0].first)}},
      {{std::int64_t(first), edge_ranges[0].first, edge_ranges[1].first}}};
  }



  template <int dim>
  void
  LatticeOperator<dim>::vmult_rows(TrilinosWrappers::MPI::Vector       &dst,
                                   const TrilinosWrappers::MPI::Vector &src,
                                   const bool       transpose,
                                   const RowSubset  rows,
                                   const RowRanges *within) const
  {
    const auto  sources = gather(src);
    const auto &x       = sources.first;
    const auto &x_first = sources.second;
    // The particles of the rows within.
    ParticleRanges particles;
    if (within)
      for (const auto &[from, past] : *within)
        {
          const std::int64_t p = first + from / n_components,
                             q =
                               first + (past + n_components - 1) / n_components;
          if (!particles.empty() && particles.back().second >= p)
            particles.back().second = std::max(particles.back().second, q);
          else if (p < q)
            particles.emplace_back(p, q);
        }
    const ParticleRanges *particles_within = within ? &particles : nullptr;
    double               *y                = dst.trilinos_vector()[0];
    // Rows outside the subset keep whatever dst held; so do the stored rows
    // outside it, except in the transposed product, whose stored part sums
    // over all rows.
    apply_kernels(x, x_first, transpose, rows, particles_within, y);
    for (const unsigned int part : {0u, 1u})
      {
        const bool in_subset =
          rows == RowSubset::all ||
          (rows == RowSubset::kept ? part == 0 : part == 1);
        if (!transpose && !in_subset)
          continue;
        // An identity row's entry is its own column's: the same in M^T.
        for (const unsigned int i : identity_rows[part])
          dst.begin()[i] += src.begin()[i];
        if (!has_own_rows[part])
          continue;
        // The stored rows only: over all owned rows, most of them empty,
        // the products and their temporary vectors cost far more than the
        // few rows they hold.
        TrilinosWrappers::MPI::Vector &values  = own_rows_values[part];
        const auto                    &entries = own_rows_entries[part];
        if (transpose)
          {
            for (std::size_t i = 0; i < entries.size(); ++i)
              values.begin()[i] = src.begin()[entries[i]];
            own_rows[part].Tvmult(own_rows_transposed, values);
            dst += own_rows_transposed;
          }
        else
          {
            own_rows[part].vmult(values, src);
            for (std::size_t i = 0; i < entries.size(); ++i)
              dst.begin()[entries[i]] += values.begin()[i];
          }
      }
  }



  template <int dim>
  std::vector<RowRanges>
  LatticeOperator<dim>::rows_near(const TrilinosWrappers::MPI::Vector &marked,
                                  const unsigned int layers) const
  {
    const std::int64_t n_c     = n_components;
    const std::size_t  n_owned = end - first;
    // Per owned particle: is it in the layer? (Bytes, not bits: the test
    // below reads one per particle and offset.)
    std::vector<unsigned char> in_layer(n_owned);
    for (std::size_t p = 0; p < n_owned; ++p)
      in_layer[p] = std::any_of(marked.begin() + n_c * p,
                                marked.begin() + n_c * (p + 1),
                                [](const double value) { return value != 0.; });
    std::vector<RowRanges>        result;
    TrilinosWrappers::MPI::Vector indicator(marked);
    for (unsigned int layer = 0;; ++layer)
      {
        RowRanges &rows = result.emplace_back();
        for (std::size_t p = 0; p < n_owned; ++p)
          if (in_layer[p])
            {
              const auto position = static_cast<unsigned int>(n_c * p);
              if (!rows.empty() && rows.back().second == position)
                rows.back().second += n_c;
              else
                rows.emplace_back(position, position + n_c);
            }
        if (layer == layers)
          return result;

        // The next layer: the particles whose bonds reach this one (the
        // offsets are closed under negation: also those it reaches). The
        // layer is read, other ranks' particles included, from the first
        // component of an indicator vector.
        std::fill(indicator.begin(), indicator.end(), 0.);
        for (std::size_t p = 0; p < n_owned; ++p)
          indicator.begin()[n_c * p] = in_layer[p];
        const auto                 sources   = gather(indicator);
        std::vector<unsigned char> next      = in_layer;
        const std::size_t          n_offsets = offsets.size();
        for (std::size_t s = 0; s + 1 < segment_start.size(); ++s)
          {
            const double       *x       = sources.first[segment_source[s]];
            const std::int64_t  x_first = sources.second[segment_source[s]];
            const std::int64_t *origin  = &bond_origin[s * n_offsets];
            const std::int64_t *lo      = &bond_lo[s * n_offsets];
            const std::int64_t *hi      = &bond_hi[s * n_offsets];
            for (std::int64_t i = segment_start[s];
                 i < std::int64_t(segment_start[s + 1]);
                 ++i)
              for (std::size_t k = 0; k < n_offsets && !next[i - first]; ++k)
                {
                  const std::int64_t j = origin[k] + i;
                  if (j >= lo[k] && j < hi[k] && x[(j - x_first) * n_c] != 0.)
                    next[i - first] = 1;
                }
          }
        in_layer.swap(next);
      }
  }



  template <int dim>
  std::size_t
  LatticeOperator<dim>::memory_consumption() const
  {
    return shared.size() + interior.size() / 8 +
           (blocks.size() + tiled_blocks.size()) * sizeof(double) +
           own_rows[0].memory_consumption() +
           (bond_origin.size() + bond_lo.size() + bond_hi.size()) *
             sizeof(std::int64_t) +
           own_rows[1].memory_consumption() +
           (edges.size() + ghosts->MyLength()) * sizeof(double) +
           own_rows_values[0].memory_consumption() +
           own_rows_values[1].memory_consumption() +
           own_rows_transposed.memory_consumption() +
           (own_rows_entries[0].size() + own_rows_entries[1].size() +
            identity_rows[0].size() + identity_rows[1].size()) *
             sizeof(unsigned int) +
           scaled.size() * sizeof(ScaledParticle) +
           scaled_index.size() * sizeof(int) +
           scaled_bonds.size() * sizeof(std::uint64_t) +
           (scaled_centres.size() + own_blocks.size() + partner_blocks.size()) *
             sizeof(double) +
           (scaled_owned.size() + touched.size()) *
             sizeof(std::pair<std::int64_t, std::size_t>) +
           offsets.size() * sizeof(LatticeIndex);
  }



  template <int dim>
  const IndexSet &
  LatticeOperator<dim>::relevant_dofs() const
  {
    return relevant;
  }



  template <int dim>
  types::global_dof_index
  LatticeOperator<dim>::n_stored_rows() const
  {
    return Utilities::MPI::sum(n_own_rows, communicator);
  }



  template <int dim>
  types::global_dof_index
  LatticeOperator<dim>::n_scaled_rows() const
  {
    return Utilities::MPI::sum(n_scaled, communicator);
  }



  template <int dim>
  types::global_dof_index
  LatticeOperator<dim>::n_compressed_rows() const
  {
    return Utilities::MPI::sum(types::global_dof_index(
                                 own_rows_entries[0].size() +
                                 own_rows_entries[1].size()),
                               communicator);
  }

  template <int dim>
  void
  store_particle_operator(
    const ParticleLattice<dim>                                     &lattice,
    const std::vector<typename ParticleLattice<dim>::LatticeIndex> &offsets,
    const unsigned int n_components,
    const unsigned int n_eliminated_components,
    const IndexSet    &owned_particles,
    const std::function<unsigned int(
      const typename ParticleLattice<dim>::LatticeIndex &)> &shared_rows_of,
    const std::function<void(types::global_dof_index, ParticleRows &)> &rows_of,
    const bool                 matrix_free,
    DiscreteModel             &model,
    const ScaledBondRows<dim> &scaled_rows)
  {
    if (matrix_free)
      {
        const auto op =
          std::make_shared<LatticeOperator<dim>>(lattice,
                                                 offsets,
                                                 n_components,
                                                 n_eliminated_components,
                                                 owned_particles,
                                                 shared_rows_of,
                                                 rows_of,
                                                 model.communicator,
                                                 scaled_rows);
        model.relevant    = op->relevant_dofs();
        model.matrix_free = op;
        model.matrix.clear();
      }
    else
      {
        model.matrix_free.reset();
        assemble_rows(
          owned_particles,
          n_components,
          rows_of,
          [n_components](types::global_dof_index) {
            return (1u << n_components) - 1;
          },
          {(1u << n_components) - 1},
          false,
          model.owned,
          model.communicator,
          {&model.matrix},
          model.relevant);
      }
  }

#define LTN_INSTANTIATE(dim)                                              \
  template class LatticeOperator<dim>;                                    \
  template void store_particle_operator<dim>(                             \
    const ParticleLattice<dim> &,                                         \
    const std::vector<typename ParticleLattice<dim>::LatticeIndex> &,     \
    const unsigned int,                                                   \
    const unsigned int,                                                   \
    const IndexSet &,                                                     \
    const std::function<unsigned int(                                     \
      const typename ParticleLattice<dim>::LatticeIndex &)> &,            \
    const std::function<void(types::global_dof_index, ParticleRows &)> &, \
    const bool,                                                           \
    DiscreteModel &,                                                      \
    const ScaledBondRows<dim> &);
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

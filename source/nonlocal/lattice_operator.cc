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
  namespace
  {
    /**
     * The doubles of the vectors the forward stencil product works on: one
     * AVX2 register (two SSE2 ones), and the number of particles it takes at
     * a time.
     */
    constexpr unsigned int lanes = 4;
  } // namespace



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
    for (auto p = first; p < end;)
      {
        const LatticeIndex index = lattice.index(p);
        const auto         line  = lattice.line(index);
        for (const auto &o : offsets)
          {
            LatticeIndex neighbour = index;
            for (unsigned int d = 0; d < dim; ++d)
              neighbour[d] += o[d];
            const auto other = lattice.line(neighbour);
            if (other.begin == other.end)
              continue;
            // Particles p..min(line end, end) - 1 reach along this offset
            // numbers origin + o_0 + i_0, clipped to the other line.
            const std::int64_t from =
              other.origin + o[0] +
              (static_cast<std::int64_t>(p) - line.origin);
            const std::int64_t to =
              from + static_cast<std::int64_t>(std::min(line.end, end)) -
              static_cast<std::int64_t>(p);
            const std::int64_t lo = std::max<std::int64_t>(from, other.begin);
            const std::int64_t hi = std::min<std::int64_t>(to, other.end);
            if (lo < hi)
              {
                reach_first =
                  std::min<types::global_dof_index>(reach_first, lo);
                reach_end = std::max<types::global_dof_index>(reach_end, hi);
              }
          }
        p = std::min(line.end, end);
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
    // imported its columns, the collar's values, first (with it, Epetra's
    // CopyAndPermute went from 4.8 % to 3.9 % of a run of the 1e5 bar of
    // benchmarks/scaling on two ranks). They and the scaled rows are
    // computed, not stored.
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
    // values into `edges`: 3.3 % of a run of the 10^6 bar (perf).
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
  bool
  LatticeOperator<dim>::intact(const std::size_t s, const unsigned int k) const
  {
    return (scaled_bonds[s * words_per_particle + k / 64] >> (k % 64)) & 1u;
  }



  template <int dim>
  double
  LatticeOperator<dim>::q_of(const std::int64_t j) const
  {
    const int s = scaled_index[j - reach_first];
    return s < 0 ? 1. : scaled[s].q;
  }



  namespace
  {
    /** `q_i`, `q_j` or their mean, as @p scale says. */
    template <typename Scale>
    double
    scale_of(const Scale scale, const double q_i, const double q_j)
    {
      return scale == Scale::own     ? q_i :
             scale == Scale::partner ? q_j :
                                       0.5 * (q_i + q_j);
    }
  } // namespace



  template <int dim>
  void
  LatticeOperator<dim>::find_scaled_rows(
    const ScaledBondRows<dim>                                  &scaled_rows,
    const std::function<void(types::global_dof_index, Rows &)> &rows_of)
  {
    scaled_index.assign(reach_end - reach_first, -1);
    if (!scaled_rows.bonds_of)
      return;
    const unsigned int n_c = n_components, n_offsets = offsets.size();
    const unsigned int block_size = n_c * n_c;
    AssertThrow(scaled_rows.bond_scale.size() == block_size &&
                  scaled_rows.centre_scale.size() == block_size &&
                  scaled_rows.centre_sign.size() == block_size,
                ExcMessage("a scaling table is not one per block entry"));
    scaling            = scaled_rows;
    scaling.bonds_of   = nullptr;
    words_per_particle = (n_offsets + 63) / 64;

    // Every particle's q first: a row reads its partners'. One whose rows
    // are all the shared ones has all its bonds, and q = 1.
    std::vector<bool> bonds;
    const auto        neighbour_of = [&](const types::global_dof_index p,
                                  const unsigned int            k) {
      LatticeIndex neighbour = lattice.index(p);
      for (unsigned int d = 0; d < dim; ++d)
        neighbour[d] += offsets[k][d];
      return lattice.number(neighbour);
    };
    for (auto p = reach_first; p < reach_end; ++p)
      {
        double q;
        if (shared[p - reach_first] == all_rows ||
            !scaled_rows.bonds_of(lattice.index(p), bonds, q))
          continue;
        AssertDimension(bonds.size(), n_offsets);
        scaled_index[p - reach_first] = scaled.size();
        scaled.push_back({std::int64_t(p), q, 0});
        scaled_bonds.resize(scaled.size() * words_per_particle, 0);
        for (unsigned int k = 0; k < n_offsets; ++k)
          if (bonds[k])
            scaled_bonds[(scaled.size() - 1) * words_per_particle + k / 64] |=
              std::uint64_t(1) << (k % 64);
      }
    // q of any particle: past the reached range (the partners of a ghost
    // particle) asked of the model.
    const auto q_at = [&](const types::global_dof_index j) {
      if (j >= reach_first && j < reach_end)
        return q_of(j);
      double q;
      return scaled_rows.bonds_of(lattice.index(j), bonds, q) ? q : 1.;
    };

    // B_k split by the number its entries scale with: O_k by q_i (half of
    // the mean's), P_k by q_j (the other half).
    own_blocks.assign(n_offsets * block_size, 0.);
    partner_blocks.assign(n_offsets * block_size, 0.);
    for (unsigned int k = 0; k < n_offsets; ++k)
      for (unsigned int e = 0; e < block_size; ++e)
        {
          const double entry             = blocks[k * block_size + e];
          const auto   scale             = scaled_rows.bond_scale[e];
          using Scale                    = typename ScaledBondRows<dim>::Scale;
          own_blocks[k * block_size + e] = scale == Scale::own  ? entry :
                                           scale == Scale::mean ? 0.5 * entry :
                                                                  0.;
          partner_blocks[k * block_size + e] =
            scale == Scale::partner ? entry :
            scale == Scale::mean    ? 0.5 * entry :
                                      0.;
        }

    // C0 = C - sigma o sum_k B_k.
    std::vector<double> centre0(blocks.begin() + n_offsets * block_size,
                                blocks.end());
    for (unsigned int k = 0; k < n_offsets; ++k)
      for (unsigned int e = 0; e < block_size; ++e)
        centre0[e] -= scaled_rows.centre_sign[e] * blocks[k * block_size + e];

    // Each row that equals the model's own is computed.
    scaled_centres.assign(scaled.size() * block_size, 0.);
    Rows                                                    rows(n_c);
    std::vector<std::pair<types::global_dof_index, double>> formula, model;
    for (std::size_t s = 0; s < scaled.size(); ++s)
      {
        const types::global_dof_index i      = scaled[s].number;
        const double                  q_i    = scaled[s].q;
        double                       *centre = &scaled_centres[s * block_size];
        std::copy(centre0.begin(), centre0.end(), centre);
        std::vector<std::pair<types::global_dof_index, double>> partners;
        for (unsigned int k = 0; k < n_offsets; ++k)
          if (intact(s, k))
            {
              const auto j = neighbour_of(i, k);
              AssertThrow(j != ParticleLattice<dim>::invalid,
                          ExcMessage("an intact bond leaves the lattice"));
              const double q_j = q_at(j);
              partners.emplace_back(j, q_j);
              for (unsigned int e = 0; e < block_size; ++e)
                centre[e] += scaled_rows.centre_sign[e] *
                             scale_of(scaled_rows.centre_scale[e], q_i, q_j) *
                             blocks[k * block_size + e];
            }
        rows_of(i, rows);
        for (unsigned int a = 0; a < n_c; ++a)
          {
            if ((shared[i - reach_first] >> a) & 1u)
              continue;
            formula.clear();
            for (unsigned int b = 0; b < n_c; ++b)
              formula.emplace_back(n_c * i + b, centre[a * n_c + b]);
            unsigned int bond = 0;
            for (unsigned int k = 0; k < n_offsets; ++k)
              if (intact(s, k))
                {
                  const auto [j, q_j] = partners[bond++];
                  for (unsigned int b = 0; b < n_c; ++b)
                    formula.emplace_back(
                      n_c * j + b,
                      scale_of(scaled_rows.bond_scale[a * n_c + b], q_i, q_j) *
                        blocks[(k * n_c + a) * n_c + b]);
                }
            model = rows[a];
            // Equal up to round-off, entries absent from one being zeros of
            // the other.
            const auto by_column = [](const auto &x, const auto &y) {
              return x.first < y.first;
            };
            std::sort(formula.begin(), formula.end(), by_column);
            std::sort(model.begin(), model.end(), by_column);
            double largest = 0;
            for (const auto &entry : model)
              largest = std::max(largest, std::abs(entry.second));
            bool equal = true;
            auto f = formula.begin(), m = model.begin();
            while (equal && (f != formula.end() || m != model.end()))
              {
                double difference;
                if (m == model.end() ||
                    (f != formula.end() && f->first < m->first))
                  difference = (f++)->second;
                else if (f == formula.end() || m->first < f->first)
                  difference = (m++)->second;
                else
                  difference = (f++)->second - (m++)->second;
                equal = std::abs(difference) <= 1e-12 * largest;
              }
            if (equal && largest > 0)
              scaled[s].rows |= 1u << a;
          }
      }

    // Only the particles with scaled rows or a q other than 1 (but for
    // round-off) kept: the others (the collar's, whose rows are
    // identities) would hold a bond mask and a centre each for nothing.
    std::size_t kept = 0;
    for (std::size_t s = 0; s < scaled.size(); ++s)
      {
        scaled_index[scaled[s].number - reach_first] = -1;
        if (scaled[s].rows == 0 && std::abs(scaled[s].q - 1.) < 1e-12)
          continue;
        scaled[kept] = scaled[s];
        std::copy_n(&scaled_bonds[s * words_per_particle],
                    words_per_particle,
                    &scaled_bonds[kept * words_per_particle]);
        std::copy_n(&scaled_centres[s * block_size],
                    block_size,
                    &scaled_centres[kept * block_size]);
        scaled_index[scaled[s].number - reach_first] = kept++;
      }
    scaled.resize(kept);
    scaled.shrink_to_fit();
    scaled_bonds.resize(kept * words_per_particle);
    scaled_bonds.shrink_to_fit();
    scaled_centres.resize(kept * block_size);
    scaled_centres.shrink_to_fit();

    // This rank's particles with scaled rows, and those a scaled row reads.
    const auto segment_of = [this](const std::int64_t p) {
      return std::size_t(std::upper_bound(segment_start.begin(),
                                          segment_start.end(),
                                          types::global_dof_index(p)) -
                         segment_start.begin() - 1);
    };
    std::vector<std::int64_t> read;
    for (std::size_t s = 0; s < scaled.size(); ++s)
      {
        if (scaled[s].rows == 0)
          continue;
        const std::int64_t i = scaled[s].number;
        if (i >= std::int64_t(first) && i < std::int64_t(end))
          {
            scaled_owned.emplace_back(s, segment_of(i));
            n_scaled += std::bitset<8>(scaled[s].rows).count();
            read.push_back(i);
          }
        for (unsigned int k = 0; k < n_offsets; ++k)
          if (intact(s, k))
            {
              const std::int64_t j = neighbour_of(i, k);
              if (j >= std::int64_t(first) && j < std::int64_t(end))
                read.push_back(j);
            }
      }
    std::sort(read.begin(), read.end());
    read.erase(std::unique(read.begin(), read.end()), read.end());
    for (const std::int64_t j : read)
      touched.emplace_back(j, segment_of(j));
  }



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
            // summed over b per bond, the rows took 9 % of a run of the 1e5
            // bar in shuffles.
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
  types::global_dof_index
  LatticeOperator<dim>::bond_lines(const types::global_dof_index p,
                                   std::vector<std::int64_t>    &origin,
                                   std::vector<std::int64_t>    &lo,
                                   std::vector<std::int64_t>    &hi) const
  {
    const LatticeIndex index = lattice.index(p);
    const auto         line  = lattice.line(index);
    for (unsigned int k = 0; k < offsets.size(); ++k)
      {
        LatticeIndex neighbour = index;
        for (unsigned int d = 0; d < dim; ++d)
          neighbour[d] += offsets[k][d];
        const auto other = lattice.line(neighbour);
        origin[k]        = other.origin + offsets[k][0] - line.origin;
        lo[k]            = other.begin;
        hi[k]            = other.end;
      }
    return std::min(line.end, end);
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
    // twice the chains. On the 2D plate the product took 17 % less time;
    // with four vectors, no less than with two.
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
                // compile the transposed product 30 % slower.
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
    with_block_size(
      n_components,
      n_eliminated_components,
      rows,
      [&](auto n_c, auto a0, auto a1) {
        constexpr int n  = decltype(n_c)::value;
        constexpr int r0 = decltype(a0)::value;
        constexpr int r1 = decltype(a1)::value;
        if (transpose)
          apply_stencil<n, true, r0, r1>(x, x_first, particles_within, y);
        else
          apply_stencil<n, false, r0, r1>(x, x_first, particles_within, y);
      });
    if (!scaled_owned.empty() || !touched.empty())
      with_block_size(n_components,
                      n_eliminated_components,
                      rows,
                      [&](auto n_c, auto a0, auto a1) {
                        apply_scaled_rows<decltype(n_c)::value,
                                          decltype(a0)::value,
                                          decltype(a1)::value>(x,
                                                               x_first,
                                                               transpose,
                                                               y);
                      });
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
        // the products and their temporary vectors took 16 % of a run of
        // the 1e5 bar (perf).
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

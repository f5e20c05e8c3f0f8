// Which particles of a lattice operator have rows other than the shared
// stencil's: those scaled per particle (the LPS dilatation's and the bonds
// near cracks and the collar's edge), found once when the operator is built.

#include <ltn/nonlocal/lattice_operator.h>

#include <algorithm>
#include <bitset>
#include <map>

namespace ltn
{
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



  template void
  LatticeOperator<2>::find_scaled_rows(
    const ScaledBondRows<2> &,
    const std::function<void(types::global_dof_index, Rows &)> &);
  template void
  LatticeOperator<3>::find_scaled_rows(
    const ScaledBondRows<3> &,
    const std::function<void(types::global_dof_index, Rows &)> &);
} // namespace ltn

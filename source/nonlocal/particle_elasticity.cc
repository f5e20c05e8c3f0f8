#include <ltn/nonlocal/collar_trace.h>
#include <ltn/nonlocal/lattice_operator.h>
#include <ltn/nonlocal/particle_elasticity.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace ltn
{
  template <int dim>
  ParticleElasticity<dim>::ParticleElasticity(
    const Geometry<dim>           &geometry,
    const Kernel                  &influence,
    const double                   spacing,
    const double                   lambda,
    const double                   mu,
    const std::vector<Crack<dim>> &cracks,
    const MPI_Comm                 communicator)
    : Base(
        geometry,
        influence,
        spacing,
        2 * influence.horizon(),
        [](const PeridynamicStencil<dim> &stencil) {
          return stencil.two_bond_reach();
        },
        communicator)
    , eps(influence.horizon())
    , coefficient_A(dim * (lambda - mu))
    , coefficient_B(dim * (dim + 2) * mu)
    , cracks(cracks)
  {
    for (const auto &crack : cracks)
      {
        Box<dim> box = crack.bounding_box();
        for (unsigned int d = 0; d < dim; ++d)
          {
            box.lower[d] -= eps + spacing;
            box.upper[d] += eps + spacing;
          }
        crack_neighbourhoods.push_back(box);
      }
    has_cut_bond.resize(lattice.n_particles());
    std::vector<bool> intact;
    for (types::global_dof_index n = 0; n < lattice.n_particles(); ++n)
      {
        const LatticeIndex index = lattice.index(n);
        if (!near_crack(lattice.position(index)))
          continue;
        // A bond is not intact when it is cut or reaches no particle.
        const double m = intact_bonds(index, intact);
        for (std::size_t k = 0; k < intact.size() && !has_cut_bond[n]; ++k)
          {
            LatticeIndex neighbour = index;
            for (unsigned int d = 0; d < dim; ++d)
              neighbour[d] += stencil.offsets()[k][d];
            has_cut_bond[n] = !intact[k] && lattice.number(neighbour) !=
                                              ParticleLattice<dim>::invalid;
          }
        if (has_cut_bond[n])
          cut_weighted_volume[n] = m;
      }

    // The dilatation is an unknown only where its sum is complete.
    for (const auto n : owned_particles)
      if (!complete(lattice.index(n)))
        model.fixed.add_index(dof(n, dim));
    model.fixed.compress();
  }



  template <int dim>
  bool
  ParticleElasticity<dim>::is_cut(const Point<dim> &x,
                                  const Point<dim> &y) const
  {
    const double tol = geometry.tolerance();
    for (std::size_t k = 0; k < cracks.size(); ++k)
      if (cracks[k].cuts(x, y, tol))
        return true;
    return false;
  }



  template <int dim>
  bool
  ParticleElasticity<dim>::complete(const LatticeIndex &index) const
  {
    for (const auto &o : stencil.offsets())
      {
        LatticeIndex neighbour = index;
        for (unsigned int d = 0; d < dim; ++d)
          neighbour[d] += o[d];
        if (lattice.number(neighbour) == ParticleLattice<dim>::invalid)
          return false;
      }
    return true;
  }



  template <int dim>
  bool
  ParticleElasticity<dim>::near_crack(const Point<dim> &x) const
  {
    for (const auto &box : crack_neighbourhoods)
      if (box.contains(x))
        return true;
    return false;
  }



  template <int dim>
  double
  ParticleElasticity<dim>::intact_bonds(const LatticeIndex &index,
                                        std::vector<bool>  &intact) const
  {
    const auto      &offsets = stencil.offsets();
    const auto      &weights = stencil.weights();
    const auto      &bonds   = stencil.bonds();
    const Point<dim> x       = lattice.position(index);
    const bool       near    = near_crack(x);
    intact.assign(offsets.size(), true);
    double m = 0;
    for (std::size_t k = 0; k < offsets.size(); ++k)
      {
        LatticeIndex neighbour = index;
        for (unsigned int d = 0; d < dim; ++d)
          neighbour[d] += offsets[k][d];
        // The neighbour's own position, so that both ends of a bond test
        // the same segment.
        intact[k] =
          lattice.number(neighbour) != ParticleLattice<dim>::invalid &&
          !(near && is_cut(x, lattice.position(neighbour)));
        if (intact[k])
          m += weights[k] * bonds[k].norm_square();
      }
    return m;
  }



  template <int dim>
  unsigned int
  ParticleElasticity<dim>::shared_rows(const LatticeIndex &index) const
  {
    const auto n = lattice.number(index);
    if (n == ParticleLattice<dim>::invalid || has_cut_bond[n])
      return 0;
    unsigned int rows = complete(index) ? 1u << dim : 0u;
    if (lattice.inside(index))
      {
        bool neighbours_intact = true;
        for (const auto &o : stencil.offsets())
          {
            LatticeIndex neighbour = index;
            for (unsigned int d = 0; d < dim; ++d)
              neighbour[d] += o[d];
            neighbours_intact =
              neighbours_intact && !has_cut_bond[lattice.number(neighbour)];
          }
        if (neighbours_intact)
          rows |= (1u << dim) - 1;
      }
    return rows;
  }



  template <int dim>
  ScaledBondRows<dim>
  ParticleElasticity<dim>::scaled_bond_rows() const
  {
    // With q = m / m_i (doc/discretization.md, 'Matrix-free particle
    // operators'): the bond
    // stiffness scales with (1/m_i + 1/m_j), so the displacement blocks
    // by the mean of q_i and q_j; a displacement row reads the partner's
    // dilatation over m_j and its own over m_i; the dilatation row is
    // over m_i. The centre sums the displacement blocks with the opposite
    // sign, the dilatation's columns of a displacement row with the same.
    using Scale             = typename ScaledBondRows<dim>::Scale;
    const unsigned int  n_c = n_components;
    ScaledBondRows<dim> rows;
    rows.bond_scale.assign(n_c * n_c, Scale::own);
    rows.centre_scale.assign(n_c * n_c, Scale::own);
    rows.centre_sign.assign(n_c * n_c, 0);
    for (unsigned int a = 0; a < n_c; ++a)
      for (unsigned int b = 0; b < n_c; ++b)
        {
          const unsigned int e = a * n_c + b;
          if (a < dim && b < dim)
            {
              rows.bond_scale[e]   = Scale::mean;
              rows.centre_scale[e] = Scale::mean;
              rows.centre_sign[e]  = -1;
            }
          else if (a < dim)
            {
              rows.bond_scale[e]  = Scale::partner;
              rows.centre_sign[e] = 1;
            }
          else if (b < dim)
            rows.centre_sign[e] = -1;
        }
    rows.bonds_of =
      [this](const LatticeIndex &index, std::vector<bool> &intact, double &q) {
        if (!complete(index))
          return false;
        const double m = intact_bonds(index, intact);
        q              = stencil.weighted_volume() / m;
        return m > 0;
      };
    return rows;
  }



  template <int dim>
  void
  ParticleElasticity<dim>::particle_rows(const types::global_dof_index n,
                                         Rows &rows) const
  {
    const auto &offsets = stencil.offsets();
    const auto &weights = stencil.weights();
    const auto &bonds   = stencil.bonds();
    // The dilatation's rows are scaled to the size of the displacement's.
    const double theta_scale = coefficient_B / dim;

    rows.resize(n_components);
    for (auto &row : rows)
      row.clear();
    const LatticeIndex index       = lattice.index(n);
    const bool         fixed_theta = !complete(index);
    const bool         free_u      = lattice.inside(index);
    for (unsigned int c = 0; c < dim; ++c)
      if (!free_u)
        rows[c].emplace_back(dof(n, c), 1.);
    if (fixed_theta)
      rows[dim].emplace_back(dof(n, dim), 1.);
    if (!free_u && fixed_theta)
      return;

    std::vector<bool> intact;
    const double      m_i = intact_bonds(index, intact);
    if (!fixed_theta)
      rows[dim].emplace_back(dof(n, dim), theta_scale);
    for (std::size_t k = 0; k < offsets.size(); ++k)
      if (intact[k])
        {
          LatticeIndex neighbour = index;
          for (unsigned int d = 0; d < dim; ++d)
            neighbour[d] += offsets[k][d];
          const auto           j  = lattice.number(neighbour);
          const Tensor<1, dim> xi = bonds[k];
          if (!fixed_theta)
            for (unsigned int b = 0; b < dim; ++b)
              {
                const double v = theta_scale * dim * weights[k] * xi[b] / m_i;
                rows[dim].emplace_back(dof(j, b), -v);
                rows[dim].emplace_back(dof(n, b), v);
              }
          if (!free_u)
            continue;
          // Neighbours of a particle of Omega_n are complete: without a
          // cut bond their weighted volume is the stencil's.
          const double m_j = has_cut_bond[j] ? cut_weighted_volume.at(j) :
                                               stencil.weighted_volume();
          const double bond_stiffness =
            weights[k] * coefficient_B * (1 / m_i + 1 / m_j) / xi.norm_square();
          for (unsigned int a = 0; a < dim; ++a)
            {
              for (unsigned int b = 0; b < dim; ++b)
                {
                  const double v = bond_stiffness * xi[a] * xi[b];
                  rows[a].emplace_back(dof(n, b), v);
                  rows[a].emplace_back(dof(j, b), -v);
                }
              rows[a].emplace_back(dof(n, dim),
                                   -weights[k] * coefficient_A * xi[a] / m_i);
              rows[a].emplace_back(dof(j, dim),
                                   -weights[k] * coefficient_A * xi[a] / m_j);
            }
        }
    // One entry per column.
    for (auto &row : rows)
      {
        std::sort(row.begin(), row.end(), [](const auto &x, const auto &y) {
          return x.first < y.first;
        });
        std::size_t last = 0;
        for (std::size_t e = 1; e < row.size(); ++e)
          if (row[e].first == row[last].first)
            row[last].second += row[e].second;
          else
            row[++last] = row[e];
        row.resize(row.empty() ? 0 : last + 1);
      }
  }



  template <int dim>
  void
  ParticleElasticity<dim>::assemble(const Function<dim> &body_force,
                                    const Function<dim> &volume_data,
                                    const bool           matrix_free)
  {
    store_particle_operator<dim>(
      lattice,
      stencil.offsets(),
      n_components,
      1,
      owned_particles,
      [this](const LatticeIndex &index) { return shared_rows(index); },
      [this](const types::global_dof_index n, Rows &rows) {
        particle_rows(n, rows);
      },
      matrix_free,
      model,
      scaled_bond_rows());

    // The surrogate for AMG: the Laplacian on the lattice, for each
    // displacement component, scaled to the diagonal of the displacement
    // rows, without the bonds cracks cut.
    const double diagonal = [&] {
      double sum = 0;
      for (std::size_t k = 0; k < stencil.bonds().size(); ++k)
        sum += 2 * stencil.weights()[k] * coefficient_B /
               stencil.weighted_volume() * stencil.bonds()[k][0] *
               stencil.bonds()[k][0] / stencil.bonds()[k].norm_square();
      return sum;
    }();
    // The collar's layers as a shear wave along an axis sees them: a
    // displacement across axis 0 that varies along it, u = f(x_0) e_1,
    // changes no dilatation, and each bond reaching m layers along axis 0
    // weighs it by c_j (xi_j)_1^2 / |xi_j|^2.
    const std::vector<double> projected =
      axis_projection(stencil.offsets(), [&](const std::size_t k) {
        return stencil.weights()[k] * stencil.bonds()[k][1] *
               stencil.bonds()[k][1] / stencil.bonds()[k].norm_square();
      });
    this->offer_lattice(diagonal,
                        coefficient_B / (dim * (dim + 2)), // the shear modulus
                        collar_trace_weights(projected),
                        [this](const Point<dim> &x, const Point<dim> &y) {
                          return near_crack(x) && is_cut(x, y);
                        });
    model.eliminated = IndexSet(model.owned.size());
    for (const auto n : owned_particles)
      model.eliminated.add_index(dof(n, dim));
    model.eliminated.compress();
    // The displacement rows are the gradient of an energy
    // (doc/discretization.md, 'Linearized peridynamics (LPS) on
    // particles'): with the dilatation eliminated, the free
    // block is its Hessian.
    model.symmetric_free_block = true;

    this->assemble_load(body_force, volume_data);
  }



  template <int dim>
  double
  ParticleElasticity<dim>::horizon() const
  {
    return eps;
  }



  template <int dim>
  std::vector<double>
  ParticleElasticity<dim>::owned_broken_bond_fractions() const
  {
    std::vector<double> result;
    for (const auto n : owned_particles)
      {
        const Point<dim> x      = lattice.position(lattice.index(n));
        unsigned int     broken = 0;
        if (near_crack(x))
          {
            std::vector<bool> intact;
            intact_bonds(lattice.index(n), intact);
            for (std::size_t k = 0; k < intact.size(); ++k)
              {
                LatticeIndex neighbour = lattice.index(n);
                for (unsigned int d = 0; d < dim; ++d)
                  neighbour[d] += stencil.offsets()[k][d];
                // Only bonds to particles that exist can be broken.
                broken += !intact[k] && lattice.number(neighbour) !=
                                          ParticleLattice<dim>::invalid ?
                            1 :
                            0;
              }
          }
        result.push_back(static_cast<double>(broken) / stencil.bonds().size());
      }
    return result;
  }



  template <int dim>
  typename ParticleElasticity<dim>::CrackOpening
  ParticleElasticity<dim>::crack_opening(
    const TrilinosWrappers::MPI::Vector &field,
    const unsigned int                   k) const
  {
    AssertIndexRange(k, cracks.size());
    const Crack<dim>    &crack = cracks[k];
    const Tensor<1, dim> n     = crack.normal();
    const double         tol   = 1e-6 * spacing;
    // Per particle next to the crack: its point on the crack, its side and
    // its normal displacement.
    std::vector<std::array<double, dim + 2>> samples;
    for (const auto number : owned_particles)
      {
        const Point<dim> x = lattice.position(lattice.index(number));
        const double     s = crack.signed_distance(x);
        if (std::abs(std::abs(s) - spacing / 2) > tol)
          continue;
        const Point<dim> on_crack = x - s * n;
        bool             inside   = true;
        for (const double t : crack.edge_coordinates(on_crack))
          inside = inside && t > -tol && t < 1 + tol;
        if (!inside)
          continue;
        std::array<double, dim + 2> sample;
        for (unsigned int d = 0; d < dim; ++d)
          sample[d] = on_crack[d];
        double normal_displacement = 0;
        for (unsigned int d = 0; d < dim; ++d)
          normal_displacement += n[d] * field(dof(number, d));
        sample[dim]     = s > 0 ? 1 : -1;
        sample[dim + 1] = normal_displacement;
        samples.push_back(sample);
      }
    std::vector<std::array<double, dim + 2>> all;
    for (const auto &part :
         Utilities::MPI::all_gather(model.communicator, samples))
      all.insert(all.end(), part.begin(), part.end());

    // Pair the two sides by their point on the crack, ordered along it.
    const auto key = [&](const std::array<double, dim + 2> &sample) {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = sample[d];
      std::vector<long> rounded;
      for (const double t : crack.edge_coordinates(p))
        rounded.push_back(std::lround(t * 1e6));
      return rounded;
    };
    std::map<std::vector<long>, std::array<double, 2>> sides;
    std::map<std::vector<long>, Point<dim>>            points;
    for (const auto &sample : all)
      {
        const auto k_sample = key(sample);
        auto      &entry    = sides
                        .emplace(k_sample,
                                 std::array<double, 2>{
                                   {std::numeric_limits<double>::quiet_NaN(),
                                    std::numeric_limits<double>::quiet_NaN()}})
                        .first->second;
        entry[sample[dim] > 0 ? 0 : 1] = sample[dim + 1];
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = sample[d];
        points[k_sample] = p;
      }
    CrackOpening result;
    for (const auto &[k_pair, values] : sides)
      if (!std::isnan(values[0]) && !std::isnan(values[1]))
        {
          result.points.push_back(points[k_pair]);
          result.opening.push_back(values[0] - values[1]);
        }
    return result;
  }

  template class ParticleElasticity<2>;
  template class ParticleElasticity<3>;
} // namespace ltn

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <ltn/nonlocal/particle_diffusion.h>
#include <ltn/nonlocal/particle_elasticity.h>
#include <ltn/scene/model_error.h>

#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace ltn
{
  namespace
  {
    /**
     * The particle model's operator on a field given at its field
     * components: the eliminated components (the LPS dilatation, whose rows
     * define it from the displacements alone: one diagonal entry each)
     * completed from the field first, so that `apply` is the operator with
     * them eliminated.
     */
    class FieldOperator
    {
    public:
      explicit FieldOperator(const DiscreteModel &model)
        : model(model)
      {
        if (model.eliminated.n_elements() == 0)
          return;
        auto ones = model.new_vector(), product = model.new_vector();
        for (const auto i : model.eliminated)
          ones(i) = 1;
        ones.compress(VectorOperation::insert);
        model.vmult(product, ones);
        for (const auto i : model.eliminated)
          eliminated_diagonal[i] = product(i);
      }

      /** Set the eliminated components of @p w from its others and @p rhs. */
      void
      complete(TrilinosWrappers::MPI::Vector       &w,
               const TrilinosWrappers::MPI::Vector &rhs) const
      {
        if (eliminated_diagonal.empty())
          return;
        for (const auto &[i, d] : eliminated_diagonal)
          w(i) = 0;
        w.compress(VectorOperation::insert);
        auto product = model.new_vector();
        model.vmult(product, w);
        for (const auto &[i, d] : eliminated_diagonal)
          w(i) = (rhs(i) - product(i)) / d;
        w.compress(VectorOperation::insert);
      }

      /** `dst = M w` with the eliminated components of @p w completed. */
      void
      apply(TrilinosWrappers::MPI::Vector       &dst,
            TrilinosWrappers::MPI::Vector       &w,
            const TrilinosWrappers::MPI::Vector &rhs) const
      {
        complete(w, rhs);
        model.vmult(dst, w);
      }

    private:
      const DiscreteModel                      &model;
      std::map<types::global_dof_index, double> eliminated_diagonal;
    };

    /**
     * The finite element field @p field (ghosted) at the point of unit
     * coordinates @p unit of a cell with the degrees of freedom
     * @p cell_dofs: one value per component (at most three).
     */
    template <int dim>
    std::array<double, 3>
    value_in_cell(const FiniteElement<dim>                   &fe,
                  const std::vector<types::global_dof_index> &cell_dofs,
                  const TrilinosWrappers::MPI::Vector        &field,
                  const Point<dim>                           &unit)
    {
      std::array<double, 3> value{};
      for (unsigned int k = 0; k < cell_dofs.size(); ++k)
        {
          const unsigned int c = fe.system_to_component_index(k).first;
          value[c] +=
            field(cell_dofs[k]) * fe.shape_value_component(k, unit, c);
        }
      return value;
    }



    /**
     * The vector over @p owned holding the sums of @p entries (global index,
     * value), which this rank may hold for indices other ranks own.
     * Collective.
     */
    TrilinosWrappers::MPI::Vector
    sum_of_entries(
      const IndexSet                                                &owned,
      const std::vector<std::pair<types::global_dof_index, double>> &entries,
      const MPI_Comm                                                 comm)
    {
      IndexSet written(owned.size());
      for (const auto &entry : entries)
        written.add_index(entry.first);
      written.compress();
      written.subtract_set(owned);
      TrilinosWrappers::MPI::Vector sums;
      sums.reinit(owned, written, comm, true);
      for (const auto &[i, value] : entries)
        sums(i) += value;
      sums.compress(VectorOperation::add);
      TrilinosWrappers::MPI::Vector result(owned, comm);
      result = sums;
      return result;
    }



    /**
     * `eta_1` (doc/model_adaptivity.md, 'From residual to energy'): the
     * load `F_k = sum_i V r_i . phi_k(x_i)` of the residual @p residual (on
     * the lattice's particles, @p n_field components, `dof(n, c)` their
     * numbers) on the finite elements of @p representer, zero in its fixed
     * and constrained rows; `z` from `M z = F` (`M` has identity rows
     * there, so `z` is zero on the Dirichlet faces); `eta_1^2 = F . z`, and
     * the terms `V r_i . z(x_i)` into @p field.
     */
    template <int dim, typename Dof>
    double
    long_wave_estimate(const ParticleLattice<dim>          &lattice,
                       const TrilinosWrappers::MPI::Vector &residual,
                       const double                         volume,
                       const DoFHandler<dim>               &dofs,
                       const DiscreteModel                 &representer,
                       const double                         tol,
                       const Dof                           &dof,
                       const unsigned int                   n_field,
                       ModelErrorOperators                 &operators,
                       ModelErrorField<dim>                *field)
    {
      const MPI_Comm comm = representer.communicator;
      AssertThrow(Utilities::MPI::sum(representer.constrained.n_elements(),
                                      comm) == 0,
                  ExcMessage("The error representer needs a mesh without "
                             "hanging nodes."));
      const auto &fe = dofs.get_fe();
      // The particles in this rank's cells, found once: each with its
      // cell and its unit coordinates there.
      struct Visit
      {
        typename DoFHandler<dim>::active_cell_iterator cell;
        types::global_dof_index                        n;
        Point<dim>                                     x, unit;
      };
      std::vector<Visit> visits;
      IndexSet           needed(residual.size());
      for_each_in_owned_cells(
        lattice,
        dofs,
        tol,
        [&](const auto       &cell,
            const auto       &index,
            const auto        n,
            const Point<dim> &unit) {
          visits.push_back({cell, n, lattice.position(index), unit});
          for (unsigned int c = 0; c < n_field; ++c)
            needed.add_index(dof(n, c));
        });
      // The residual there.
      needed.compress();
      needed.add_indices(residual.locally_owned_elements());
      TrilinosWrappers::MPI::Vector r(residual.locally_owned_elements(),
                                      needed,
                                      comm);
      r = residual;

      std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
      std::vector<std::pair<types::global_dof_index, double>> loads;
      for (const Visit &visit : visits)
        {
          visit.cell->get_dof_indices(cell_dofs);
          for (unsigned int k = 0; k < cell_dofs.size(); ++k)
            {
              const unsigned int c     = fe.system_to_component_index(k).first;
              const double       value = r(dof(visit.n, c));
              if (value != 0)
                loads.emplace_back(
                  cell_dofs[k],
                  volume * value * fe.shape_value_component(k, visit.unit, c));
            }
        }
      TrilinosWrappers::MPI::Vector F = representer.new_vector();
      F = sum_of_entries(representer.owned, loads, comm);
      for (const auto i : representer.fixed)
        F(i) = 0;
      F.compress(VectorOperation::insert);

      TrilinosWrappers::MPI::Vector z = representer.new_vector();
      if (!operators.representer_solver)
        operators.representer_solver = std::make_shared<const DirectSolver>(
          representer.matrix,
          0.5,
          DirectSolver::Symmetry::general,
          DirectSolver::Ordering::nested_dissection);
      operators.representer_solver->solve(z, F);
      const double eta_1_squared = F * z;

      if (field)
        {
          const TrilinosWrappers::MPI::Vector z_ghosted =
            representer.ghosted(z);
          for (const Visit &visit : visits)
            {
              visit.cell->get_dof_indices(cell_dofs);
              const std::array<double, 3> z_at =
                value_in_cell(fe, cell_dofs, z_ghosted, visit.unit);
              double term = 0;
              for (unsigned int c = 0; c < n_field; ++c)
                term += volume * r(dof(visit.n, c)) * z_at[c];
              if (term != 0)
                {
                  field->long_wave_points.push_back(visit.x);
                  field->long_wave_terms.push_back(term);
                }
            }
        }
      return std::sqrt(std::max(eta_1_squared, 0.));
    }
  } // namespace



  template <int dim, typename ParticleModel>
  ModelErrorRecord
  estimate_model_error(const Geometry<dim>                 &geometry,
                       const ParticleModel                 *coupled,
                       const TrilinosWrappers::MPI::Vector &nonlocal_field,
                       const DoFHandler<dim>               &local_dofs,
                       const TrilinosWrappers::MPI::Vector &local_field,
                       const ParticleModel                 &reference,
                       const double                         interaction_range,
                       const std::array<bool, 2 * dim>     &dirichlet_faces,
                       const TrilinosWrappers::MPI::Vector *reference_solution,
                       const TrilinosWrappers::MPI::Vector *region_reference,
                       const DoFHandler<dim>               *representer_dofs,
                       const DiscreteModel                 *representer,
                       ModelErrorOperators                 &operators,
                       ModelErrorField<dim>                *field)
  {
    using LatticeIndex             = typename ParticleModel::LatticeIndex;
    constexpr unsigned int n_comp  = ParticleModel::n_components;
    constexpr unsigned int n_field = ParticleModel::n_field_components;
    const DiscreteModel   &model   = reference.get_model();
    const auto            &lattice = reference.get_lattice();
    const auto            &region  = geometry.nonlocal_region();
    const MPI_Comm         comm    = model.communicator;
    const double           tol     = geometry.tolerance();
    const double           volume  = reference.particle_volume();
    const auto             dof     = [](const auto n, const unsigned int c) {
      return ParticleModel::dof(n, c);
    };

    // Without a coupled nonlocal model the region is empty.
    const auto in_region = [&](const Point<dim> &x) {
      return coupled && region.contains_strictly(x, tol);
    };
    // The coupled lattice is the reference's shifted by whole spacings.
    LatticeIndex zero{}, one{};
    one[0]               = 1;
    const double spacing = lattice.position(one)[0] - lattice.position(zero)[0];
    LatticeIndex shift{};
    if (coupled)
      for (unsigned int d = 0; d < dim; ++d)
        shift[d] = static_cast<int>(
          std::round((lattice.position(zero)[d] -
                      coupled->get_lattice().position(zero)[d]) /
                     spacing));

    // The composite field: the volume constraint beyond the body, u_n on
    // Omega_n (read through ghosts), u_l elsewhere (below).
    TrilinosWrappers::MPI::Vector w = model.new_vector();
    std::vector<std::pair<types::global_dof_index, types::global_dof_index>>
                   from_coupled;
    const IndexSet coupled_owned =
      coupled ? coupled->get_model().owned : IndexSet(0);
    IndexSet needed(coupled_owned.size());
    for (const auto i : model.owned)
      {
        if (i % n_comp != 0)
          continue;
        const auto         n     = i / n_comp;
        const LatticeIndex index = lattice.index(n);
        const Point<dim>   x     = lattice.position(index);
        if (reference.role(index) == DofRole::fixed)
          for (unsigned int c = 0; c < n_field; ++c)
            w(dof(n, c)) = model.rhs(dof(n, c));
        else if (in_region(x))
          {
            LatticeIndex at = index;
            for (unsigned int d = 0; d < dim; ++d)
              at[d] += shift[d];
            const auto m = coupled->get_lattice().number(at);
            AssertThrow(m != ParticleLattice<dim>::invalid, ExcInternalError());
            for (unsigned int c = 0; c < n_field; ++c)
              {
                from_coupled.emplace_back(dof(n, c), dof(m, c));
                needed.add_index(dof(m, c));
              }
          }
      }
    if (coupled)
      {
        needed.compress();
        needed.add_indices(coupled_owned);
        TrilinosWrappers::MPI::Vector coupled_values(coupled_owned,
                                                     needed,
                                                     comm);
        coupled_values = nonlocal_field;
        for (const auto &[i, j] : from_coupled)
          w(i) = coupled_values(j);
      }
    w.compress(VectorOperation::insert);

    // u_l at the lattice points of the body outside Omega_n, each in the
    // local cell that holds it, added on the rank that owns the point.
    const auto &fe = local_dofs.get_fe();
    std::vector<std::pair<types::global_dof_index, double>> local_values;
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for_each_in_owned_cells(lattice,
                            local_dofs,
                            tol,
                            [&](const auto                   &cell,
                                const LatticeIndex           &index,
                                const types::global_dof_index n,
                                const Point<dim>             &unit) {
                              const Point<dim> x = lattice.position(index);
                              if (reference.role(index) == DofRole::fixed ||
                                  in_region(x))
                                return;
                              cell->get_dof_indices(cell_dofs);
                              const std::array<double, 3> value =
                                value_in_cell(fe, cell_dofs, local_field, unit);
                              for (unsigned int c = 0; c < n_field; ++c)
                                local_values.emplace_back(dof(n, c), value[c]);
                            });
    w += sum_of_entries(model.owned, local_values, comm);

    const FieldOperator operator_of_field(model);
    const auto          no_data       = model.new_vector();
    const auto          is_free_field = [&](const types::global_dof_index i) {
      return i % n_comp < n_field && model.role(i) == DofRole::free;
    };

    // chi and c_G, unless known.
    if (operators.chi == 0)
      {
        // chi: probes one particle in every K^dim block of the lattice, K
        // beyond twice the stencil's reach, so that each probe's row sees
        // only itself; the value most probes share is that of the uncut
        // interior (rows next to cracks and the body's faces differ).
        const unsigned int reach =
          static_cast<unsigned int>(std::ceil(2 * interaction_range / spacing));
        const int block = 2 * reach + 1;
        auto      probe = model.new_vector(), probed = model.new_vector();
        for (const auto i : model.owned)
          if (i % n_comp == 0 && is_free_field(i))
            {
              const LatticeIndex index = lattice.index(i / n_comp);
              bool               on    = true;
              for (unsigned int d = 0; d < dim; ++d)
                on = on && ((index[d] % block) + block) % block == 0;
              if (on)
                probe(i) = 1;
            }
        probe.compress(VectorOperation::insert);
        operator_of_field.apply(probed, probe, no_data);
        std::vector<double> diagonals;
        for (const auto i : model.owned)
          if (probe(i) == 1)
            diagonals.push_back(probed(i));
        std::vector<double> all;
        for (const auto &part : Utilities::MPI::all_gather(comm, diagonals))
          all.insert(all.end(), part.begin(), part.end());
        std::sort(all.begin(), all.end());
        AssertThrow(!all.empty(), ExcInternalError());
        double       chi  = all.front();
        unsigned int most = 0;
        for (std::size_t k = 0; k < all.size();)
          {
            std::size_t end = k;
            while (end < all.size() &&
                   all[end] - all[k] <= 1e-10 * std::abs(all[k]))
              ++end;
            if (end - k > most)
              {
                most = end - k;
                chi  = all[k];
              }
            k = end;
          }


        // c_G: the largest eigenvalue of the operator on the free field
        // components over chi, by the power method.
        std::mt19937                           random(17);
        std::uniform_real_distribution<double> uniform(-1, 1);
        auto                                   v      = model.new_vector();
        double                                 lambda = 0;
        for (unsigned int iteration = 0; iteration < 40; ++iteration)
          {
            if (iteration == 0)
              for (const auto i : model.owned)
                v(i) = is_free_field(i) ? uniform(random) : 0.;
            v.compress(VectorOperation::insert);
            v /= v.l2_norm();
            auto y = model.new_vector();
            operator_of_field.apply(y, v, no_data);
            double vy = 0;
            for (const auto i : model.owned)
              if (is_free_field(i))
                vy += v(i) * y(i);
            lambda = Utilities::MPI::sum(vy, comm);
            for (const auto i : model.owned)
              v(i) = is_free_field(i) ? y(i) : 0.;
          }
        operators.c_G = lambda / chi;
        operators.chi = chi;
      }
    const double chi = operators.chi, c_G = operators.c_G;

    // The estimate over E: the free points within the interaction range of
    // the body outside Omega_n whose reach stays inside the body. Within
    // that range of a Dirichlet face the residual is the two problems' own
    // difference there (a volume constraint against a boundary value),
    // which no nonlocal region short of the face removes: reported apart.
    // Next to other faces no nonlocal reference exists: not estimated.
    ModelErrorRecord record;
    record.computed             = true;
    record.chi                  = chi;
    record.c_G                  = c_G;
    double                  sum = 0, boundary_sum = 0, energy = 0, largest = -1;
    Point<dim>              largest_at;
    types::global_dof_index n_points      = 0;
    TrilinosWrappers::MPI::Vector applied = model.new_vector();
    operator_of_field.apply(applied, w, model.rhs);
    // The residual at the points of E (the long waves' load), zero
    // elsewhere.
    TrilinosWrappers::MPI::Vector residual_on_e = model.new_vector();
    // The scale: the energy of the composite field's free part, `V w_f^T
    // A_ff w_f` (the norm the error is measured in, of the field itself).
    auto free_part = w, free_applied = model.new_vector();
    for (const auto i : model.owned)
      if (!is_free_field(i))
        free_part(i) = 0;
    free_part.compress(VectorOperation::insert);
    operator_of_field.apply(free_applied, free_part, no_data);
    for (const auto i : model.owned)
      {
        if (i % n_comp != 0 || !is_free_field(i))
          continue;
        const auto       n = i / n_comp;
        const Point<dim> x = lattice.position(lattice.index(n));
        for (unsigned int c = 0; c < n_field; ++c)
          energy += volume * free_part(dof(n, c)) * free_applied(dof(n, c));
        if (coupled &&
            region.depth(x, 2 * interaction_range) > interaction_range + tol)
          continue;
        bool near_face = false, near_other_face = false;
        for (unsigned int f = 0; f < 2 * dim; ++f)
          if (std::abs(x[f / 2] - (f % 2 == 0 ? geometry.body.lower[f / 2] :
                                                geometry.body.upper[f / 2])) <
              interaction_range)
            {
              near_face       = true;
              near_other_face = near_other_face || !dirichlet_faces[f];
            }
        if (near_other_face)
          continue;
        double squared = 0;
        for (unsigned int c = 0; c < n_field; ++c)
          {
            const double r = model.rhs(dof(n, c)) - applied(dof(n, c));
            squared += r * r;
            if (!near_face)
              residual_on_e(dof(n, c)) = r;
          }
        const double contribution = volume * squared / chi / c_G;
        if (field)
          {
            field->points.push_back(x);
            field->indicator.push_back(contribution);
            field->boundary_layer.push_back(near_face ? 1. : 0.);
          }
        if (near_face)
          {
            boundary_sum += contribution;
            continue;
          }
        sum += contribution;
        ++n_points;
        if (contribution > largest)
          {
            largest    = contribution;
            largest_at = x;
          }
      }
    residual_on_e.compress(VectorOperation::insert);
    record.estimate_short = std::sqrt(Utilities::MPI::sum(sum, comm));
    if (representer)
      record.estimate_long = long_wave_estimate(lattice,
                                                residual_on_e,
                                                volume,
                                                *representer_dofs,
                                                *representer,
                                                tol,
                                                dof,
                                                n_field,
                                                operators,
                                                field);
    record.estimate = std::hypot(record.estimate_short, record.estimate_long);
    record.boundary_layer = std::sqrt(Utilities::MPI::sum(boundary_sum, comm));
    const double scale =
      std::sqrt(std::max(Utilities::MPI::sum(energy, comm), 1e-300));
    record.relative = record.estimate / scale;
    record.n_points = Utilities::MPI::sum(n_points, comm);
    record.norm     = scale;
    // The energy of `reference - w` on the free field components, with the
    // dilatation eliminated.
    const auto error_norm = [&](const TrilinosWrappers::MPI::Vector &other) {
      auto error = other, error_applied = model.new_vector();
      for (const auto i : model.owned)
        error(i) = is_free_field(i) ? error(i) - w(i) : 0.;
      error.compress(VectorOperation::insert);
      operator_of_field.apply(error_applied, error, no_data);
      double error_energy = 0;
      for (const auto i : model.owned)
        if (is_free_field(i))
          error_energy += volume * error(i) * error_applied(i);
      return std::sqrt(std::max(Utilities::MPI::sum(error_energy, comm), 0.));
    };
    // The error against @p other, relative, and the estimate's effectivity.
    const auto measure = [&](const TrilinosWrappers::MPI::Vector *other,
                             bool                                &has,
                             double                              &error,
                             double                              &relative,
                             double                              &effectivity) {
      if (!other)
        return;
      has         = true;
      error       = error_norm(*other);
      relative    = error / scale;
      effectivity = record.estimate / std::max(error, 1e-300);
    };
    measure(reference_solution,
            record.has_true_error,
            record.true_error,
            record.true_relative,
            record.effectivity);
    measure(region_reference,
            record.has_region_error,
            record.region_error,
            record.region_relative,
            record.region_effectivity);
    if (field)
      field->composite = w;
    // The largest contribution and its point, the same on every rank.
    const auto all_largest =
      Utilities::MPI::all_gather(comm, std::make_pair(largest, largest_at));
    const auto top = std::max_element(all_largest.begin(),
                                      all_largest.end(),
                                      [](const auto &a, const auto &b) {
                                        return a.first < b.first;
                                      });
    record.largest = std::max(top->first, 0.);
    for (unsigned int d = 0; d < dim; ++d)
      record.largest_at.push_back(top->second[d]);
    return record;
  }

#define LTN_INSTANTIATE(dim, Model)               \
  template ModelErrorRecord estimate_model_error( \
    const Geometry<dim> &,                        \
    const Model *,                                \
    const TrilinosWrappers::MPI::Vector &,        \
    const DoFHandler<dim> &,                      \
    const TrilinosWrappers::MPI::Vector &,        \
    const Model &,                                \
    double,                                       \
    const std::array<bool, 2 * dim> &,            \
    const TrilinosWrappers::MPI::Vector *,        \
    const TrilinosWrappers::MPI::Vector *,        \
    const DoFHandler<dim> *,                      \
    const DiscreteModel *,                        \
    ModelErrorOperators &,                        \
    ModelErrorField<dim> *);
  LTN_INSTANTIATE(2, ParticleDiffusion<2>)
  LTN_INSTANTIATE(3, ParticleDiffusion<3>)
  LTN_INSTANTIATE(2, ParticleElasticity<2>)
  LTN_INSTANTIATE(3, ParticleElasticity<3>)
#undef LTN_INSTANTIATE
} // namespace ltn

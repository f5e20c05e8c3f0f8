#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_generator.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <ltn/nonlocal/gauss_jacobi.h>
#include <ltn/nonlocal/nonlocal_weak_form_1d.h>

#include <algorithm>
#include <cmath>

namespace ltn
{
  namespace
  {
    /**
     * The Lagrange basis of FE_Q(p) on the unit interval, evaluated directly
     * from its support points: the assembly evaluates it hundreds of
     * millions of times on fine levels, and this is several times cheaper
     * than FiniteElement::shape_value().
     */
    class LagrangeBasis1D
    {
    public:
      explicit LagrangeBasis1D(const FE_Q<1> &fe)
      {
        for (const Point<1> &p : fe.get_unit_support_points())
          nodes.push_back(p[0]);
        for (unsigned int k = 0; k < nodes.size(); ++k)
          {
            double denominator = 1;
            for (unsigned int m = 0; m < nodes.size(); ++m)
              if (m != k)
                denominator *= nodes[k] - nodes[m];
            inverse_denominators.push_back(1. / denominator);
          }
      }

      double
      value(const unsigned int k, const double t) const
      {
        double product = inverse_denominators[k];
        for (unsigned int m = 0; m < nodes.size(); ++m)
          if (m != k)
            product *= t - nodes[m];
        return product;
      }

    private:
      std::vector<double> nodes;
      std::vector<double> inverse_denominators;
    };

    /**
     * [lo, hi] cut at the points of @p kinks inside it (all of it without
     * kinks): the pieces on which a piecewise-affine weight is affine.
     */
    std::vector<std::pair<double, double>>
    pieces(const double lo, const double hi, const std::vector<double> &kinks)
    {
      std::vector<std::pair<double, double>> result;
      double                                 start = lo;
      for (const double k : kinks)
        if (k > start && k < hi)
          {
            result.emplace_back(start, k);
            start = k;
          }
      result.emplace_back(start, hi);
      return result;
    }
  } // namespace



  NonlocalWeakForm1D::NonlocalWeakForm1D(const Geometry<1> &geometry,
                                         const Kernel      &kernel,
                                         const unsigned int degree,
                                         const double       h)
    : geometry(geometry)
    , kernel(kernel)
    , fe(degree)
    , dof_handler(triangulation)
  {
    // One box in 1D (Geometry::parse_parameters()).
    const Box<1> region = geometry.nonlocal_region().bounding_box();
    const double a      = region.lower[0];
    const double b      = region.upper[0];
    const auto   n_collar =
      static_cast<unsigned int>(std::ceil(kernel.horizon() / h - 1e-10));
    const auto n_inside = static_cast<unsigned int>(std::round((b - a) / h));
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              std::vector<unsigned int>{
                                                n_inside + 2 * n_collar},
                                              Point<1>(a - n_collar * h),
                                              Point<1>(b + n_collar * h));
    dof_handler.distribute_dofs(fe);

    support_points.resize(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(MappingQ1<1>(),
                                         dof_handler,
                                         support_points);

    // Serial: every rank holds all of the 1D model.
    const auto n       = dof_handler.n_dofs();
    model.communicator = MPI_COMM_SELF;
    model.owned        = complete_index_set(n);
    model.relevant     = model.owned;
    model.controls     = IndexSet(n);
    model.fixed        = IndexSet(n);
    const double tol   = 1e-10 * h;
    for (types::global_dof_index i = 0; i < n; ++i)
      if (!geometry.nonlocal_region().contains_strictly(support_points[i], tol))
        (geometry.nonlocal_region_of(support_points[i], 0) ==
             Region::physical_collar ?
           model.fixed :
           model.controls)
          .add_index(i);
    model.locate_controls<1>(
      [&](const types::global_dof_index i) { return support_points[i]; },
      [](const types::global_dof_index) { return 0u; });
  }



  void
  NonlocalWeakForm1D::assemble(const Function<1> &rhs,
                               const Function<1> &volume_data)
  {
    assemble_pair_form(model.matrix, nullptr);
    assemble_rhs(rhs);

    // Close the model: identity rows for the collar.
    std::vector<types::global_dof_index> collar;
    for (const IndexSet *rows : {&model.fixed, &model.controls})
      collar.insert(collar.end(), rows->begin(), rows->end());
    model.matrix.clear_rows(collar, 1.);
    for (const auto i : model.controls)
      model.rhs(i) = 0;
    for (const auto i : model.fixed)
      model.rhs(i) = volume_data.value(support_points[i]);
    model.matrix.compress(VectorOperation::insert);
    model.rhs.compress(VectorOperation::insert);
  }



  WeightedForm
  NonlocalWeakForm1D::weighted_form(const Function<1>         &rhs,
                                    const BlendingFunction<1> &beta) const
  {
    WeightedForm form;
    assemble_pair_form(form.matrix, &beta);
    form.load                                  = model.new_vector();
    const std::vector                    kinks = beta.kinks(0);
    const QGauss<1>                      rule(fe.degree + 3);
    const LagrangeBasis1D                basis(fe);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (geometry.nonlocal_region().contains_strictly(cell->center(), 0))
        {
          cell->get_dof_indices(dofs);
          const double a = cell->vertex(0)[0], b = cell->vertex(1)[0];
          for (const auto &[lo, hi] : pieces(a, b, kinks))
            for (unsigned int q = 0; q < rule.size(); ++q)
              {
                const Point<1> x(lo + (hi - lo) * rule.point(q)[0]);
                const double   w =
                  rule.weight(q) * (hi - lo) * beta.value(x) * rhs.value(x);
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  form.load(dofs[i]) +=
                    w * basis.value(i, (x[0] - a) / (b - a));
              }
        }
    form.load.compress(VectorOperation::add);
    return form;
  }



  void
  NonlocalWeakForm1D::assemble_pair_form(TrilinosWrappers::SparseMatrix &matrix,
                                         const BlendingFunction<1> *beta) const
  {
    // Cells from left to right, so that the cells within the horizon of a
    // cell form a contiguous window.
    std::vector<DoFHandler<1>::active_cell_iterator> cells;
    for (const auto &cell : dof_handler.active_cell_iterators())
      cells.push_back(cell);
    std::sort(cells.begin(), cells.end(), [](const auto &c1, const auto &c2) {
      return c1->vertex(0)[0] < c2->vertex(0)[0];
    });

    const double eps                       = kernel.horizon();
    const auto   for_each_interacting_pair = [&](const auto &action) {
      for (std::size_t i = 0; i < cells.size(); ++i)
        {
          std::size_t first = i, last = i;
          while (first > 0 &&
                 cells[i]->vertex(0)[0] - cells[first - 1]->vertex(1)[0] < eps)
            --first;
          while (last + 1 < cells.size() &&
                 cells[last + 1]->vertex(0)[0] - cells[i]->vertex(1)[0] < eps)
            ++last;
          for (std::size_t j = first; j <= last; ++j)
            action(cells[i], cells[j]);
        }
    };

    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs_1(dofs_per_cell),
      dofs_2(dofs_per_cell);
    std::vector<types::global_dof_index> pair_dofs;

    const auto collect_pair_dofs = [&](const auto &cell_1, const auto &cell_2) {
      cell_1->get_dof_indices(dofs_1);
      cell_2->get_dof_indices(dofs_2);
      pair_dofs = dofs_1;
      pair_dofs.insert(pair_dofs.end(), dofs_2.begin(), dofs_2.end());
      std::sort(pair_dofs.begin(), pair_dofs.end());
      pair_dofs.erase(std::unique(pair_dofs.begin(), pair_dofs.end()),
                      pair_dofs.end());
    };

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    for_each_interacting_pair([&](const auto &cell_1, const auto &cell_2) {
      collect_pair_dofs(cell_1, cell_2);
      for (const auto i : pair_dofs)
        dsp.add_entries(i, pair_dofs.begin(), pair_dofs.end(), true);
    });
    matrix.reinit(model.owned, model.owned, dsp, model.communicator);

    // With a blending weight the integrand in x gains one degree on each
    // piece where the weight is affine (2p + 1: still exact with p + 1
    // points), and G(xi) one more (2p + 2), which Gauss-Legendre integrates
    // exactly for the constant kernel with p + 2 points.
    // (doc/baseline_couplings.md, 'Energy-based blending').
    const std::vector<double> kinks =
      beta ? beta->kinks(0) : std::vector<double>();
    const double    exponent = kernel.exponent();
    const double    c        = kernel.scale();
    const QGauss<1> x_rule(fe.degree + 1);
    // Pieces touching xi = 0: the integrand is xi^2 times a polynomial of
    // degree <= 2p - 1, against the weight |xi|^(2 - beta).
    const Quadrature<1> near_rule =
      gauss_jacobi_unit_interval(fe.degree + 1, 2 - exponent);
    // Pieces away from 0: a polynomial of degree <= 2p + 1 (weighted:
    // 2p + 2) against |xi|^-beta, which is smooth there.
    const QGauss<1> far_rule(exponent == 0 ? fe.degree + 1 + (beta ? 1 : 0) :
                                             12);
    const LagrangeBasis1D basis(fe);

    FullMatrix<double>  local_matrix;
    std::vector<int>    index_in_1, index_in_2;
    std::vector<double> differences;

    for_each_interacting_pair([&](const auto &cell_1, const auto &cell_2) {
      collect_pair_dofs(cell_1, cell_2);
      const unsigned int n = pair_dofs.size();
      local_matrix.reinit(n, n);
      index_in_1.assign(n, -1);
      index_in_2.assign(n, -1);
      differences.resize(n);
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int m = 0; m < dofs_per_cell; ++m)
          {
            if (dofs_1[m] == pair_dofs[k])
              index_in_1[k] = m;
            if (dofs_2[m] == pair_dofs[k])
              index_in_2[k] = m;
          }

      const double a1 = cell_1->vertex(0)[0], b1 = cell_1->vertex(1)[0];
      const double a2 = cell_2->vertex(0)[0], b2 = cell_2->vertex(1)[0];
      const double tol = 1e-12 * (b1 - a1);

      // Add weight * G(xi) to the local matrix, where G(xi) is the integral
      // over x of the product of differences at (x, x + xi).
      const auto add_G = [&](const double xi, const double weight) {
        const double x_lo = std::max(a1, a2 - xi);
        const double x_hi = std::min(b1, b2 - xi);
        if (x_hi <= x_lo)
          return;
        const auto add_piece = [&](const double lo, const double hi) {
          for (unsigned int q = 0; q < x_rule.size(); ++q)
            {
              const double x  = lo + (hi - lo) * x_rule.point(q)[0];
              const double y  = x + xi;
              const double t1 = (x - a1) / (b1 - a1), t2 = (y - a2) / (b2 - a2);
              for (unsigned int k = 0; k < n; ++k)
                differences[k] =
                  (index_in_1[k] >= 0 ? basis.value(index_in_1[k], t1) : 0.) -
                  (index_in_2[k] >= 0 ? basis.value(index_in_2[k], t2) : 0.);
              double w = weight * x_rule.weight(q) * (hi - lo);
              if (beta)
                w *=
                  0.5 * (beta->value(Point<1>(x)) + beta->value(Point<1>(y)));
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  local_matrix(i, j) += w * differences[i] * differences[j];
            }
        };
        if (!beta)
          return add_piece(x_lo, x_hi);
        // The weight's kinks in x and in y = x + xi cut [x_lo, x_hi].
        std::vector<double> cuts = kinks;
        for (const double k : kinks)
          cuts.push_back(k - xi);
        std::sort(cuts.begin(), cuts.end());
        for (const auto &[lo, hi] : pieces(x_lo, x_hi, cuts))
          add_piece(lo, hi);
      };

      const double        lo     = std::max(a2 - b1, -eps);
      const double        hi     = std::min(b2 - a1, eps);
      std::vector<double> breaks = {lo, hi, 0., a2 - a1, b2 - b1};
      // Where a kink of the weight crosses an end of the x-interval.
      for (const double k : kinks)
        for (const double xi : {k - a1, k - b1, a2 - k, b2 - k})
          breaks.push_back(xi);
      breaks.erase(std::remove_if(breaks.begin(),
                                  breaks.end(),
                                  [&](const double xi) {
                                    return xi < lo || xi > hi;
                                  }),
                   breaks.end());
      std::sort(breaks.begin(), breaks.end());

      for (std::size_t p = 0; p + 1 < breaks.size(); ++p)
        {
          const double l = breaks[p], r = breaks[p + 1];
          if (r - l <= tol)
            continue;
          if (std::abs(l) <= tol || std::abs(r) <= tol)
            {
              // xi = s rho, rho in (0, len): the weight rho^(2-beta) is in
              // the rule, G(xi) / xi^2 is the polynomial it integrates.
              const double len = r - l;
              const double s   = (std::abs(l) <= tol) ? 1. : -1.;
              for (unsigned int q = 0; q < near_rule.size(); ++q)
                {
                  const double rho = len * near_rule.point(q)[0];
                  add_G(s * rho,
                        c * std::pow(len, 3 - exponent) * near_rule.weight(q) /
                          (rho * rho));
                }
            }
          else
            for (unsigned int q = 0; q < far_rule.size(); ++q)
              {
                const double xi = l + (r - l) * far_rule.point(q)[0];
                add_G(xi,
                      (r - l) * far_rule.weight(q) * c *
                        std::pow(std::abs(xi), -exponent));
              }
        }

      for (unsigned int i = 0; i < n; ++i)
        matrix.add(pair_dofs[i], n, pair_dofs.data(), &local_matrix(i, 0));
    });
    matrix.compress(VectorOperation::add);
  }



  void
  NonlocalWeakForm1D::assemble_rhs(const Function<1> &rhs)
  {
    model.rhs = model.new_vector();
    const QGauss<1>                      quadrature(fe.degree + 3);
    FEValues<1>                          fe_values(fe,
                          quadrature,
                          update_values | update_quadrature_points |
                            update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (geometry.nonlocal_region().contains_strictly(cell->center(), 0))
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double f = rhs.value(fe_values.quadrature_point(q));
              for (unsigned int i = 0; i < dofs.size(); ++i)
                model.rhs(dofs[i]) +=
                  f * fe_values.shape_value(i, q) * fe_values.JxW(q);
            }
        }
    model.rhs.compress(VectorOperation::add);
  }



  const DoFHandler<1> &
  NonlocalWeakForm1D::get_dof_handler() const
  {
    return dof_handler;
  }



  const DiscreteModel &
  NonlocalWeakForm1D::get_model() const
  {
    return model;
  }



  Region
  NonlocalWeakForm1D::region_of(const Point<1> &p) const
  {
    return geometry.nonlocal_region_of(p, kernel.horizon());
  }



  const std::vector<Point<1>> &
  NonlocalWeakForm1D::get_support_points() const
  {
    return support_points;
  }



  ErrorNorms
  NonlocalWeakForm1D::errors(const TrilinosWrappers::MPI::Vector &field,
                             const Function<1>                   &exact) const
  {
    const double tol = geometry.tolerance();
    return field_errors<1>(dof_handler, field, exact, [&](const Point<1> &p) {
      return geometry.nonlocal_region().contains_strictly(p, tol);
    });
  }
} // namespace ltn

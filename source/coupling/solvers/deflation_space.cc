#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_templates.h>

#include <ltn/coupling/solvers/deflation_space.h>

#include <algorithm>
#include <utility>

namespace ltn
{
  namespace
  {
    /**
     * `C += A^T B` for column-major `A` (k x m), `B` (k x n) and `C` (m x n,
     * leading dimension ldc).
     */
    void
    add_transposed_product(const std::size_t  k,
                           const unsigned int m,
                           const unsigned int n,
                           const double      *A,
                           const double      *B,
                           double            *C,
                           const unsigned int ldc)
    {
      if (k == 0 || m == 0 || n == 0)
        return;
      const types::blas_int rows = k, columns_A = m, columns_B = n,
                            leading_C = ldc;
      const double one                = 1.;
      gemm("T",
           "N",
           &columns_A,
           &columns_B,
           &rows,
           &one,
           A,
           &rows,
           B,
           &rows,
           &one,
           C,
           &leading_C);
    }
  } // namespace



  const double *
  DeflationSpace::ModelStates::state(const unsigned int a) const
  {
    return panels[a / panel_width].data() +
           std::size_t(a % panel_width) * local_size;
  }



  DeflationSpace::DeflationSpace(std::vector<Column>    Z_,
                                 const NormalEquations &equations,
                                 const std::size_t      block_bytes)
    : equations(equations)
    , communicator(equations.new_state(0).get_mpi_communicator())
    , Z(std::move(Z_))
    , block_bytes(block_bytes)
  {
    for (const unsigned int k : {0u, 1u})
      {
        states[k].local_size = equations.new_state(k).locally_owned_size();
        // The same on every rank: a panel's states may be one collective
        // solve (NormalEquations::forward_columns).
        const std::size_t largest =
          Utilities::MPI::max(states[k].local_size, communicator);
        states[k].panel_width = std::max<std::size_t>(
          1, block_bytes / sizeof(double) / std::max<std::size_t>(1, largest));
      }
    for (unsigned int j = 0; j < Z.size(); ++j)
      states[Z[j].model].columns.push_back(j);
    for (unsigned int k : {0u, 1u})
      {
        ModelStates &model = states[k];
        for (std::size_t first = 0; first < model.columns.size();
             first += model.panel_width)
          {
            const std::size_t end =
              std::min(first + model.panel_width, model.columns.size());
            // A panel's columns solved at once where the model can and no
            // column has a guess, else one by one from their guesses.
            const bool guessed =
              std::any_of(model.columns.begin() + first,
                          model.columns.begin() + end,
                          [this](const unsigned int j) {
                            return Z[j].state_guess.size() > 0;
                          });
            std::vector<VectorType> panel_states;
            if (equations.forward_columns && !guessed)
              {
                std::vector<VectorType> controls;
                for (std::size_t a = first; a < end; ++a)
                  controls.push_back(Z[model.columns[a]].controls);
                panel_states = equations.forward_columns(k, controls);
              }
            else
              for (std::size_t a = first; a < end; ++a)
                {
                  Column &z = Z[model.columns[a]];
                  panel_states.push_back(
                    equations.forward(k,
                                      z.controls,
                                      z.state_guess.size() ? &z.state_guess :
                                                             nullptr));
                  z.state_guess.clear(); // the state itself is kept
                }
            std::vector<double> &panel = model.panels.emplace_back();
            panel.reserve(model.local_size * (end - first));
            for (const VectorType &state : panel_states)
              panel.insert(panel.end(), state.begin(), state.end());
          }
        if (!model.columns.empty())
          {
            const VectorType observed = equations.observed_unknowns(k);
            for (std::size_t i = 0; i < model.local_size; ++i)
              if (observed.begin()[i] != 0)
                model.observed_rows.push_back(i);
            model.pack_observed_rows();
          }
      }
    form_coarse_matrix();
  }



  void
  DeflationSpace::form_coarse_matrix()
  {
    // E(i, j) = (V z_i)^T B^T W B (V z_j) + alpha z_i . z_j. Column j's
    // observation gives the gradients of the models k >= model(j); the rest
    // of E is its transpose. The gradients of a block of columns are packed
    // and multiplied with the packed states at once.
    const unsigned int        m = Z.size();
    std::vector<double>       E(std::size_t(m) * m, 0.);
    std::vector<unsigned int> column_in_model(m);
    for (const auto &model : states)
      for (unsigned int a = 0; a < model.columns.size(); ++a)
        column_in_model[model.columns[a]] = a;
    // Only model k's own gradient is needed where no later model has
    // columns: the assembled B_k^T W B_k, if given, serves.
    const auto alone = [&](const unsigned int k) {
      return equations.observe_alone[k] &&
             (k == 1 || states[1].columns.empty());
    };
    // The blocks are the same on every rank, sized by the largest share of
    // each model's unknowns: observe_alone is collective.
    std::array<std::size_t, 2> largest;
    for (const unsigned int l : {0u, 1u})
      largest[l] = Utilities::MPI::max(states[l].local_size, communicator);
    for (unsigned int first = 0; first < m;)
      {
        // The block: the columns from `first` on whose gradients fit in
        // block_bytes (at least one).
        std::vector<unsigned int> block;
        for (std::size_t bytes = 0;
             first < m && (block.empty() || bytes < block_bytes);
             ++first)
          {
            const unsigned int k = Z[first].model;
            for (unsigned int l = k; l < 2; ++l)
              if (!states[l].columns.empty() && (l == k || !alone(k)))
                bytes += sizeof(double) * largest[l];
            block.push_back(first);
          }
        // The gradients of the block's columns, model by model in the
        // block's order. Consecutive columns of a model that observes
        // alone, whose states lie one after the other in a panel, go to
        // observe_alone together.
        std::array<std::vector<double>, 2> gradients;
        for (std::size_t b = 0; b < block.size();)
          {
            const unsigned int k    = Z[block[b]].model;
            const unsigned int a    = column_in_model[block[b]];
            const std::size_t  size = states[k].local_size;
            if (alone(k))
              {
                std::size_t n = 1;
                while (b + n < block.size() && Z[block[b + n]].model == k &&
                       (a + n) % states[k].panel_width != 0)
                  ++n;
                std::vector<double> &g = gradients[k];
                g.resize(g.size() + n * size);
                equations.observe_alone[k](n,
                                           states[k].state(a),
                                           g.data() + g.size() - n * size);
                b += n;
                continue;
              }
            NormalEquations::States column;
            column[k] = equations.new_state(k);
            std::copy_n(states[k].state(a), size, column[k].begin());
            const Observation observed = equations.observe(column);
            for (unsigned int l = k; l < 2; ++l)
              if (!states[l].columns.empty())
                {
                  const VectorType g = equations.observe_transpose(l, observed);
                  gradients[l].insert(gradients[l].end(), g.begin(), g.end());
                }
            ++b;
          }
        // The block's columns whose observation gave model l's gradient.
        for (const unsigned int l : {0u, 1u})
          {
            std::vector<unsigned int> with_gradient;
            for (const unsigned int j : block)
              if (Z[j].model <= l)
                with_gradient.push_back(j);
            if (with_gradient.empty() || states[l].columns.empty())
              continue;
            // E is symmetric: within model l only the states from the
            // block's first column on are multiplied, which holds the lower
            // triangle (about half the products where l has many columns).
            const bool         own_model = std::all_of(with_gradient.begin(),
                                               with_gradient.end(),
                                               [&](const unsigned int j) {
                                                 return Z[j].model == l;
                                               });
            const unsigned int first_state =
              own_model ? column_in_model[with_gradient[0]] : 0;
            const std::size_t   n_states = states[l].columns.size();
            std::vector<double> y(n_states * with_gradient.size(), 0.);
            add_state_products(
              l, gradients[l].data(), with_gradient.size(), y, first_state);
            for (std::size_t b = 0; b < with_gradient.size(); ++b)
              for (std::size_t a = first_state; a < n_states; ++a)
                E[std::size_t(with_gradient[b]) * m + states[l].columns[a]] =
                  y[b * n_states + a];
          }
      }
    Utilities::MPI::sum(E, communicator, E);

    coarse_matrix.reinit(m, m);
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int i = 0; i < m; ++i)
        {
          // E is stored by columns j, its entries (i, j) for model(i) >
          // model(j), and for model(i) = model(j) where i >= j.
          const bool lower =
            Z[i].model > Z[j].model || (Z[i].model == Z[j].model && i >= j);
          coarse_matrix(i, j) =
            lower ? E[std::size_t(j) * m + i] : E[std::size_t(i) * m + j];
        }
    if (equations.alpha != 0)
      for (unsigned int j = 0; j < m; ++j)
        for (unsigned int i = 0; i < m; ++i)
          if (Z[i].model == Z[j].model)
            coarse_matrix(i, j) +=
              equations.alpha * (Z[i].controls * Z[j].controls);
    coarse_matrix.set_property(LAPACKSupport::symmetric);
    if (m > 0)
      coarse_matrix.compute_cholesky_factorization();
  }



  void
  DeflationSpace::add_state_products(const unsigned int   k,
                                     const double        *g,
                                     const unsigned int   n_columns,
                                     std::vector<double> &y,
                                     const unsigned int   first_state) const
  {
    const ModelStates              &model = states[k];
    const std::size_t               size  = model.local_size;
    const std::vector<std::size_t> &rows  = model.observed_rows;
    if (rows.empty())
      return;
    std::vector<double> packed_g(rows.size() * n_columns);
    for (unsigned int c = 0; c < n_columns; ++c)
      for (std::size_t r = 0; r < rows.size(); ++r)
        packed_g[c * rows.size() + r] = g[c * size + rows[r]];
    for (unsigned int p = first_state / model.panel_width;
         p < model.packed_panels.size();
         ++p)
      {
        // The panel's states from first_state on.
        const unsigned int first_column = p * model.panel_width;
        const unsigned int skipped =
          first_state > first_column ? first_state - first_column : 0;
        const unsigned int width =
          model.packed_panels[p].size() / rows.size() - skipped;
        add_transposed_product(rows.size(),
                               width,
                               n_columns,
                               model.packed_panels[p].data() +
                                 std::size_t(skipped) * rows.size(),
                               packed_g.data(),
                               y.data() + first_column + skipped,
                               model.columns.size());
      }
  }



  void
  DeflationSpace::ModelStates::pack_observed_rows()
  {
    packed_panels.resize(panels.size());
    for (unsigned int p = 0; p < panels.size(); ++p)
      {
        const std::size_t width = panels[p].size() / local_size;
        packed_panels[p].resize(observed_rows.size() * width);
        for (std::size_t c = 0; c < width; ++c)
          for (std::size_t r = 0; r < observed_rows.size(); ++r)
            packed_panels[p][c * observed_rows.size() + r] =
              panels[p][c * local_size + observed_rows[r]];
      }
  }



  void
  DeflationSpace::coarse_solve(Vector<double> &y) const
  {
    if (y.size() > 0)
      coarse_matrix.solve(y);
  }



  Vector<double>
  DeflationSpace::solve_product(const BlockVectorType &v,
                                const Observation     &observed) const
  {
    Vector<double> y(Z.size());
    if (Z.empty())
      return y;
    std::vector<double> products(Z.size(), 0.);
    for (const unsigned int k : {0u, 1u})
      if (!states[k].columns.empty())
        {
          const VectorType    g = equations.observe_transpose(k, observed);
          std::vector<double> y_k(states[k].columns.size(), 0.);
          add_state_products(k, g.begin(), 1, y_k);
          for (std::size_t a = 0; a < y_k.size(); ++a)
            products[states[k].columns[a]] = y_k[a];
        }
    Utilities::MPI::sum(products, communicator, products);
    for (std::size_t j = 0; j < Z.size(); ++j)
      y(j) = products[j] +
             (equations.alpha != 0 ? equations.alpha * dot(Z[j], v) : 0.);
    coarse_solve(y);
    return y;
  }



  namespace
  {
    /**
     * `y = sum_p panels[p] c_p`, `c_p` the entries of @p c at the panels'
     * columns (`panel_width` each) among @p columns: `rows` rows each.
     */
    void
    combine_panels(const std::vector<std::vector<double>> &panels,
                   const std::size_t                       rows,
                   const unsigned int                      panel_width,
                   const std::vector<unsigned int>        &columns,
                   const Vector<double>                   &c,
                   double                                 *y)
    {
      const types::blas_int n_rows = rows, one_step = 1;
      for (unsigned int p = 0; p < panels.size() && n_rows > 0; ++p)
        {
          std::vector<double> c_p;
          for (std::size_t a = p * panel_width;
               a < std::min<std::size_t>((p + 1) * panel_width, columns.size());
               ++a)
            c_p.push_back(c(columns[a]));
          const types::blas_int n_columns = c_p.size();
          const double          one = 1., beta = (p == 0 ? 0. : 1.);
          gemv("N",
               &n_rows,
               &n_columns,
               &one,
               panels[p].data(),
               &n_rows,
               c_p.data(),
               &one_step,
               &beta,
               y,
               &one_step);
        }
    }
  } // namespace



  void
  DeflationSpace::add(const Vector<double> &c,
                      BlockVectorType      &v,
                      Observation          &observed) const
  {
    if (Z.empty())
      return;
    for (std::size_t j = 0; j < Z.size(); ++j)
      v.block(Z[j].model).add(c(j), Z[j].controls);
    // The combined state V_k Z_k c_k of each model with columns, at the
    // unknowns the observation reads (zero elsewhere).
    NormalEquations::States combined;
    for (const unsigned int k : {0u, 1u})
      if (!states[k].columns.empty())
        {
          const ModelStates  &model = states[k];
          std::vector<double> at_rows(model.observed_rows.size());
          combine_panels(model.packed_panels,
                         at_rows.size(),
                         model.panel_width,
                         model.columns,
                         c,
                         at_rows.data());
          combined[k] = equations.new_state(k);
          for (std::size_t r = 0; r < at_rows.size(); ++r)
            combined[k].begin()[model.observed_rows[r]] = at_rows[r];
        }
    const Observation added = equations.observe(combined);
    for (std::size_t q = 0; q < observed.size(); ++q)
      observed[q] += added[q];
  }



  void
  DeflationSpace::add_states(const Vector<double>    &c,
                             NormalEquations::States &added_to) const
  {
    for (const unsigned int k : {0u, 1u})
      if (!states[k].columns.empty())
        {
          const ModelStates  &model = states[k];
          std::vector<double> combined(model.local_size);
          combine_panels(model.panels,
                         model.local_size,
                         model.panel_width,
                         model.columns,
                         c,
                         combined.data());
          for (std::size_t i = 0; i < combined.size(); ++i)
            added_to[k].begin()[i] += combined[i];
        }
  }



  bool
  DeflationSpace::spans(const unsigned int k) const
  {
    // As many columns as the model has controls span them all: the columns
    // are independent (Gram-Schmidt drops dependent ones, unit columns are
    // distinct).
    const std::vector<unsigned int> &columns = states[k].columns;
    return !columns.empty() && columns.size() == Z[columns[0]].controls.size();
  }



  double
  DeflationSpace::dot(const Column &z, const BlockVectorType &v) const
  {
    return z.controls * v.block(z.model);
  }



  unsigned int
  DeflationSpace::size() const
  {
    return Z.size();
  }
} // namespace ltn

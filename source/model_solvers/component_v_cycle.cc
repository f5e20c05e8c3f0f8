#include <deal.II/base/exceptions.h>

#include <ltn/model_solvers/component_v_cycle.h>

#include <ml_MultiLevelPreconditioner.h>
#include <ml_epetra_utils.h>
#include <ml_include.h>
#include <ml_mls.h>


namespace ltn
{
  namespace
  {
    /** An ML operator copied into an Epetra matrix (null if it fails). */
    std::unique_ptr<Epetra_CrsMatrix>
    copy_of(ML_Operator &op)
    {
      Epetra_CrsMatrix *copy = nullptr;
      if (ML_Operator2EpetraCrsMatrix(&op, copy) != 0)
        {
          delete copy;
          return nullptr;
        }
      return std::unique_ptr<Epetra_CrsMatrix>(copy);
    }

    /** An Epetra call's error code, which must be zero. */
    void
    check(const int error)
    {
      AssertThrow(error == 0, ExcMessage("an Epetra product in the V-cycle"));
    }
  } // namespace



  /**
   * One level that the cycle runs itself: its operator (the stencil on the
   * finest, else a copy of ML's matrix), the Chebyshev step's scaling, the
   * transfers to and from the next coarser level, and work vectors.
   */
  struct ComponentVCycle::Level
  {
    std::unique_ptr<Epetra_CrsMatrix> matrix; // null on the finest level
    /** 1 / (theta d_i), the Chebyshev step's scaling of row i. */
    std::vector<double> step;
    /** ML's prolongation from the next coarser level; its transpose
     *  restricts (ML's restriction is that transpose, stored apart). */
    std::unique_ptr<Epetra_CrsMatrix> prolongation;
    /** The right-hand side and solution (not on the finest level, whose
     *  are the caller's), and the residual. */
    std::unique_ptr<Epetra_MultiVector> rhs, solution, residual;
  };



  ComponentVCycle::ComponentVCycle(const TrilinosWrappers::PreconditionAMG &amg,
                                   const Epetra_CrsMatrix &matrix,
                                   const StencilMatrix    &stencil,
                                   const unsigned int      n_components)
    : stencil(stencil)
    , n_components(n_components)
  {
    const auto *hierarchy =
      dynamic_cast<const ML_Epetra::MultiLevelPreconditioner *>(
        &amg.trilinos_operator());
    ML  *ml_struct = hierarchy ? const_cast<ML *>(hierarchy->GetML()) : nullptr;
    bool form      = ml_struct != nullptr && n_components >= 1 &&
                ml_struct->ML_finest_level == 0 &&
                ml_struct->ML_num_actual_levels >= 2;
    // The levels run here: the two finest, or the finest alone if the
    // second is ML's coarsest (its direct solve stays ML's).
    const unsigned int n_own =
      form ? std::min(2, ml_struct->ML_num_actual_levels - 1) : 0;
    for (unsigned int l = 0; l < n_own && form; ++l)
      {
        const ML_Smoother &pre  = ml_struct->pre_smoother[l];
        const ML_Smoother &post = ml_struct->post_smoother[l];
        form                    = form && pre.smoother->func_ptr == &ML_Cheby &&
               post.smoother->func_ptr == &ML_Cheby;
        if (!form)
          break;
        const auto *chebyshev =
          static_cast<const MLSthing *>(pre.smoother->data);
        const ML_Operator &A = ml_struct->Amat[l];
        form =
          form && chebyshev->mlsDeg == 1 &&
          chebyshev->block_scaling == nullptr &&
          static_cast<const MLSthing *>(post.smoother->data)->mlsDeg == 1 &&
          A.lambda_max > 0 && !(A.lambda_min == 1. && A.lambda_max == 1.);
        if (!form)
          break;
        Level &level = levels.emplace_back();
        if (l > 0)
          level.matrix = copy_of(ml_struct->Amat[l]);
        level.prolongation = copy_of(ml_struct->Pmat[l + 1]);
        form = form && (l == 0 || level.matrix) && level.prolongation;
        if (!form)
          break;
        const Epetra_CrsMatrix &own = l == 0 ? matrix : *level.matrix;
        form = form && level.prolongation->RangeMap().SameAs(own.RowMap()) &&
               level.prolongation->RowMap().SameAs(own.RowMap());
        if (!form)
          break;
        // The step of ML's Chebyshev smoother of degree 1 (ML_Cheby): the
        // eigenvalue interval [lambda_max / ratio, 1.1 lambda_max] of
        // D^{-1} A, its midpoint theta, and zero diagonals taken as one.
        const double  upper = 1.1 * A.lambda_max;
        const double  lower = A.lambda_max / chebyshev->eig_ratio;
        const double  theta = (upper + lower) / 2;
        Epetra_Vector diagonal(own.RowMap());
        own.ExtractDiagonalCopy(diagonal);
        level.step.resize(own.NumMyRows());
        for (int i = 0; i < own.NumMyRows(); ++i)
          level.step[i] = 1. / (theta * (diagonal[i] == 0. ? 1. : diagonal[i]));
        const auto vectors = [&](const Epetra_BlockMap &map) {
          return std::make_unique<Epetra_MultiVector>(map, n_components);
        };
        if (l > 0)
          {
            level.rhs      = vectors(own.RowMap());
            level.solution = vectors(own.RowMap());
          }
        level.residual = vectors(own.RowMap());
      }
    if (form)
      {
        const Epetra_Map &coarse = levels.back().prolongation->DomainMap();
        ml_rhs = std::make_unique<Epetra_MultiVector>(coarse, n_components);
        ml_solution =
          std::make_unique<Epetra_MultiVector>(coarse, n_components);
        for (std::size_t l = 1; l < levels.size(); ++l)
          form = form && levels[l - 1].prolongation->DomainMap().SameAs(
                           levels[l].matrix->RowMap());
      }
    // All ranks or none: the cycle is collective.
    const auto &comm = matrix.Comm();
    int         mine = form ? 1 : 0, all = 0;
    comm.MinAll(&mine, &all, 1);
    if (all == 1)
      ml = ml_struct;
    else
      levels.clear();
  }



  ComponentVCycle::~ComponentVCycle() = default;



  bool
  ComponentVCycle::usable() const
  {
    return ml != nullptr;
  }



  void
  ComponentVCycle::apply_operator(const unsigned int        l,
                                  const Epetra_MultiVector &x,
                                  Epetra_MultiVector       &y) const
  {
    const Level &level = levels[l];
    if (level.matrix)
      check(level.matrix->Multiply(false, x, y));
    else
      for (unsigned int c = 0; c < n_components; ++c)
        stencil.apply(x[c], y[c]);
  }



  void
  ComponentVCycle::cycle(const unsigned int        l,
                         const Epetra_MultiVector &b,
                         Epetra_MultiVector       &x) const
  {
    const Level        &level = levels[l];
    Epetra_MultiVector &r     = *level.residual;
    const std::size_t   n     = level.step.size();
    const double       *step  = level.step.data();
    // Pre-smoothing from zero, then the residual.
    for (unsigned int c = 0; c < n_components; ++c)
      {
        const double *const b_c = b[c];
        double *const       x_c = x[c];
        for (std::size_t i = 0; i < n; ++i)
          x_c[i] = b_c[i] * step[i];
      }
    apply_operator(l, x, r);
    for (unsigned int c = 0; c < n_components; ++c)
      {
        const double *const b_c = b[c];
        double *const       r_c = r[c];
        for (std::size_t i = 0; i < n; ++i)
          r_c[i] = b_c[i] - r_c[i];
      }
    // The coarse correction.
    const bool          last       = l + 1 == levels.size();
    Epetra_MultiVector &coarse_rhs = last ? *ml_rhs : *levels[l + 1].rhs;
    check(level.prolongation->Multiply(true, r, coarse_rhs));
    Epetra_MultiVector *coarse_solution = nullptr;
    if (last)
      {
        ML *ml_struct = ml;
        ml_solution->PutScalar(0.);
        for (unsigned int c = 0; c < n_components; ++c)
          ML_Cycle_MG(&ml_struct->SingleLevel[l + 1],
                      (*ml_solution)[c],
                      (*ml_rhs)[c],
                      ML_ZERO,
                      ml_struct->comm,
                      ML_NO_RES_NORM,
                      ml_struct);
        coarse_solution = ml_solution.get();
      }
    else
      {
        coarse_solution = levels[l + 1].solution.get();
        cycle(l + 1, coarse_rhs, *coarse_solution);
      }
    // The residual's vector is free until the post-smoothing.
    check(level.prolongation->Multiply(false, *coarse_solution, r));
    check(x.Update(1., r, 1.));
    // Post-smoothing.
    apply_operator(l, x, r);
    for (unsigned int c = 0; c < n_components; ++c)
      {
        const double *const b_c = b[c], *const r_c = r[c];
        double *const x_c = x[c];
        for (std::size_t i = 0; i < n; ++i)
          x_c[i] += (b_c[i] - r_c[i]) * step[i];
      }
  }



  void
  ComponentVCycle::vmult(Epetra_MultiVector       &dst,
                         const Epetra_MultiVector &src) const
  {
    Assert(usable(), ExcInternalError());
    AssertDimension(static_cast<unsigned int>(src.NumVectors()), n_components);
    Assert(&dst != &src, ExcMessage("the cycle reads its input throughout"));
    cycle(0, src, dst);
  }



  void
  ComponentVCycle::release_ml_levels()
  {
    Assert(usable(), ExcInternalError());
    // An emptied operator, as ML leaves the levels it does not use: its
    // destructor cleans it again.
    const auto empty = [this](ML_Operator &op) {
      ML_Operator_Clean(&op);
      ML_Operator_Init(&op, ml->comm);
    };
    for (unsigned int l = 0; l < levels.size(); ++l)
      {
        if (l > 0)
          empty(ml->Amat[l]);
        empty(ml->Rmat[l]);
        empty(ml->Pmat[l + 1]);
      }
  }



  std::size_t
  ComponentVCycle::memory_consumption() const
  {
    std::size_t bytes        = 0;
    const auto  matrix_bytes = [](const Epetra_CrsMatrix *M) {
      return M ? std::size_t(M->NumMyNonzeros()) *
                     (sizeof(double) + sizeof(int)) +
                   std::size_t(M->NumMyRows() + 1) * sizeof(int) :
                  std::size_t(0);
    };
    const auto vector_bytes = [](const Epetra_MultiVector *v) {
      return v ? std::size_t(v->MyLength()) * v->NumVectors() * sizeof(double) :
                 std::size_t(0);
    };
    for (const Level &level : levels)
      bytes +=
        matrix_bytes(level.matrix.get()) +
        matrix_bytes(level.prolongation.get()) +
        level.step.size() * sizeof(double) + vector_bytes(level.rhs.get()) +
        vector_bytes(level.solution.get()) + vector_bytes(level.residual.get());
    return bytes + vector_bytes(ml_rhs.get()) + vector_bytes(ml_solution.get());
  }
} // namespace ltn

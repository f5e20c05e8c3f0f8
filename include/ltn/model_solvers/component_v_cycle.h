#pragma once

#include <deal.II/lac/trilinos_precondition.h>

#include <ltn/model_solvers/stencil_matrix.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>

#include <memory>
#include <vector>

struct ML_Struct;

namespace ltn
{
  using namespace dealii;

  /**
   * ML's V-cycle on a scalar lattice surrogate, applied to the components of
   * a field at once (doc/discretization.md, 'Iterative model solvers').
   * ML applies its
   * cycle to one vector at a time, so one cycle per component read the
   * transfers between the two finest levels and the second level's matrix
   * once per component: on the 3D bars of benchmarks/scaling those are most
   * of the cycle's bytes (the finest level is the stencil). This class runs
   * the two finest levels itself on all components, with Epetra's products
   * on the block of components (each matrix read once for all of them) of
   * copies of ML's matrices and ML's Chebyshev coefficients, and hands the
   * coarser levels to ML's own cycle, one component at a time. The result is
   * ML's cycle per component, to round-off.
   */
  class ComponentVCycle
  {
  public:
    /**
     * From @p amg, ML's hierarchy on the surrogate @p matrix, whose finest
     * level @p stencil serves (StencilMatrix::serve_finest_level()); both
     * must outlive this object. usable() says whether the hierarchy has the
     * form this class repeats: at least two levels, numbered from the
     * finest, and Chebyshev smoothing of degree 1 on those it runs.
     */
    ComponentVCycle(const TrilinosWrappers::PreconditionAMG &amg,
                    const Epetra_CrsMatrix                  &matrix,
                    const StencilMatrix                     &stencil,
                    const unsigned int                       n_components);

    ~ComponentVCycle();

    bool
    usable() const;

    /**
     * Column `c` of @p dst the V-cycle applied to column `c` of @p src, for
     * every column; both on the surrogate's map, with as many columns as
     * components. Collective.
     */
    void
    vmult(Epetra_MultiVector &dst, const Epetra_MultiVector &src) const;

    /**
     * Free ML's own matrices of the levels this cycle runs (their operators,
     * the transfers between them and to the next level, and their
     * transposes, which the cycle forms by products): after this, ML's
     * hierarchy can only run from the first level it keeps, as vmult()
     * calls it, not from the finest (`amg.vmult()` must not be called).
     * Only where usable(); once.
     */
    void
    release_ml_levels();

    /** Bytes of the copied matrices and the work vectors (estimated). */
    std::size_t
    memory_consumption() const;

  private:
    struct Level;

    /**
     * @p x the cycle from level @p l on applied to @p b. Levels 0 ..
     * levels.size() - 1 run here, the next one in ML.
     */
    void
    cycle(const unsigned int        l,
          const Epetra_MultiVector &b,
          Epetra_MultiVector       &x) const;

    /** `y = A_l x` on every column. */
    void
    apply_operator(const unsigned int        l,
                   const Epetra_MultiVector &x,
                   Epetra_MultiVector       &y) const;

    const StencilMatrix &stencil;
    const unsigned int   n_components;
    /** ML's hierarchy, where usable(); else null. */
    ML_Struct                          *ml = nullptr;
    std::vector<Level>                  levels;
    std::unique_ptr<Epetra_MultiVector> ml_rhs, ml_solution;
  };
} // namespace ltn

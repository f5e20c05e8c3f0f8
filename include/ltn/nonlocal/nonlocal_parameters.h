#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ltn/nonlocal/kernel.h>
#include <ltn/problem/geometry.h>

#include <string>

namespace ltn
{
  using namespace dealii;

  /** How a particle operator is stored (`Nonlocal model/Operator`). */
  enum class OperatorStorage
  {
    /** Chosen per level by choose_solvers() (scene/solver_choice.h). */
    automatic,
    /** A sparse matrix, which the direct solvers need. */
    assembled,
    /**
     * One stencil shared by the particles away from collar and cracks,
     * rows stored only for the others (LatticeOperator).
     */
    matrix_free
  };

  /** The names of the storages in `Nonlocal model/Operator`. */
  inline const SelectionNames<OperatorStorage> &
  operator_storage_names()
  {
    static const SelectionNames<OperatorStorage> names = {
      {OperatorStorage::automatic, "auto"},
      {OperatorStorage::assembled, "assembled"},
      {OperatorStorage::matrix_free, "matrix-free"}};
    return names;
  }

  /**
   * The parameters of the nonlocal model (subsection `Nonlocal model`): its
   * kernel, its horizon (fixed, or a multiple of the mesh size for studies
   * with `eps = m h -> 0`), and the degree of its discretization.
   */
  struct NonlocalParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** The horizon at mesh size @p h. */
    double
    horizon(const double h) const;

    /** The particle spacing (2D, 3D) at mesh size @p h. */
    double
    particle_spacing(const double h) const;

    /**
     * Check the particle lattice of the coarsest level (mesh size @p h)
     * against @p geometry and the local model's degree @p local_degree:
     * the spacing resolves the horizon, divides the nonlocal region, and
     * leaves every local control observed; an InputError names the ratio
     * otherwise.
     */
    template <int dim>
    void
    validate_particles(const Geometry<dim> &geometry,
                       const unsigned int   local_degree,
                       const double         h) const;

    /**
     * Check that the particle lattice of the finest level (mesh size
     * @p h), with its collar @p collar_horizons horizons deep and
     * @p unknowns_per_particle unknowns at each particle, can be held: its
     * unknowns within deal.II's and Trilinos's 32-bit indices, and at
     * least 64 bytes per unknown (eight vectors of doubles, fewer than any
     * solver keeps) within the physical memory of the machines of
     * @p communicator. An InputError names the spacing ratio otherwise.
     */
    template <int dim>
    void
    check_particle_count(const Geometry<dim> &geometry,
                         const double         h,
                         const unsigned int   collar_horizons,
                         const unsigned int   unknowns_per_particle,
                         const MPI_Comm       communicator) const;

    /** The kernel at mesh size @p h, for a @p dim dimensional model. */
    Kernel
    kernel(const unsigned int dim, const double h) const;

    KernelKind   kernel_kind      = KernelKind::constant;
    double       fractional_order = 0.5;
    double       fixed_horizon    = 0;
    double       horizon_ratio    = 0;
    unsigned int degree           = 1;
    double       spacing_ratio    = 1;
    /** How the particle operator is stored (`Operator`). */
    OperatorStorage operator_storage = OperatorStorage::automatic;
  };
} // namespace ltn

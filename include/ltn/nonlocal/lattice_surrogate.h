#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <ltn/base/model_lattice.h>
#include <ltn/nonlocal/particle_lattice.h>

#include <functional>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The surrogate of a particle model for algebraic multigrid
   * (doc/discretization.md, 'Iterative model solvers'): the
   * nearest-neighbour Laplacian on
   * the lattice,
   *
   *   (L x)_p = diagonal / (2 dim) sum_{q ~ p} (x_p - x_q),
   *
   * over the axis neighbours `q` of a particle `p` of `Omega_n` whose bond
   * no crack cuts (@p is_cut); neighbours in the collar enter as zero
   * values (the model fixes them by identity rows), so `L` is symmetric.
   * Its rows and columns are the particles of `Omega_n` alone
   * (`LatticeSurrogate::nodes`): the preconditioner is the identity on the
   * collar, whose rows of the model are identities. At fixed `eps / h` the
   * model's operator is spectrally equivalent to `L` in each of its first
   * @p n_field_components components (the displacement; the rest, the
   * dilatation, are eliminated), which keeps AMG's iteration counts
   * independent of `h`.
   *
   * `L` is right at long wavelengths only up to a factor: the model's
   * operator tends to @p long_wave_modulus times the Laplacian there (the
   * diffusion coefficient; for LPS the shear modulus, its softest waves),
   * `L` to `diagonal h^2 / (2 dim)` times it. At short wavelengths, where
   * `L` keeps growing, a nonlocal operator levels off at its diagonal. The
   * preconditioner therefore adds the inverse of `L`'s diagonal, weighted
   * by a factor (ModelSolverSettings::short_wave_factor) times the ratio of
   * the two long-wave moduli (`LatticeSurrogate::long_wave_ratio`), to its
   * cycle on `L` (doc/discretization.md, 'Iterative model solvers').
   *
   * The same bonds from particles of `Omega_n` to particles of the collar
   * make the coupling `C` (`LatticeSurrogate::collar`): for values `y` on the
   * collar, `L v = C y` gives their discrete harmonic extension `v` into
   * `Omega_n` (doc/discretization.md, 'A surrogate model of the nonlocal
   * control block'). The model's stencil
   * reaches several layers into the collar, and weighs them unequally: each
   * bond takes the collar's values on its axis, layer `m` (`m = 1, 2, ...`)
   * with the weight `collar_trace[m - 1]` (collar_trace_weights()), so that
   * `C` extends them as the model would.
   *
   * Fills @p surrogate over this rank's @p owned_particles, one row per
   * particle of `Omega_n`, distributed over @p communicator.
   */
  template <int dim>
  void
  assemble_lattice_surrogate(
    const ParticleLattice<dim> &lattice,
    const IndexSet             &owned_particles,
    const unsigned int          n_field_components,
    const double                diagonal,
    const double                long_wave_modulus,
    const std::vector<double>  &collar_trace,
    const double                spacing,
    const std::function<bool(const Point<dim> &, const Point<dim> &)> &is_cut,
    const MPI_Comm    communicator,
    LatticeSurrogate &surrogate);
} // namespace ltn

#pragma once

#include <deal.II/base/function.h>

#include <deal.II/lac/trilinos_vector.h>

#include <ltn/nonlocal/nonlocal_weak_form_1d.h>
#include <ltn/nonlocal/particle_diffusion.h>
#include <ltn/nonlocal/particle_elasticity.h>

#include <string>

namespace ltn
{
  /**
   * Write the nonlocal field as `directory/name.pvtu` (see
   * write_parallel_vtu()) with `u`, and with an exact solution `u_exact` and
   * `error`, plus the `region` tag: on the 1D finite element mesh, or on the
   * particles, each rank its own. Return the name of the `.pvtu` record.
   */
  std::string
  write_nonlocal_vtu(const NonlocalWeakForm1D            &nonlocal,
                     const TrilinosWrappers::MPI::Vector &field,
                     const Function<1>                   *exact,
                     const std::string                   &directory,
                     const std::string                   &name);

  /**
   * Write the particles of LPS as `directory/name.pvtu`: the `displacement`
   * (a vector, for ParaView's Warp By Vector), the `dilatation` (where it is
   * an unknown; zero in the outer collar), the `broken_bond_fraction` (bonds
   * cut by cracks), the `region` tag, and with an exact solution
   * `displacement_exact` and `error`. Return the name of the `.pvtu` record.
   */
  template <int dim>
  std::string
  write_nonlocal_vtu(const ParticleElasticity<dim>       &nonlocal,
                     const TrilinosWrappers::MPI::Vector &field,
                     const Function<dim>                 *exact,
                     const std::string                   &directory,
                     const std::string                   &name);

  template <int dim>
  std::string
  write_nonlocal_vtu(const ParticleDiffusion<dim>        &nonlocal,
                     const TrilinosWrappers::MPI::Vector &field,
                     const Function<dim>                 *exact,
                     const std::string                   &directory,
                     const std::string                   &name);
} // namespace ltn

#pragma once

#include <deal.II/base/function.h>

#include <deal.II/lac/vector.h>

#include <ltn/nonlocal/nonlocal_weak_form_1d.h>
#include <ltn/nonlocal/particle_diffusion.h>

#include <string>

namespace ltn
{
  /**
   * Write the nonlocal field to VTU with `u`, and with an exact solution
   * `u_exact` and `error`, plus the `region` tag: on the 1D finite element
   * mesh, or on the particles.
   */
  void
  write_nonlocal_vtu(const NonlocalWeakForm1D &nonlocal,
                     const Vector<double>     &field,
                     const Function<1>        *exact,
                     const std::string        &filename);

  template <int dim>
  void
  write_nonlocal_vtu(const ParticleDiffusion<dim> &nonlocal,
                     const Vector<double>         &field,
                     const Function<dim>          *exact,
                     const std::string            &filename);
} // namespace ltn

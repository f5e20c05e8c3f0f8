#pragma once

#include <deal.II/base/parameter_handler.h>

namespace ltn
{
  using namespace dealii;

  /**
   * The refinement levels of a scene (subsection `Discretization`): level
   * `l` has mesh size `h_l = h_0 / 2^l`. One level is one coupled solve;
   * several make a convergence study in one run.
   */
  struct Discretization
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** The mesh size of level @p level. */
    double
    mesh_size(const unsigned int level) const;

    double       coarsest_mesh_size = 0.125;
    unsigned int n_levels           = 1;
  };
} // namespace ltn

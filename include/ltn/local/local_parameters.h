#pragma once

#include <deal.II/base/parameter_handler.h>

#include <deal.II/fe/component_mask.h>

#include <ltn/problem/geometry.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The parameters of the local (finite element) model, subsection
   * `Local model`, shared by the Poisson and the elasticity model: the
   * element degree, the Dirichlet faces (and, for elasticity, which
   * displacement components each fixes) and the adaptive refinement.
   */
  template <int dim>
  struct LocalParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the subsection; an InputError names `Local model/Dirichlet
     * components` if its text is malformed, names an unknown face or
     * component, a component beyond `dim`, or a face that is not in
     * `Dirichlet boundaries`.
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Check the parameters against the scene's @p geometry: an InputError
     * names `Local model/Graded mesh layers` if it grades the mesh of a scene
     * without a nonlocal region.
     */
    void
    validate(const Geometry<dim> &geometry) const;

    /**
     * The components of a field with @p n_components components that the
     * Dirichlet condition on body face @p face fixes: none on a face that is
     * not in `Dirichlet boundaries`, those listed in `Dirichlet components`
     * for a face listed there (then @p n_components must be `dim`), all
     * otherwise.
     */
    ComponentMask
    dirichlet_mask(const unsigned int face,
                   const unsigned int n_components) const;

    unsigned int           degree = 1;
    std::set<unsigned int> dirichlet_faces;
    /**
     * The faces of `Dirichlet components`, each with the displacement
     * components (`dim` flags) it fixes.
     */
    std::map<unsigned int, std::vector<bool>> dirichlet_components;
    /** `Dirichlet components` as written, for error messages. */
    std::string dirichlet_components_text;
    /** Cells of size h within this many h of `Omega_n` (0: everywhere). */
    unsigned int graded_mesh_layers  = 0;
    unsigned int adaptive_cycles     = 0;
    double       refinement_fraction = 0.3;
  };
} // namespace ltn

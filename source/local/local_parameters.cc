#include <deal.II/base/utilities.h>

#include <ltn/base/input_error.h>
#include <ltn/local/local_parameters.h>
#include <ltn/problem/geometry.h>

namespace ltn
{
  template <int dim>
  void
  LocalParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Local model");
    {
      prm.declare_entry("Finite element degree",
                        "1",
                        Patterns::Integer(1, 4),
                        "Degree p of the continuous FE_Q(p) elements of the "
                        "local model (of each displacement component in "
                        "elasticity).");
      prm.declare_entry("Dirichlet boundaries",
                        "x+",
                        Patterns::List(Patterns::Selection("x-|x+|y-|y+|z-|z+"),
                                       0,
                                       6),
                        "Faces of the body with the Dirichlet condition "
                        "u = `Boundary data` of `Diffusion data` or "
                        "`Elasticity data` (and, where the nonlocal region "
                        "touches them, the volume constraint on its physical "
                        "collar). The other faces of the local region on the "
                        "body's boundary get the Neumann condition: du/dn = "
                        "`Diffusion data/Boundary gradient` . n in "
                        "diffusion, the traction `Elasticity data/Traction` "
                        "- `Pressure` n in elasticity.");
      prm.declare_entry("Dirichlet components",
                        "",
                        Patterns::Anything(),
                        "Elasticity only: a comma-separated list of "
                        "`face: components`, e.g. `x-: x, y-: y, z-: z|y`. "
                        "On a listed face (one of the Dirichlet boundaries) "
                        "only these displacement components (x, y, z) are "
                        "fixed, the traction acts on the others; Dirichlet "
                        "boundaries not listed fix all components.");
      prm.declare_entry("Graded mesh layers",
                        "0",
                        Patterns::Integer(0, 1000),
                        "0: the local mesh has cells of `Discretization/Mesh "
                        "size` h everywhere. n > 0: all cells within n h of "
                        "the nonlocal region have size h; a cell of size 2^k h "
                        "lies at least 2^(k-1) n h from it, up to the coarsest "
                        "cells the body and the nonlocal region's corners "
                        "allow. Far from the "
                        "nonlocal region the field is smooth and coarse cells "
                        "resolve it. Coupled scenes only.");
      prm.declare_entry("Adaptive refinement cycles",
                        "0",
                        Patterns::Integer(0, 20),
                        "On every level, after the first coupled solve, "
                        "refine the local mesh this many times by Kelly's "
                        "error indicator, solving again each time (one line "
                        "each in the convergence table; particles and "
                        "horizon stay those of the level).");
      prm.declare_entry("Refinement fraction",
                        "0.3",
                        Patterns::Double(0, 1),
                        "The fraction of cells, with the largest indicators, "
                        "that an adaptive cycle refines.");
    }
    prm.leave_subsection();
  }



  namespace
  {
    /** The pieces of @p text between delimiters, trimmed, empty ones kept. */
    std::vector<std::string>
    split_keeping_empty(const std::string &text, const char delimiter)
    {
      std::vector<std::string> pieces;
      std::size_t              begin = 0;
      while (true)
        {
          const std::size_t end = text.find(delimiter, begin);
          pieces.push_back(Utilities::trim(text.substr(begin, end - begin)));
          if (end == std::string::npos)
            return pieces;
          begin = end + 1;
        }
    }



    /**
     * Parse `face: components, ...` into the fixed components of each face;
     * every face must be one of @p dirichlet_faces.
     */
    template <int dim>
    std::map<unsigned int, std::vector<bool>>
    parse_dirichlet_components(const std::string            &text,
                               const std::set<unsigned int> &dirichlet_faces)
    {
      const std::string parameter = "Local model/Dirichlet components";
      const std::string syntax =
        "a comma-separated list of `face: components` with components "
        "separated by `|`, e.g. `x-: x, y-: y|z`";
      std::string component_names;
      for (unsigned int c = 0; c < dim; ++c)
        component_names += std::string(c == 0 ? "" : ", ") + "xyz"[c];

      std::map<unsigned int, std::vector<bool>> result;
      if (Utilities::trim(text).empty())
        return result;
      // Not split_string_list(), which drops a trailing empty entry: a
      // stray comma is an error.
      for (const std::string &entry : split_keeping_empty(text, ','))
        {
          const auto colon     = entry.find(':');
          const bool has_colon = colon != std::string::npos;
          check_input(has_colon, parameter, text, syntax);
          const std::string face_text = Utilities::trim(entry.substr(0, colon));
          const std::string components_text =
            Utilities::trim(entry.substr(colon + 1));
          check_input(!face_text.empty() && !components_text.empty(),
                      parameter,
                      text,
                      syntax);
          unsigned int face = 2 * dim;
          std::string  face_names;
          for (unsigned int f = 0; f < 2 * dim; ++f)
            {
              face_names += " " + Geometry<dim>::face_name(f);
              if (Geometry<dim>::face_name(f) == face_text)
                face = f;
            }
          check_input(face < 2 * dim,
                      parameter,
                      text,
                      "face names of the body in " + std::to_string(dim) +
                        "D, from:" + face_names + " (got `" + face_text + "`)");
          check_input(dirichlet_faces.count(face) == 1,
                      parameter,
                      text,
                      "faces among `Local model/Dirichlet boundaries` only: " +
                        face_text + " is not one of them");
          check_input(result.count(face) == 0,
                      parameter,
                      text,
                      "each face at most once: " + face_text +
                        " appears twice");

          std::vector<bool> fixed(dim, false);
          for (const std::string &name :
               split_keeping_empty(components_text, '|'))
            {
              check_input(!name.empty(), parameter, text, syntax);
              const std::size_t c = std::string("xyz").find(name);
              check_input(name.size() == 1 && c != std::string::npos && c < dim,
                          parameter,
                          text,
                          "displacement components of a " +
                            std::to_string(dim) + "D body, from " +
                            component_names + " (got `" + name + "` on " +
                            face_text + ")");
              fixed[c] = true;
            }
          result[face] = fixed;
        }
      return result;
    }
  } // namespace



  template <int dim>
  void
  LocalParameters<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Local model");
    {
      degree = prm.get_integer("Finite element degree");
      dirichlet_faces.clear();
      for (const std::string &name :
           Utilities::split_string_list(prm.get("Dirichlet boundaries")))
        dirichlet_faces.insert(
          Geometry<dim>::face_number(name, "Local model/Dirichlet boundaries"));
      dirichlet_components_text = prm.get("Dirichlet components");
      dirichlet_components =
        parse_dirichlet_components<dim>(dirichlet_components_text,
                                        dirichlet_faces);
      graded_mesh_layers  = prm.get_integer("Graded mesh layers");
      adaptive_cycles     = prm.get_integer("Adaptive refinement cycles");
      refinement_fraction = prm.get_double("Refinement fraction");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  LocalParameters<dim>::validate(const Geometry<dim> &geometry) const
  {
    check_input(graded_mesh_layers == 0 || geometry.has_nonlocal_model(),
                "Local model/Graded mesh layers",
                std::to_string(graded_mesh_layers),
                "0 in a scene without a nonlocal model (the mesh is graded "
                "towards the nonlocal region)");
  }



  template <int dim>
  ComponentMask
  LocalParameters<dim>::dirichlet_mask(const unsigned int face,
                                       const unsigned int n_components) const
  {
    if (dirichlet_faces.count(face) == 0)
      return ComponentMask(n_components, false);
    const auto listed = dirichlet_components.find(face);
    if (listed == dirichlet_components.end())
      return ComponentMask(n_components, true);
    AssertThrow(n_components == dim, ExcDimensionMismatch(n_components, dim));
    return ComponentMask(listed->second);
  }



  template struct LocalParameters<1>;
  template struct LocalParameters<2>;
  template struct LocalParameters<3>;
} // namespace ltn

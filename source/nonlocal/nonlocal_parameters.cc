#include <deal.II/base/types.h>

#include <ltn/base/input_error.h>
#include <ltn/base/memory.h>
#include <ltn/nonlocal/nonlocal_parameters.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ltn
{
  void
  NonlocalParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlocal model");
    {
      prm.declare_entry("Kernel",
                        "constant",
                        selection_pattern(kernel_names()),
                        "The kernel gamma(|xi|) of nonlocal diffusion, zero "
                        "beyond the horizon and normalized so that its second "
                        "moment is one: `constant`, `inverse distance` "
                        "(c/|xi|), or `fractional` (c |xi|^-(dim+2s)).");
      prm.declare_entry("Fractional order",
                        "0.5",
                        Patterns::Double(0, 1),
                        "The order s in (0,1) of the `fractional` kernel "
                        "|xi|^-(dim+2s). Ignored by the other kernels.");

      prm.declare_entry("Horizon",
                        "0.125",
                        Patterns::Double(),
                        "The horizon eps: the radius of the kernel's support "
                        "(length units). Must be positive. Ignored when "
                        "`Horizon to mesh size ratio` is positive.");
      prm.declare_entry("Horizon to mesh size ratio",
                        "0",
                        Patterns::Double(0),
                        "If positive, the horizon is this multiple m of the "
                        "mesh size of each level, eps = m h, so that a "
                        "refinement study drives eps -> 0 (asymptotic "
                        "compatibility). Zero keeps `Horizon` fixed.");
      prm.declare_entry("Particle spacing to mesh size ratio",
                        "1",
                        Patterns::Double(0),
                        "2D and 3D: the spacing of the particle lattice as a "
                        "multiple of the mesh size of each level. The "
                        "lattice fills the nonlocal region, so the spacing "
                        "must divide its extents; it need not line up with "
                        "the finite element mesh.");
      prm.declare_entry("Operator",
                        "auto",
                        selection_pattern(operator_storage_names()),
                        "How the particle operator (2D, 3D) is stored: "
                        "`assembled` (a sparse matrix; needed by the direct "
                        "solvers), `matrix-free` (one stencil shared by the "
                        "particles away from collar and cracks, rows stored "
                        "only for the others; needs Coupling/Model solvers = "
                        "preconditioned gmres or preconditioned cg), or "
                        "`auto`: assembled below 50,000 particle unknowns "
                        "(and 2.5e7 unknowns times bonds per particle) "
                        "and in 1D, matrix-free from there on unless the "
                        "scene names direct solvers (the choice is printed; "
                        "doc/prm_guide.md, 'Large scenes').");
      prm.declare_entry("Finite element degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "1D: degree of the continuous finite elements of the "
                        "nonlocal weak form.");
    }
    prm.leave_subsection();
  }



  void
  NonlocalParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Nonlocal model");
    {
      kernel_kind      = parse_selection(kernel_names(), prm.get("Kernel"));
      fractional_order = prm.get_double("Fractional order");
      fixed_horizon    = prm.get_double("Horizon");
      horizon_ratio    = prm.get_double("Horizon to mesh size ratio");
      degree           = prm.get_integer("Finite element degree");
      spacing_ratio    = prm.get_double("Particle spacing to mesh size ratio");
      operator_storage =
        parse_selection(operator_storage_names(), prm.get("Operator"));
      check_input(spacing_ratio > 0,
                  "Nonlocal model/Particle spacing to mesh size ratio",
                  to_string(spacing_ratio),
                  "a positive ratio");
      check_input(horizon_ratio > 0 || fixed_horizon > 0,
                  "Nonlocal model/Horizon",
                  to_string(fixed_horizon),
                  "the horizon must be positive");
      check_input(kernel_kind != KernelKind::fractional ||
                    (fractional_order > 0 && fractional_order < 1),
                  "Nonlocal model/Fractional order",
                  to_string(fractional_order),
                  "the fractional kernel needs an order s strictly between 0 "
                  "and 1");
    }
    prm.leave_subsection();
  }



  double
  NonlocalParameters::horizon(const double h) const
  {
    return (horizon_ratio > 0) ? horizon_ratio * h : fixed_horizon;
  }



  double
  NonlocalParameters::particle_spacing(const double h) const
  {
    return spacing_ratio * h;
  }



  template <int dim>
  void
  NonlocalParameters::validate_particles(const Geometry<dim> &geometry,
                                         const unsigned int   local_degree,
                                         const double         h) const
  {
    const double spacing = particle_spacing(h);
    const double eps     = horizon(h);
    // One particle per nodal spacing of FE_Q(p), or some local control
    // modes go unobserved in the overlap and the system is singular.
    check_input(spacing_ratio * local_degree <= 1 + 1e-12,
                "Nonlocal model/Particle spacing to mesh size ratio",
                to_string(spacing_ratio),
                "at most 1/p = " + to_string(1. / local_degree) +
                  " for FE_Q(p) on the local side, so that the particles "
                  "of the overlap observe every local control");
    check_input(spacing <= eps * (1 + 1e-12),
                "Nonlocal model/Particle spacing to mesh size ratio",
                to_string(spacing_ratio),
                "the particle spacing " + to_string(spacing) +
                  " must not exceed the horizon " + to_string(eps));
    // The lattice's cells fill every box: the spacing divides each box's
    // extent and its offset from the lower corner of the boxes' bounding
    // box (the lattice's origin).
    const auto &region = geometry.nonlocal_region();
    const auto  origin = region.bounding_box().lower;
    for (const auto &box : region.boxes())
      for (unsigned int d = 0; d < dim; ++d)
        for (const auto &[length, what] :
             {std::make_pair(box.upper[d] - box.lower[d],
                             std::string("the nonlocal region's extent ")),
              std::make_pair(box.lower[d] - origin[d],
                             std::string("the offset between the nonlocal "
                                         "region's boxes "))})
          check_input(is_whole_multiple(length, spacing),
                      "Nonlocal model/Particle spacing to mesh size ratio",
                      to_string(spacing_ratio),
                      "the particle spacing " + to_string(spacing) +
                        " must divide " + what + to_string(length) +
                        " a whole number of times");
  }

  template <int dim>
  void
  NonlocalParameters::check_particle_count(
    const Geometry<dim> &geometry,
    const double         h,
    const unsigned int   collar_horizons,
    const unsigned int   unknowns_per_particle,
    const MPI_Comm       communicator) const
  {
    const double spacing = particle_spacing(h);
    // The lattice spans each box of the nonlocal region and its collar: an
    // upper bound of the particles it holds (the collar's corners are cut
    // off, and collars of boxes overlap).
    double particles = 0;
    for (const auto &box : geometry.nonlocal_region().boxes())
      {
        double in_box = 1;
        for (unsigned int d = 0; d < dim; ++d)
          in_box *= std::round((box.upper[d] - box.lower[d]) / spacing) +
                    2 * std::ceil(collar_horizons * horizon(h) / spacing);
        particles += in_box;
      }
    const double      unknowns = particles * unknowns_per_particle;
    const std::string parameter =
      "Nonlocal model/Particle spacing to mesh size ratio";
    const std::string lattice =
      "the finest level's particle lattice (spacing " + to_string(spacing) +
      ") would hold up to " + to_string(particles) + " particles with " +
      to_string(unknowns) + " unknowns";
    // The indices of deal.II's unknowns and of Trilinos's (Epetra's) maps,
    // 32 bits as Debian builds them.
    const double largest = std::min<double>(
      std::numeric_limits<types::global_dof_index>::max(),
      std::numeric_limits<TrilinosWrappers::types::int_type>::max());
    check_input(unknowns <= largest,
                parameter,
                to_string(spacing_ratio),
                "at most " + to_string(largest) +
                  " unknowns, the limit of the indices of deal.II and "
                  "Trilinos as built here: " +
                  lattice);
    // Unknown where the system does not say (then not checked).
    const double memory = physical_memory_bytes(communicator);
    check_input(memory <= 0 || 64 * unknowns <= memory,
                parameter,
                to_string(spacing_ratio),
                "a lattice that fits the memory: " + lattice +
                  ", which take at least 64 bytes each (" +
                  to_string(64 * unknowns / 1e9) + " GB), more than the " +
                  to_string(memory / 1e9) + " GB of physical memory here");
  }

  template void
  NonlocalParameters::check_particle_count(const Geometry<2> &,
                                           double,
                                           unsigned int,
                                           unsigned int,
                                           MPI_Comm) const;
  template void
  NonlocalParameters::check_particle_count(const Geometry<3> &,
                                           double,
                                           unsigned int,
                                           unsigned int,
                                           MPI_Comm) const;

  template void
  NonlocalParameters::validate_particles(const Geometry<2> &,
                                         unsigned int,
                                         double) const;
  template void
  NonlocalParameters::validate_particles(const Geometry<3> &,
                                         unsigned int,
                                         double) const;



  Kernel
  NonlocalParameters::kernel(const unsigned int dim, const double h) const
  {
    return Kernel(kernel_kind, fractional_order, dim, horizon(h));
  }
} // namespace ltn

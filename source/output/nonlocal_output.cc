#include <ltn/output/field_output.h>
#include <ltn/output/nonlocal_output.h>
#include <ltn/output/parallel_vtu.h>
#include <ltn/output/point_cloud_output.h>

namespace ltn
{
  std::string
  write_nonlocal_vtu(const NonlocalWeakForm1D            &nonlocal,
                     const TrilinosWrappers::MPI::Vector &field,
                     const Function<1>                   *exact,
                     const std::string                   &directory,
                     const std::string                   &name)
  {
    return write_field_vtu<1>(
      nonlocal.get_dof_handler(),
      field,
      exact,
      [&](const Point<1> &p) { return nonlocal.region_of(p); },
      directory,
      name);
  }



  template <int dim>
  std::string
  write_nonlocal_vtu(const ParticleDiffusion<dim>        &nonlocal,
                     const TrilinosWrappers::MPI::Vector &field,
                     const Function<dim>                 *exact,
                     const std::string                   &directory,
                     const std::string                   &name)
  {
    const auto          positions = nonlocal.owned_positions();
    std::vector<double> values(field.begin(), field.end());
    std::vector<std::pair<std::string, std::vector<double>>> fields;
    if (exact != nullptr)
      {
        std::vector<double> exact_values, error;
        for (std::size_t i = 0; i < positions.size(); ++i)
          {
            exact_values.push_back(exact->value(positions[i]));
            error.push_back(values[i] - exact_values.back());
          }
        fields.emplace_back("u_exact", exact_values);
        fields.emplace_back("error", error);
      }
    fields.emplace(fields.begin(), "u", std::move(values));
    std::vector<double> tags;
    for (const Region r : nonlocal.owned_regions())
      tags.push_back(static_cast<double>(r));
    fields.emplace_back("region", tags);
    AssertDimension(positions.size(), owned.n_elements());

    PointCloudOutput<dim> output(positions, fields);
    return write_parallel_vtu(output,
                              directory,
                              name,
                              nonlocal.get_model().communicator);
  }

  template <int dim>
  std::string
  write_nonlocal_vtu(const ParticleElasticity<dim>       &nonlocal,
                     const TrilinosWrappers::MPI::Vector &field,
                     const Function<dim>                 *exact,
                     const std::string                   &directory,
                     const std::string                   &name)
  {
    using Particles                       = ParticleElasticity<dim>;
    const auto                  positions = nonlocal.owned_positions();
    const auto                  first     = positions.empty() ?
                                              0 :
                                              nonlocal.get_model().owned.nth_index_in_set(0) /
                           Particles::n_components;
    std::vector<Tensor<1, dim>> displacement(positions.size());
    std::vector<double>         dilatation(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i)
      {
        for (unsigned int c = 0; c < dim; ++c)
          displacement[i][c] = field(Particles::dof(first + i, c));
        dilatation[i] = field(Particles::dof(first + i, dim));
      }
    std::vector<std::pair<std::string, std::vector<Tensor<1, dim>>>> vectors;
    vectors.emplace_back("displacement", displacement);
    if (exact != nullptr)
      {
        std::vector<Tensor<1, dim>> exact_values(positions.size()), error;
        for (std::size_t i = 0; i < positions.size(); ++i)
          {
            for (unsigned int c = 0; c < dim; ++c)
              exact_values[i][c] = exact->value(positions[i], c);
            error.push_back(displacement[i] - exact_values[i]);
          }
        vectors.emplace_back("displacement_exact", exact_values);
        vectors.emplace_back("error", error);
      }
    std::vector<double> tags;
    for (const Region r : nonlocal.owned_regions())
      tags.push_back(static_cast<double>(r));
    const std::vector<std::pair<std::string, std::vector<double>>> scalars = {
      {"dilatation", dilatation},
      {"broken_bond_fraction", nonlocal.owned_broken_bond_fractions()},
      {"region", tags}};
    PointCloudOutput<dim> output(positions, scalars, vectors);
    return write_parallel_vtu(output,
                              directory,
                              name,
                              nonlocal.get_model().communicator);
  }

  template std::string
  write_nonlocal_vtu(const ParticleElasticity<2> &,
                     const TrilinosWrappers::MPI::Vector &,
                     const Function<2> *,
                     const std::string &,
                     const std::string &);
  template std::string
  write_nonlocal_vtu(const ParticleElasticity<3> &,
                     const TrilinosWrappers::MPI::Vector &,
                     const Function<3> *,
                     const std::string &,
                     const std::string &);
  template std::string
  write_nonlocal_vtu(const ParticleDiffusion<2> &,
                     const TrilinosWrappers::MPI::Vector &,
                     const Function<2> *,
                     const std::string &,
                     const std::string &);
  template std::string
  write_nonlocal_vtu(const ParticleDiffusion<3> &,
                     const TrilinosWrappers::MPI::Vector &,
                     const Function<3> *,
                     const std::string &,
                     const std::string &);
} // namespace ltn

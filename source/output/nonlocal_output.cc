#include <ltn/output/field_output.h>
#include <ltn/output/nonlocal_output.h>
#include <ltn/output/point_cloud_output.h>

#include <fstream>

namespace ltn
{
  void
  write_nonlocal_vtu(const NonlocalWeakForm1D &nonlocal,
                     const Vector<double>     &field,
                     const Function<1>        *exact,
                     const std::string        &filename)
  {
    write_field_vtu<1>(nonlocal.get_dof_handler(),
                       field,
                       exact,
                       nonlocal.dof_regions(),
                       filename);
  }



  template <int dim>
  void
  write_nonlocal_vtu(const ParticleDiffusion<dim> &nonlocal,
                     const Vector<double>         &field,
                     const Function<dim>          *exact,
                     const std::string            &filename)
  {
    const auto &positions = nonlocal.get_positions();
    std::vector<std::pair<std::string, std::vector<double>>> fields;
    fields.emplace_back("u", std::vector<double>(field.begin(), field.end()));
    if (exact != nullptr)
      {
        std::vector<double> values(positions.size()), error(positions.size());
        for (std::size_t i = 0; i < positions.size(); ++i)
          {
            values[i] = exact->value(positions[i]);
            error[i]  = field[i] - values[i];
          }
        fields.emplace_back("u_exact", values);
        fields.emplace_back("error", error);
      }
    std::vector<double> tags;
    for (const Region r : nonlocal.regions())
      tags.push_back(static_cast<double>(r));
    fields.emplace_back("region", tags);

    std::ofstream out(filename);
    PointCloudOutput<dim>(positions, fields).write_vtu(out);
  }

  template void
  write_nonlocal_vtu(const ParticleDiffusion<2> &,
                     const Vector<double> &,
                     const Function<2> *,
                     const std::string &);
  template void
  write_nonlocal_vtu(const ParticleDiffusion<3> &,
                     const Vector<double> &,
                     const Function<3> *,
                     const std::string &);
} // namespace ltn

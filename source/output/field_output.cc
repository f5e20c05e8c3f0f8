#include <deal.II/base/data_out_base.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <ltn/output/field_output.h>

#include <fstream>

namespace ltn
{
  template <int dim>
  void
  write_field_vtu(const DoFHandler<dim>     &dof_handler,
                  const Vector<double>      &field,
                  const Function<dim>       *exact_solution,
                  const std::vector<Region> &regions,
                  const std::string         &filename)
  {
    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(field, "u");

    Vector<double> exact(dof_handler.n_dofs()), error(dof_handler.n_dofs());
    if (exact_solution != nullptr)
      {
        VectorTools::interpolate(dof_handler, *exact_solution, exact);
        error = field;
        error -= exact;
        data_out.add_data_vector(exact, "u_exact");
        data_out.add_data_vector(error, "error");
      }
    Vector<double> region(regions.size());
    for (std::size_t i = 0; i < regions.size(); ++i)
      region[i] = static_cast<double>(regions[i]);
    data_out.add_data_vector(region, "region");

    data_out.build_patches(dof_handler.get_fe().degree);
    std::ofstream out(filename);
    data_out.write_vtu(out);
  }



  void
  write_level_collection(
    const std::string                                 &filename,
    const std::vector<std::pair<double, std::string>> &level_files)
  {
    std::ofstream out(filename);
    DataOutBase::write_pvd_record(out, level_files);
  }

  template void
  write_field_vtu(const DoFHandler<1> &,
                  const Vector<double> &,
                  const Function<1> *,
                  const std::vector<Region> &,
                  const std::string &);
  template void
  write_field_vtu(const DoFHandler<2> &,
                  const Vector<double> &,
                  const Function<2> *,
                  const std::vector<Region> &,
                  const std::string &);
  template void
  write_field_vtu(const DoFHandler<3> &,
                  const Vector<double> &,
                  const Function<3> *,
                  const std::vector<Region> &,
                  const std::string &);
} // namespace ltn

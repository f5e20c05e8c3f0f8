#include <deal.II/base/data_out_base.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/mapping_q1.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <ltn/output/field_output.h>
#include <ltn/output/parallel_vtu.h>

#include <fstream>
#include <map>

namespace ltn
{
  namespace
  {
    /** @p v with the values of @p dof_handler's locally relevant dofs. */
    template <int dim>
    TrilinosWrappers::MPI::Vector
    ghosted(const DoFHandler<dim>               &dof_handler,
            const TrilinosWrappers::MPI::Vector &v)
    {
      TrilinosWrappers::MPI::Vector result(
        dof_handler.locally_owned_dofs(),
        DoFTools::extract_locally_relevant_dofs(dof_handler),
        dof_handler.get_communicator());
      result = v;
      return result;
    }
  } // namespace



  template <int dim>
  std::array<TrilinosWrappers::MPI::Vector, 2>
  nodal_exact_and_error(const DoFHandler<dim>               &dof_handler,
                        const TrilinosWrappers::MPI::Vector &field,
                        const Function<dim>                 &exact)
  {
    AssertThrow(exact.n_components == dof_handler.get_fe().n_components(),
                ExcDimensionMismatch(exact.n_components,
                                     dof_handler.get_fe().n_components()));
    const IndexSet                owned = dof_handler.locally_owned_dofs();
    TrilinosWrappers::MPI::Vector values(owned, dof_handler.get_communicator());
    TrilinosWrappers::MPI::Vector error(values);
    VectorTools::interpolate(dof_handler, exact, values);
    for (const auto i : owned)
      error(i) = field(i) - values(i);
    error.compress(VectorOperation::insert);
    return {{ghosted(dof_handler, values), ghosted(dof_handler, error)}};
  }



  template <int dim>
  std::string
  write_field_vtu(const DoFHandler<dim>               &dof_handler,
                  const TrilinosWrappers::MPI::Vector &field,
                  const Function<dim>                 *exact_solution,
                  const std::function<Region(const Point<dim> &)> &region_of,
                  const std::string                               &directory,
                  const std::string                               &name)
  {
    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(field, "u");

    std::array<TrilinosWrappers::MPI::Vector, 2> exact_and_error;
    if (exact_solution != nullptr)
      {
        exact_and_error =
          nodal_exact_and_error(dof_handler, field, *exact_solution);
        data_out.add_data_vector(exact_and_error[0], "u_exact");
        data_out.add_data_vector(exact_and_error[1], "error");
      }

    std::map<types::global_dof_index, Point<dim>> support_points;
    DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                         dof_handler,
                                         support_points);
    const IndexSet                owned = dof_handler.locally_owned_dofs();
    TrilinosWrappers::MPI::Vector region(owned, dof_handler.get_communicator());
    for (const auto i : owned)
      region(i) = static_cast<double>(region_of(support_points.at(i)));
    region.compress(VectorOperation::insert);
    const TrilinosWrappers::MPI::Vector region_ghosted =
      ghosted(dof_handler, region);
    data_out.add_data_vector(region_ghosted, "region");

    data_out.build_patches(dof_handler.get_fe().degree);
    return write_parallel_vtu(data_out,
                              directory,
                              name,
                              dof_handler.get_communicator());
  }



  void
  write_level_collection(
    const std::string                                 &filename,
    const std::vector<std::pair<double, std::string>> &level_files)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    std::ofstream out(filename);
    DataOutBase::write_pvd_record(out, level_files);
  }

  void
  write_grouped_collection(
    const std::string                                              &filename,
    const std::vector<std::vector<std::pair<double, std::string>>> &parts)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    std::ofstream out(filename);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" "
           "byte_order=\"LittleEndian\">\n  <Collection>\n";
    for (std::size_t part = 0; part < parts.size(); ++part)
      for (const auto &[time, file] : parts[part])
        out << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\""
            << part << "\" file=\"" << file << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
  }

#define LTN_INSTANTIATE(dim)                                                   \
  template std::string write_field_vtu(                                        \
    const DoFHandler<dim> &,                                                   \
    const TrilinosWrappers::MPI::Vector &,                                     \
    const Function<dim> *,                                                     \
    const std::function<Region(const Point<dim> &)> &,                         \
    const std::string &,                                                       \
    const std::string &);                                                      \
  template std::array<TrilinosWrappers::MPI::Vector, 2> nodal_exact_and_error( \
    const DoFHandler<dim> &,                                                   \
    const TrilinosWrappers::MPI::Vector &,                                     \
    const Function<dim> &);
  LTN_INSTANTIATE(1)
  LTN_INSTANTIATE(2)
  LTN_INSTANTIATE(3)
#undef LTN_INSTANTIATE
} // namespace ltn

#include <ltn/output/point_cloud_output.h>

namespace ltn
{
  template <int dim>
  PointCloudOutput<dim>::PointCloudOutput(
    const std::vector<Point<dim>>                                  &points,
    const std::vector<std::pair<std::string, std::vector<double>>> &fields,
    const std::vector<std::pair<std::string, std::vector<Tensor<1, dim>>>>
      &vector_fields)
    : patches(points.size())
  {
    for (const auto &field : fields)
      names.push_back(field.first);
    for (const auto &field : vector_fields)
      {
        vector_ranges.emplace_back(
          names.size(),
          names.size() + dim - 1,
          field.first,
          DataComponentInterpretation::component_is_part_of_vector);
        for (unsigned int d = 0; d < dim; ++d)
          names.push_back(field.first);
      }
    for (std::size_t i = 0; i < points.size(); ++i)
      {
        patches[i].vertices[0] = points[i];
        patches[i].patch_index = i;
        patches[i].data.reinit(names.size(), 1);
        unsigned int row = 0;
        for (const auto &field : fields)
          patches[i].data(row++, 0) = field.second[i];
        for (const auto &field : vector_fields)
          for (unsigned int d = 0; d < dim; ++d)
            patches[i].data(row++, 0) = field.second[i][d];
      }
  }



  template <int dim>
  const std::vector<DataOutBase::Patch<0, dim>> &
  PointCloudOutput<dim>::get_patches() const
  {
    return patches;
  }



  template <int dim>
  std::vector<std::string>
  PointCloudOutput<dim>::get_dataset_names() const
  {
    return names;
  }

  template <int dim>
  std::vector<
    std::tuple<unsigned int,
               unsigned int,
               std::string,
               DataComponentInterpretation::DataComponentInterpretation>>
  PointCloudOutput<dim>::get_nonscalar_data_ranges() const
  {
    return vector_ranges;
  }

  template class PointCloudOutput<1>;
  template class PointCloudOutput<2>;
  template class PointCloudOutput<3>;
} // namespace ltn

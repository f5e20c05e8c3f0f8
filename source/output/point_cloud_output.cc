#include <ltn/output/point_cloud_output.h>

namespace ltn
{
  template <int dim>
  PointCloudOutput<dim>::PointCloudOutput(
    const std::vector<Point<dim>>                                  &points,
    const std::vector<std::pair<std::string, std::vector<double>>> &fields)
    : patches(points.size())
  {
    for (const auto &field : fields)
      names.push_back(field.first);
    for (std::size_t i = 0; i < points.size(); ++i)
      {
        patches[i].vertices[0] = points[i];
        patches[i].patch_index = i;
        patches[i].data.reinit(fields.size(), 1);
        for (std::size_t f = 0; f < fields.size(); ++f)
          patches[i].data(f, 0) = fields[f].second[i];
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

  template class PointCloudOutput<1>;
  template class PointCloudOutput<2>;
  template class PointCloudOutput<3>;
} // namespace ltn

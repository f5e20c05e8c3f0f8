#pragma once

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/point.h>

#include <string>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * Scalar fields on a cloud of points (particles), written through deal.II's
   * own writers (VTU, and all other DataOutInterface formats): each point is
   * a patch of dimension zero, as in Particles::DataOut.
   */
  template <int dim>
  class PointCloudOutput : public DataOutInterface<0, dim>
  {
  public:
    /**
     * @param points the positions.
     * @param fields named values, one per point each.
     */
    PointCloudOutput(
      const std::vector<Point<dim>>                                  &points,
      const std::vector<std::pair<std::string, std::vector<double>>> &fields);

  private:
    const std::vector<DataOutBase::Patch<0, dim>> &
    get_patches() const override;

    std::vector<std::string>
    get_dataset_names() const override;

    std::vector<DataOutBase::Patch<0, dim>> patches;
    std::vector<std::string>                names;
  };
} // namespace ltn

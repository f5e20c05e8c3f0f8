#pragma once

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/numerics/data_component_interpretation.h>

#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * Scalar and vector fields on a cloud of points (particles), written
   * through deal.II's own writers (VTU, and all other DataOutInterface
   * formats): each point is a patch of dimension zero, as in
   * Particles::DataOut. Vector fields are marked as such, so that ParaView
   * shows them as vectors (glyphs, Warp By Vector).
   */
  template <int dim>
  class PointCloudOutput : public DataOutInterface<0, dim>
  {
  public:
    /**
     * @param points the positions.
     * @param fields named values, one per point each.
     * @param vector_fields named vectors, one per point each.
     */
    PointCloudOutput(
      const std::vector<Point<dim>>                                  &points,
      const std::vector<std::pair<std::string, std::vector<double>>> &fields,
      const std::vector<std::pair<std::string, std::vector<Tensor<1, dim>>>>
        &vector_fields = {});

  private:
    const std::vector<DataOutBase::Patch<0, dim>> &
    get_patches() const override;

    std::vector<std::string>
    get_dataset_names() const override;

    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
    get_nonscalar_data_ranges() const override;

    std::vector<DataOutBase::Patch<0, dim>> patches;
    std::vector<std::string>                names;
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      vector_ranges;
  };
} // namespace ltn

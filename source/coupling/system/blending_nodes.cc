#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/mapping_q1.h>

#include <ltn/coupling/system/blending_nodes.h>
#include <ltn/coupling/system/coupling_system.h>
#include <ltn/problem/blending_function.h>

#include <algorithm>
#include <tuple>

namespace ltn
{
  void
  add_blending_nodes(OverlapQuadrature<1>     &overlap,
                     const Geometry<1>        &geometry,
                     const NonlocalWeakForm1D &nonlocal,
                     const DoFHandler<1>      &local_dofs)
  {
    const std::array<const DoFHandler<1> *, 2> dofs = {
      {&nonlocal.get_dof_handler(), &local_dofs}};
    // (position, model, degree of freedom) of every degree of freedom.
    std::vector<std::tuple<double, unsigned int, types::global_dof_index>>
          entries;
    auto &blending = overlap.blending_nodes;
    for (const unsigned int k : {nonlocal_model, local_model})
      {
        std::vector<Point<1>> positions(dofs[k]->n_dofs());
        DoFTools::map_dofs_to_support_points(MappingQ1<1>(),
                                             *dofs[k],
                                             positions);
        blending.node_of_dof[k].resize(positions.size());
        for (types::global_dof_index i = 0; i < positions.size(); ++i)
          entries.emplace_back(positions[i][0], k, i);
      }
    std::sort(entries.begin(), entries.end());

    const double              tolerance = geometry.tolerance();
    const BlendingFunction<1> beta(geometry);
    double                    last = 0;
    for (const auto &[x, k, i] : entries)
      {
        if (blending.beta.empty() || x - last > tolerance)
          {
            blending.beta.push_back(beta.value(Point<1>(x)));
            last = x;
          }
        blending.node_of_dof[k][i] = blending.beta.size() - 1;
      }
  }
} // namespace ltn

#include <ltn/base/model_lattice.h>

namespace ltn
{
  ModelLattice::ModelLattice(
    const unsigned int                      node_dofs,
    std::vector<std::array<double, 3>>      node_positions,
    std::function<void(LatticeSurrogate &)> build_surrogate)
    : node_dofs(node_dofs)
    , node_positions(std::move(node_positions))
    , build_surrogate(std::move(build_surrogate))
  {}



  const LatticeSurrogate &
  ModelLattice::surrogate() const
  {
    if (!built)
      {
        auto surrogate = std::make_unique<LatticeSurrogate>();
        build_surrogate(*surrogate);
        built = std::move(surrogate);
      }
    return *built;
  }



  std::size_t
  ModelLattice::memory_consumption() const
  {
    if (!built)
      return 0;
    const auto bytes = [](const TrilinosWrappers::SparseMatrix &m) {
      return m.m() == 0 ? std::size_t(0) : m.memory_consumption();
    };
    return bytes(built->matrix) + bytes(built->collar) +
           built->nodes.size() * sizeof(unsigned int);
  }
} // namespace ltn

#include <ltn/coupling/system/normal_equations.h>

namespace ltn
{
  NormalEquations::BlockVectorType
  NormalEquations::gradient(const Observation &d) const
  {
    return adjoint({{observe_transpose(0, d), observe_transpose(1, d)}});
  }
} // namespace ltn

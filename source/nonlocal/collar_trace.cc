#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ltn/nonlocal/collar_trace.h>

namespace ltn
{
  using namespace dealii;

  std::vector<double>
  collar_trace_weights(const std::vector<double> &projected_weights)
  {
    const int M = projected_weights.size();
    AssertThrow(M > 0, ExcMessage("a stencil reaches at least one layer"));
    const int N = 60 * M;
    // Row j - 1 for free particle j; columns j - 1 for v_j; the collar
    // values move to the right-hand sides, one per layer.
    LAPACKFullMatrix<double> chain(N, N);
    FullMatrix<double>       collar(N, M);
    for (int j = 1; j <= N; ++j)
      for (int m = 1; m <= M; ++m)
        {
          const double w = projected_weights[m - 1];
          chain(j - 1, j - 1) += 2 * w;
          chain(j - 1, std::min(j + m, N) - 1) -= w;
          if (j - m >= 1)
            chain(j - 1, j - m - 1) -= w;
          else
            collar(j - 1, m - j) += w; // layer l = m - j + 1
        }
    chain.compute_lu_factorization();
    std::vector<double> trace(M);
    for (int l = 0; l < M; ++l)
      {
        Vector<double> v(N);
        for (int j = 0; j < N; ++j)
          v(j) = collar(j, l);
        chain.solve(v);
        trace[l] = v(N - 1);
      }
    return trace;
  }
} // namespace ltn

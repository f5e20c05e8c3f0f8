#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <ltn/model_solvers/stencil_matrix.h>

#include <Epetra_MpiComm.h>
#include <ml_MultiLevelPreconditioner.h>
#include <ml_include.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

namespace ltn
{
  namespace
  {
    constexpr std::size_t max_offsets = 8;

    /** Four doubles (one AVX2 register, two SSE2 ones), and their bits. */
    using Lanes = double __attribute__((vector_size(4 * sizeof(double))));
    using LaneBits =
      std::int64_t __attribute__((vector_size(4 * sizeof(std::int64_t))));

    /** Per 4-bit number b: lane l all ones where bit l of b is set. */
    const std::array<LaneBits, 16> lane_masks = [] {
      std::array<LaneBits, 16> masks;
      for (unsigned int b = 0; b < 16; ++b)
        for (unsigned int l = 0; l < 4; ++l)
          masks[b][l] = (b >> l) & 1u ? -1 : 0;
      return masks;
    }();

    template <typename Vector, typename Value>
    Vector
    load(const Value *values)
    {
      Vector v;
      std::memcpy(&v, values, sizeof(v));
      return v;
    }

    /**
     * The rows from @p begin in groups of four, as long as a group ends by
     * @p end, whose every partner is owned; returns the first row left.
     * An absent partner's value is masked to zero: the bits of offset k of
     * the group's four rows, gathered from their four bytes into a 4-bit
     * number by one multiplication, pick the lanes kept. Scalar, the rows'
     * bits converted to doubles took 8 % of a run of the 1e5 bar (perf).
     */
    template <int K>
    std::size_t
    apply_inner(const double       *x,
                const std::uint8_t *present,
                const double       *diagonal,
                const std::int64_t *offsets,
                const double        off_diagonal,
                const std::size_t   begin,
                const std::size_t   end,
                double             *y)
    {
      std::array<std::ptrdiff_t, K> o;
      std::copy_n(offsets, K, o.begin());
      const Lanes c = Lanes{} + off_diagonal;
      std::size_t i = begin;
      for (; i + 4 <= end; i += 4)
        {
          // Byte l of `bits` is row i + l's; bit k of each byte moves to
          // bit 24 + l of the product, and nothing else reaches bits 24-27.
          const std::uint32_t bits = load<std::uint32_t>(present + i);
          Lanes               sum  = {};
          for (int k = 0; k < K; ++k)
            {
              const std::uint32_t lanes =
                (((bits >> k) & 0x01010101u) * 0x01020408u) >> 24;
              sum += reinterpret_cast<Lanes>(load<LaneBits>(x + i + o[k]) &
                                             lane_masks[lanes & 15u]);
            }
          const Lanes result =
            load<Lanes>(diagonal + i) * load<Lanes>(x + i) + c * sum;
          std::memcpy(y + i, &result, sizeof(result));
        }
      return i;
    }

    /**
     * The stencils that serve ML's finest levels, by the matrix that ML's
     * operator holds (its `data`, which ML's other functions on the level
     * read as that matrix, so that it cannot point to the stencil itself).
     */
    std::map<const void *, const StencilMatrix *> served;

    /** ML's finest-level product, where a StencilMatrix serves it. */
    int
    apply_stencil_matrix(ML_Operator *op, int, double *x, int, double *y)
    {
      served.at(op->data)->apply(x, y);
      return 1;
    }
  } // namespace



  StencilMatrix::StencilMatrix(const Epetra_CrsMatrix &matrix)
    : matrix(matrix)
    , communicator(dynamic_cast<const Epetra_MpiComm &>(matrix.Comm()).Comm())
  {
    const Epetra_Map &rows = matrix.RowMap();
    const std::size_t n    = matrix.NumMyRows();
    bool form = rows.LinearMap() && rows.SameAs(matrix.DomainMap()) &&
                rows.SameAs(matrix.RangeMap());
    first = n > 0 ? rows.GID64(0) : 0;

    // The offsets and the off-diagonal value, then the rows' bits.
    std::vector<std::int64_t> local_offsets;
    double                    value = std::numeric_limits<double>::quiet_NaN();
    const auto                for_each_entry = [&](const auto &visit) {
      for (std::size_t i = 0; i < n && form; ++i)
        {
          int     count;
          double *values;
          int    *columns;
          matrix.ExtractMyRowView(i, count, values, columns);
          for (int j = 0; j < count; ++j)
            visit(i,
                  matrix.GCID64(columns[j]) - (first + std::int64_t(i)),
                  values[j]);
        }
    };
    for_each_entry([&](std::size_t, const std::int64_t offset, const double a) {
      if (offset == 0 || a == 0)
        return;
      if (std::isnan(value))
        value = a;
      form = form && a == value;
      if (std::find(local_offsets.begin(), local_offsets.end(), offset) ==
          local_offsets.end())
        local_offsets.push_back(offset);
      form = form && local_offsets.size() <= max_offsets;
    });
    const double highest =
      Utilities::MPI::max(std::isnan(value) ?
                            -std::numeric_limits<double>::max() :
                            value,
                          communicator);
    const double lowest =
      Utilities::MPI::min(std::isnan(value) ?
                            std::numeric_limits<double>::max() :
                            value,
                          communicator);
    form = form && (highest < lowest || highest == lowest);
    for (const auto &ranks :
         Utilities::MPI::all_gather(communicator, local_offsets))
      for (const std::int64_t offset : ranks)
        if (std::find(offsets.begin(), offsets.end(), offset) == offsets.end())
          offsets.push_back(offset);
    std::sort(offsets.begin(), offsets.end());
    form         = form && offsets.size() <= max_offsets;
    off_diagonal = highest == lowest ? highest : 0.;

    present.assign(n, 0);
    diagonal.assign(n, 0.);
    for_each_entry(
      [&](const std::size_t i, const std::int64_t offset, const double a) {
        if (offset == 0)
          diagonal[i] += a;
        else if (a != 0)
          {
            const std::uint8_t bit =
              1u << (std::find(offsets.begin(), offsets.end(), offset) -
                     offsets.begin());
            form = form && !(present[i] & bit); // no column twice
            present[i] |= bit;
          }
      });
    stencil = Utilities::MPI::min(form ? 1 : 0, communicator) == 1;
    if (!stencil)
      {
        present  = {};
        diagonal = {};
        return;
      }

    const std::int64_t reach_below =
      offsets.empty() ? 0 : std::min<std::int64_t>(0, offsets.front());
    const std::int64_t reach_above =
      offsets.empty() ? 0 : std::max<std::int64_t>(0, offsets.back());
    inner_begin = std::min<std::int64_t>(n, -reach_below);
    inner_end =
      std::max<std::int64_t>(inner_begin, std::int64_t(n) - reach_above);
    const std::int64_t end = first + n;
    below                  = std::max<std::int64_t>(0, first + reach_below);
    above = std::min<std::int64_t>(matrix.NumGlobalRows64(), end + reach_above);
    IndexSet read(matrix.NumGlobalRows64());
    if (n > 0)
      {
        read.add_range(below, first);
        read.add_range(end, above);
      }
    read.compress();
    edges = std::make_unique<Epetra_Vector>(
      read.make_trilinos_map(communicator, true));
    importer =
      std::make_unique<Epetra_Import>(edges->Map(), matrix.DomainMap());
  }



  StencilMatrix::~StencilMatrix()
  {
    const auto entry = served.find(&matrix);
    if (entry != served.end() && entry->second == this)
      served.erase(entry);
  }



  bool
  StencilMatrix::is_stencil() const
  {
    return stencil;
  }



  void
  StencilMatrix::apply(const double *x, double *y) const
  {
    Assert(stencil, ExcInternalError());
    const Epetra_Vector owned(View,
                              matrix.DomainMap(),
                              const_cast<double *>(x));
    const int           error = edges->Import(owned, *importer, Insert);
    AssertThrow(error == 0, ExcMessage("importing the stencil's edges"));

    // The rows near the range's ends, partner by partner.
    const std::size_t  n   = present.size();
    const std::int64_t end = first + n, n_below = first - below;
    const double      *edge_values = edges->Values();
    const auto         value       = [&](const std::int64_t g) {
      return g < first ? edge_values[g - below] :
                           g < end   ? x[g - first] :
                                       edge_values[n_below + g - end];
    };
    const auto edge_row = [&](const std::size_t i) {
      double sum = 0;
      for (std::size_t k = 0; k < offsets.size(); ++k)
        if (present[i] & (1u << k))
          sum += value(first + std::int64_t(i) + offsets[k]);
      y[i] = diagonal[i] * x[i] + off_diagonal * sum;
    };
    for (std::size_t i = 0; i < inner_begin; ++i)
      edge_row(i);
    const auto inner = [&](auto n_offsets) {
      return apply_inner<decltype(n_offsets)::value>(x,
                                                     present.data(),
                                                     diagonal.data(),
                                                     offsets.data(),
                                                     off_diagonal,
                                                     inner_begin,
                                                     inner_end,
                                                     y);
    };
    std::size_t rest = inner_begin;
    if (offsets.size() == 4) // the 2D lattice
      rest = inner(std::integral_constant<int, 4>());
    else if (offsets.size() == 6) // the 3D lattice
      rest = inner(std::integral_constant<int, 6>());
    // The inner rows past the last group of four, or of another number of
    // offsets, and the rows near the upper end.
    for (std::size_t i = rest; i < n; ++i)
      edge_row(i);
  }



  bool
  StencilMatrix::serve_finest_level(
    const TrilinosWrappers::PreconditionAMG &amg) const
  {
    const auto *hierarchy =
      dynamic_cast<const ML_Epetra::MultiLevelPreconditioner *>(
        &amg.trilinos_operator());
    ML_Operator *finest = hierarchy ? hierarchy->GetML()->Amat +
                                        hierarchy->GetML()->ML_finest_level :
                                      nullptr;
    const bool   mine =
      finest != nullptr && finest->data == static_cast<const void *>(&matrix);
    // All ranks or none: the product imports, collectively.
    if (Utilities::MPI::min((stencil && mine) ? 1 : 0, communicator) == 0)
      return false;
    served[&matrix] = this;
    ML_Operator_Set_ApplyFunc(finest, &apply_stencil_matrix);
    return true;
  }



  std::size_t
  StencilMatrix::memory_consumption() const
  {
    return present.capacity() * sizeof(std::uint8_t) +
           diagonal.capacity() * sizeof(double) +
           (edges ? edges->MyLength() * sizeof(double) : 0);
  }
} // namespace ltn

#pragma once

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ltn/base/discrete_model.h>
#include <ltn/nonlocal/lattice_rows.h>
#include <ltn/nonlocal/particle_lattice.h>

#include <Epetra_Import.h>
#include <Epetra_Vector.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace ltn
{
  using namespace dealii;

  /**
   * The rows of particles whose bonds are some of the stencil's and whose
   * blocks are the shared ones scaled per particle (doc/discretization.md,
   * 'Matrix-free particle operators', "Rows next to a crack"): particle
   * `i` with intact bonds
   * `I_i` and scale `q_i` (1 where it has all its bonds) has
   *
   *   (M x)_i = C_i x_i + sum_{k in I_i} (s_{ik} o B_k) x_{i + o_k},
   *   C_i     = C0 + sigma o sum_{k in I_i} (t_{ik} o B_k),
   *
   * `o` entry by entry: entry `(a, b)` of `s_{ik}` is `q_i`, `q_j` or their
   * mean (`j = i + o_k`) as `bond_scale` says, of `t_{ik}` as
   * `centre_scale` says, `sigma` is -1, 0 or 1, and `C0 = C - sigma o sum_k
   * B_k`, so that a particle with all its bonds and `q = 1` has the shared
   * rows. LatticeOperator checks each particle's rows against the model's
   * own before it computes them so; any other row stays stored.
   */
  template <int dim>
  struct ScaledBondRows
  {
    enum class Scale : unsigned char
    {
      own,
      partner,
      mean
    };
    /** Per entry of a block, row-major: how a bond's entries scale. */
    std::vector<Scale> bond_scale;
    /** Per entry of the centre block: how its sum over bonds scales. */
    std::vector<Scale> centre_scale;
    /** Per entry of the centre block: sigma. */
    std::vector<int> centre_sign;
    /**
     * For a particle: whether its rows may be of this form, and if so its
     * intact bonds (per offset) and its `q`. Empty: no such rows.
     */
    std::function<bool(const typename ParticleLattice<dim>::LatticeIndex &,
                       std::vector<bool> &,
                       double &)>
      bonds_of;
  };



  /**
   * A particle model's operator without its matrix (doc/discretization.md,
   * 'Matrix-free particle operators'). A particle away from boundaries,
   * collar and cracks has the
   * same rows as every other such particle up to the shift of its numbers:
   * a dense `n_components x n_components` block per bond offset `o_k` and
   * one for the particle itself,
   *
   *   (M x)_i = C x_i + sum_k B_k x_{i + o_k},
   *
   * stored once. Near boundaries some of a particle's component rows may
   * still be the shared ones (the dilatation row of LPS in the first horizon
   * of the collar, where the displacement rows are identities); a mask per
   * particle says which. Of the other rows, identities are copies and the
   * shared ones scaled (ScaledBondRows) are computed; only the rest are
   * stored, as a sparse matrix
   * (`own_rows`, the kept and the eliminated components' rows apart, so
   * that a product of one subset of rows applies only its own). Degrees of
   * freedom are numbered particle by particle,
   * `n_components p + c`.
   *
   * `Tvmult` gathers too: `(M^T y)_j = C^T y_j + sum_k B_k^T y_{j - o_k}`
   * over the shared rows of the particles `j - o_k`, plus the scaled rows'
   * blocks gathered the same way, plus `own_rows^T y`. Both
   * read this rank's particles and the contiguous range of numbers that
   * their bonds reach, imported once per product.
   *
   * The last `n_eliminated_components` components of each particle are the
   * model's eliminated degrees of freedom: vmult_rows() computes only their
   * rows, or only the others', of the shared stencil and of the stored
   * rows (transposed, the stored rows are applied whole).
   */
  template <int dim>
  class LatticeOperator : public MatrixFreeOperator
  {
  public:
    using LatticeIndex = typename ParticleLattice<dim>::LatticeIndex;
    using Rows         = ParticleRows;

    /**
     * @param lattice the particles.
     * @param offsets the bond offsets `o_k`, closed under negation: every
     *   shared-stencil row reads only these neighbours and the particle.
     * @param n_components degrees of freedom per particle.
     * @param n_eliminated_components how many of them, the last ones, are
     *   eliminated (DiscreteModel::eliminated).
     * @param owned_particles this rank's particles, a contiguous range.
     * @param shared_rows_of per particle, the mask of its component rows
     *   (bit `c` for component `c`) that are the shared ones.
     * @param rows_of the row of any particle, for those that do not and
     *   to read the shared one from.
     * @param scaled_rows the form of the rows that are the shared ones
     *   scaled, which are then computed, not stored.
     */
    LatticeOperator(
      const ParticleLattice<dim>      &lattice,
      const std::vector<LatticeIndex> &offsets,
      const unsigned int               n_components,
      const unsigned int               n_eliminated_components,
      const IndexSet                  &owned_particles,
      const std::function<unsigned int(const LatticeIndex &)> &shared_rows_of,
      const std::function<void(types::global_dof_index, Rows &)> &rows_of,
      const MPI_Comm                                              communicator,
      const ScaledBondRows<dim> &scaled_rows = ScaledBondRows<dim>());

    void
    vmult_rows(TrilinosWrappers::MPI::Vector       &dst,
               const TrilinosWrappers::MPI::Vector &src,
               const bool                           transpose,
               const RowSubset                      rows,
               const RowRanges                     *within) const override;

    std::vector<RowRanges>
    rows_near(const TrilinosWrappers::MPI::Vector &marked,
              const unsigned int                   layers) const override;

    std::size_t
    memory_consumption() const override;

    /** The degrees of freedom this rank's rows read (a contiguous range). */
    const IndexSet &
    relevant_dofs() const;

    /**
     * The number of component rows of all ranks that are not the shared
     * ones: identities, the shared ones scaled, and the stored ones.
     */
    types::global_dof_index
    n_stored_rows() const;

    /** The number of those that are the shared ones scaled (all ranks). */
    types::global_dof_index
    n_scaled_rows() const;

    /** The number of those that a sparse matrix stores (all ranks). */
    types::global_dof_index
    n_compressed_rows() const;

  private:
    /**
     * The doubles of the vectors the forward stencil product works on: one
     * AVX2 register (two SSE2 ones), and the number of particles it takes
     * at a time.
     */
    static constexpr unsigned int lanes = 4;

    /**
     * For the particles from @p p to the end of a segment (the number
     * returned: the end of its run of a lattice line, of this rank's range,
     * or where some neighbour line's next run begins), where the bond along
     * `o_k` of particle `i` reaches: number `origin[k] + i`, present if in
     * `[lo[k], hi[k])`.
     */
    types::global_dof_index
    bond_lines(const types::global_dof_index p,
               std::vector<std::int64_t>    &origin,
               std::vector<std::int64_t>    &lo,
               std::vector<std::int64_t>    &hi) const;

    /** Particle numbers `[first, end)`, ascending and disjoint. */
    using ParticleRanges = std::vector<std::pair<std::int64_t, std::int64_t>>;

    /**
     * Where the products read @p src: the owned values, then the two ranges
     * of `edges` filled from them and the other ranks' (read_edges()), and
     * the particle number of each one's first value.
     */
    std::pair<std::array<const double *, 3>, std::array<std::int64_t, 3>>
    gather(const TrilinosWrappers::MPI::Vector &src) const;

    /**
     * The shared-stencil part of `M x` (or of `M^T x`) for this rank's
     * particles into the owned values @p y, at the components `[a0, a1)` of
     * each particle only; with @p within, for its particles only, zero for
     * the others. Segment `s` reads the values of particle `i` at
     * `x[source][(i - x_first[source]) n_c]`, `source = segment_source[s]`.
     */
    template <int n_c, bool transpose, int a0, int a1>
    void
    apply_stencil(const std::array<const double *, 3> &x,
                  const std::array<std::int64_t, 3>   &x_first,
                  const ParticleRanges                *within,
                  double                              *y) const;

    /**
     * The kernels' part of the product in vmult_rows(): apply_stencil() and
     * then apply_scaled_rows() for the rows @p rows, with the block size and
     * the components as compile-time constants (lattice_kernels.cc, the
     * file compiled for the machine's vector instructions).
     */
    void
    apply_kernels(const std::array<const double *, 3> &x,
                  const std::array<std::int64_t, 3>   &x_first,
                  const bool                           transpose,
                  const RowSubset                      rows,
                  const ParticleRanges                *within,
                  double                              *y) const;

    /**
     * The pieces of lattice lines this rank's particles lie on: piece `s`
     * holds the particles `[segment_start[s], segment_start[s + 1])`, and
     * its bond along `o_k` reaches as bond_lines() says, with
     * `origin = bond_origin[s n + k]`, `lo = bond_lo[s n + k]`,
     * `hi = bond_hi[s n + k]` (`n` offsets). Built once, not looked up in
     * every product line by line.
     */
    std::vector<types::global_dof_index> segment_start;
    std::vector<std::int64_t>            bond_origin, bond_lo, bond_hi;
    /**
     * Per segment, where its products read the values: 0 from the owned
     * vector itself, when all the particles its bonds reach are this
     * rank's; else 1 or 2, the lower or the upper of the two ranges of
     * `edges` (read_edges()).
     */
    std::vector<unsigned char> segment_source;
    /** The particle numbers `[first, end)` of the two ranges of `edges`. */
    std::array<std::pair<std::int64_t, std::int64_t>, 2> edge_ranges;

    const ParticleLattice<dim>     &lattice;
    const std::vector<LatticeIndex> offsets;
    /** The index of the offset `-o_k`. */
    std::vector<unsigned int> reverse;
    const unsigned int        n_components;
    const unsigned int        n_eliminated_components;
    /** This rank's particles `[first, end)`, and the range they reach. */
    types::global_dof_index first, end, reach_first, reach_end;
    /** Per particle of the reached range: the mask of its shared rows. */
    std::vector<unsigned char> shared;
    /** The mask of all `n_components` rows. */
    unsigned int all_rows;
    /** `B_k` for every offset, then `C`: row-major blocks. */
    std::vector<double> blocks;
    /**
     * The rows of `blocks`, each repeated over the values of a group of
     * particles the forward product takes at once, up to the least common
     * multiple of `n_components` and the vector lanes.
     */
    std::vector<double> tiled_blocks;
    /**
     * Per owned particle: are its rows and those of all its bond partners
     * the shared ones (so that the transposed product needs no tests)?
     */
    std::vector<bool> interior;
    /**
     * The stored rows of the kept components, then of the eliminated ones
     * (the Schur complement of doc/discretization.md, 'Iterative model
     * solvers', asks for each subset in turn).
     */
    std::array<TrilinosWrappers::SparseMatrix, 2> own_rows;
    /**
     * Per part: a product with its stored rows, over those rows only, and
     * the rows' indices into this rank's owned values.
     */
    mutable std::array<TrilinosWrappers::MPI::Vector, 2> own_rows_values;
    std::array<std::vector<unsigned int>, 2>             own_rows_entries;
    /**
     * Per part: the indices into this rank's owned values of the rows
     * that are rows of the identity, which `own_rows` leaves out.
     */
    std::array<std::vector<unsigned int>, 2> identity_rows;
    /** A transposed product with stored rows, over the owned values. */
    mutable TrilinosWrappers::MPI::Vector own_rows_transposed;
    /** Does any rank store a row of the kept (eliminated) components? */
    std::array<bool, 2>     has_own_rows = {{false, false}};
    types::global_dof_index n_own_rows   = 0;
    IndexSet                owned_dofs, relevant;
    MPI_Comm                communicator;
    /**
     * The values near the ends of this rank's range, owned or not, that
     * the segments with `segment_source` 1 or 2 read: importing the whole
     * reached range instead copied every owned value into it first, in
     * every product.
     */
    mutable std::vector<double> edges;
    /** The values of `edges` other ranks own, in the order of `edges`. */
    std::unique_ptr<Epetra_Vector> ghosts;
    /** The plan that fills `ghosts` from an owned vector, built once. */
    std::unique_ptr<Epetra_Import> importer;
    /**
     * The pieces of `edges`, in order: `count` values from position `from`
     * of `ghosts` or (`from_ghosts` false) of the owned values, to position
     * `to`: Epetra's import would copy the owned ones one by one through
     * its permutation lists.
     */
    struct EdgePiece
    {
      std::size_t to, from, count;
      bool        from_ghosts;
    };
    std::vector<EdgePiece> edge_pieces;

    /** Set `segment_source`, `edge_ranges`, `edges` and the rest above. */
    void
    read_edges();

    /**
     * A particle whose rows in the mask `rows` are the shared ones scaled
     * (possibly none: a partner's `q`): its number and `q`. Its bonds and
     * `C_i` are at its index in `scaled_bonds` and `scaled_centres`.
     */
    struct ScaledParticle
    {
      std::int64_t  number;
      double        q;
      unsigned char rows;
    };
    /** The scaled rows' form (its tables; `bonds_of` is not kept). */
    ScaledBondRows<dim> scaling;
    /**
     * The particles of the reached range whose rows are scaled, or whose
     * `q` is not 1; per particle of the range, its index here or -1.
     */
    std::vector<ScaledParticle> scaled;
    std::vector<int>            scaled_index;
    /** Per scaled particle: the words of its intact bonds' bits. */
    std::vector<std::uint64_t> scaled_bonds;
    unsigned int               words_per_particle = 0;
    /** Per scaled particle: `C_i`, row-major. */
    std::vector<double> scaled_centres;
    /**
     * Per offset: the entries of `B_k` a bond scales by `q_i` and by `q_j`
     * (the mean's half in each), row-major.
     */
    std::vector<double> own_blocks, partner_blocks;
    /**
     * This rank's particles with scaled rows (forward), and those with a
     * scaled partner or scaled rows (transposed): the index into `scaled`
     * or the number, and the segment.
     */
    std::vector<std::pair<std::int64_t, std::size_t>> scaled_owned, touched;
    types::global_dof_index                           n_scaled = 0;

    /** Is bond `k` of scaled particle `s` intact? */
    bool
    intact(const std::size_t s, const unsigned int k) const
    {
      return (scaled_bonds[s * words_per_particle + k / 64] >> (k % 64)) & 1u;
    }

    /** `q` of particle @p j of the reached range. */
    double
    q_of(const std::int64_t j) const
    {
      const int s = scaled_index[j - reach_first];
      return s < 0 ? 1. : scaled[s].q;
    }

    /** Find the scaled particles (`scaled_rows` as for the constructor). */
    void
    find_scaled_rows(
      const ScaledBondRows<dim>                                  &scaled_rows,
      const std::function<void(types::global_dof_index, Rows &)> &rows_of);

    /**
     * Add the scaled rows' part of `M x` at the components `[a0, a1)` of
     * each particle (of `M^T x`: the columns), to the owned values @p y;
     * @p x and @p x_first as in apply_stencil(): a scaled row and its
     * partners read where their segment does.
     */
    template <int n_c, int a0, int a1>
    void
    apply_scaled_rows(const std::array<const double *, 3> &x,
                      const std::array<std::int64_t, 3>   &x_first,
                      const bool                           transpose,
                      double                              *y) const;
  };

  /**
   * Store a particle model's operator in @p model: with @p matrix_free a
   * LatticeOperator (the other arguments as its constructor's, @p
   * scaled_rows included), otherwise
   * the assembled rows of all @p owned_particles; and the degrees of
   * freedom its rows read in `model.relevant`.
   */
  template <int dim>
  void
  store_particle_operator(
    const ParticleLattice<dim>                                     &lattice,
    const std::vector<typename ParticleLattice<dim>::LatticeIndex> &offsets,
    const unsigned int n_components,
    const unsigned int n_eliminated_components,
    const IndexSet    &owned_particles,
    const std::function<unsigned int(
      const typename ParticleLattice<dim>::LatticeIndex &)> &shared_rows_of,
    const std::function<void(types::global_dof_index, ParticleRows &)> &rows_of,
    const bool                 matrix_free,
    DiscreteModel             &model,
    const ScaledBondRows<dim> &scaled_rows = ScaledBondRows<dim>());
} // namespace ltn

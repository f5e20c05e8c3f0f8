#include <deal.II/base/utilities.h>

#include <ltn/output/parallel_vtu.h>

#include <fstream>
#include <vector>

namespace ltn
{
  template <int dim, int spacedim>
  std::string
  write_parallel_vtu(DataOutInterface<dim, spacedim> &data,
                     const std::string               &directory,
                     const std::string               &name,
                     const MPI_Comm                   communicator)
  {
    const std::string  record = name + ".pvtu";
    const unsigned int ranks  = Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int rank   = Utilities::MPI::this_mpi_process(communicator);
    if (ranks == 1 && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return record;

    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data.set_flags(flags);
    const auto piece = [&](const unsigned int r) {
      return name + "." + Utilities::int_to_string(r, 4) + ".vtu";
    };
    {
      std::ofstream out(directory + "/" + piece(rank));
      data.write_vtu(out);
      AssertThrow(out, ExcIO());
    }
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < ranks; ++r)
          pieces.push_back(piece(r));
        std::ofstream out(directory + "/" + record);
        data.write_pvtu_record(out, pieces);
        AssertThrow(out, ExcIO());
      }
    return record;
  }

  template std::string
  write_parallel_vtu(DataOutInterface<0, 2> &,
                     const std::string &,
                     const std::string &,
                     MPI_Comm);
  template std::string
  write_parallel_vtu(DataOutInterface<0, 3> &,
                     const std::string &,
                     const std::string &,
                     MPI_Comm);
  template std::string
  write_parallel_vtu(DataOutInterface<1, 1> &,
                     const std::string &,
                     const std::string &,
                     MPI_Comm);
  template std::string
  write_parallel_vtu(DataOutInterface<2, 2> &,
                     const std::string &,
                     const std::string &,
                     MPI_Comm);
  template std::string
  write_parallel_vtu(DataOutInterface<3, 3> &,
                     const std::string &,
                     const std::string &,
                     MPI_Comm);
} // namespace ltn

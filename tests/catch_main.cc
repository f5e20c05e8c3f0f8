// Catch2 runner for LtN's tests, inside an MPI environment (deal.II's
// parallel classes need one even on one rank).

#define CATCH_CONFIG_RUNNER
#include <deal.II/base/mpi.h>

#include <ltn/base/blas_threads.h>

#include <catch2/catch.hpp>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ltn::use_one_blas_thread();
  return Catch::Session().run(argc, argv);
}

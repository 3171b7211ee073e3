// The main of the tests that run under mpirun: MPI (and FFTW's MPI library) around Catch2's
// session. Every rank runs every test; a test's assertions compare quantities already reduced
// over the ranks, so all ranks pass or fail together, and the process's exit status is the worst
// rank's (mpirun returns a failing rank's).
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "distributed/mpi_session.hpp"

int main(int argc, char* argv[]) {
  coatfft::MpiSession session(argc, argv);
  return Catch::Session().run(argc, argv);
}

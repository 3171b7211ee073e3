#pragma once
// What an MPI launcher (mpirun, mpiexec) told this process through its environment, read without
// initialising MPI (which costs about half a second with Open MPI, and needs an MPI build): Open
// MPI's OMPI_COMM_WORLD_SIZE and _RANK, or MPICH's (Hydra's) PMI_SIZE and PMI_RANK.
#include <cstdlib>
#include <string>
#include <utility>

namespace coatfft::detail {

struct MpiLaunch {
  bool launched = false;  ///< a launcher started this process
  int size = 1;           ///< the ranks it started
  int rank = 0;           ///< this process's rank among them
};

inline MpiLaunch mpi_launch() {
  const auto number = [](const char* name) -> int {
    const char* v = std::getenv(name);
    if (v == nullptr) return -1;
    try {
      return std::stoi(v);
    } catch (...) {
      return -1;
    }
  };
  for (const auto& [size_name, rank_name] :
       {std::pair{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK"}, {"PMI_SIZE", "PMI_RANK"}}) {
    const int size = number(size_name), rank = number(rank_name);
    if (size >= 1 && rank >= 0) return {true, size, rank};
  }
  return {};
}

}  // namespace coatfft::detail

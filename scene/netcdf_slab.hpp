#pragma once
// A distributed run's fields as one NetCDF file ([output] format = "netcdf" under mpirun): the
// serial run's fields.nc (scene/scene_netcdf.hpp), each rank putting its rows of every field in
// collective calls (io/netcdf_collective.hpp), none gathering a field. Built with
// COATFFT_MPI.
#include <filesystem>

#include "distributed/communicator.hpp"
#include "scene/distributed_run.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// Writes the fields of `run` that `spec` asks for (uz, pressure, gap) into the new file `path`,
/// with rank 0's summary.json object as the file's attribute `summary`. Collective;
/// InvalidArgument on every rank when any rank cannot create or write the file.
void write_run_netcdf_slab(const Communicator& comm, const std::filesystem::path& path,
                           const OutputSpec& spec, const Grid& grid,
                           const DistributedSceneRun& run);

}  // namespace coatfft::scene

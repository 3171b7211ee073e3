#include "scene/netcdf_slab.hpp"

#include <string>

#include "io/netcdf_collective.hpp"
#include "scene/scene_netcdf.hpp"

namespace coatfft::scene {

void write_run_netcdf_slab(const Communicator& comm, const std::filesystem::path& path,
                           const OutputSpec& spec, const Grid& grid,
                           const DistributedSceneRun& run) {
  // Every rank defines the same header: rank 0's summary (the ranks' own timings differ).
  std::string summary = run.summary.dump();
  comm.broadcast(summary);
  io::NetcdfDataset d = run_dataset(grid, nlohmann::json::parse(summary));
  d.first_row = run.slab.y0;
  d.rows = run.slab.rows;
  if (spec.uz) d.variables.push_back(field_variable("uz", run.uz));
  if (spec.pressure) d.variables.push_back(field_variable("pressure", run.pressure));
  if (spec.gap) d.variables.push_back(field_variable("gap", run.gap));
  io::write_netcdf_collective(comm, path, d);
}

}  // namespace coatfft::scene

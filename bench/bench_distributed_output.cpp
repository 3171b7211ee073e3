// The fields' files of a distributed run (docs/scale.md, "NetCDF files by the ranks together"):
// one N x N field (a rough surface made by the ranks) written as .npy by MPI-IO
// (io/npy_slab.hpp) and as NetCDF by PnetCDF's collective writes
// (io/netcdf_collective.hpp), each rank its rows; each time the median of repeats, from a
// barrier to the slowest rank, of creating, writing and closing the file (not synced to the disk:
// the page cache's speed). With --serial, write_npy and write_netcdf of the whole field in a
// process without MPI. One CSV row on stdout (rank 0); scripts/distributed_scale_run.sh
// (WHAT=output) writes bench/results/distributed_output.csv.
//   mpirun -np P bench_distributed_output --size N [--repeats R] [--folder DIR]
//   bench_distributed_output --serial --size N
#include <unistd.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "bench/command_line.hpp"
#include "bench/slowest_rank_median.hpp"
#include "distributed/mpi_session.hpp"
#include "distributed/self_affine_slab.hpp"
#include "io/netcdf_collective.hpp"
#include "io/netcdf_writer.hpp"
#include "io/npy.hpp"
#include "io/npy_slab.hpp"
#include "surfaces/self_affine_surface.hpp"

namespace {

using namespace coatfft;
namespace fs = std::filesystem;

struct Options {
  std::ptrdiff_t n = 2048;
  int repeats = 5;
  bool serial = false;
  std::string folder;  // "": the system's temporary folder
};

SelfAffineSpec surface_spec() {
  SelfAffineSpec spec;
  spec.hurst = 0.8;
  spec.rms_slope = 0.05;
  spec.seed = 2004;
  return spec;
}

struct Row {
  double npy_s = 0, netcdf_s = 0;
};

// The median write time of `path` [s] on the slowest rank: the file removed by `root` before each
// write (the NetCDF writers refuse an existing file) and after the last.
template <typename Write, typename Barrier, typename Max>
double median_write_s(int repeats, const fs::path& path, bool root, Write&& write,
                      Barrier&& barrier, Max&& max) {
  const auto remove = [&] {
    if (root) fs::remove(path);
    barrier();
  };
  remove();
  const double ms = bench::slowest_rank_median_ms(repeats, write, remove, max);
  remove();
  return 1e-3 * ms;
}

Row run_distributed(const Options& o, const Grid& grid, const fs::path& folder) {
  const Communicator comm = Communicator::world();
  const Field z = self_affine_slab(comm, grid, surface_spec());
  const Slab slab = slab_of(comm, grid.nx(), grid.ny());
  const auto barrier = [&] { comm.barrier(); };
  const auto max = [&](double t) { return comm.max(t); };
  const bool root = comm.rank() == 0;
  Row row;
  row.npy_s = median_write_s(
      o.repeats, folder / "z.npy", root,
      [&] { io::write_npy_slab(comm, folder / "z.npy", z, slab); }, barrier, max);
  row.netcdf_s = median_write_s(
      o.repeats, folder / "z.nc", root,
      [&] { io::write_heights_slab(comm, folder / "z.nc", z, grid, slab, true); }, barrier, max);
  return row;
}

Row run_serial(const Options& o, const Grid& grid, const fs::path& folder) {
  const Field z = self_affine_surface(grid, surface_spec());
  const auto none = [] {};
  const auto same = [](double t) { return t; };
  Row row;
  row.npy_s = median_write_s(
      o.repeats, folder / "z.npy", true, [&] { io::write_npy(folder / "z.npy", z); }, none, same);
  row.netcdf_s = median_write_s(
      o.repeats, folder / "z.nc", true,
      [&] { io::write_heights(folder / "z.nc", io::HeightsFormat::netcdf, z, grid, true); }, none,
      same);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{
      "A distributed run's field written as .npy (MPI-IO) and as NetCDF (PnetCDF), one CSV row"};
  Options o;
  app.add("--size", o.n, "grid size N (N x N cells)").show_default();
  app.add("--repeats", o.repeats, "timed writes of each file").show_default();
  app.add("--folder", o.folder, "where the files are written (default: the temporary folder)");
  app.flag("--serial", o.serial, "write_npy and write_netcdf of the whole field, without MPI");
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    std::unique_ptr<MpiSession> session;
    if (!o.serial) session = std::make_unique<MpiSession>(argc, argv);
    const int ranks = session ? session->world().size() : 0;
    const bool root = !session || session->world().rank() == 0;
    // One folder for all ranks: rank 0's process id names it.
    std::string name = "coatfft_bench_output_" + std::to_string(::getpid());
    if (session) session->world().broadcast(name);
    const fs::path folder =
        (o.folder.empty() ? fs::temp_directory_path() : fs::path(o.folder)) / name;
    if (root) fs::create_directories(folder);
    if (session) session->world().barrier();
    const Grid grid(o.n, o.n, 1e-3, 1e-3);
    const Row row = o.serial ? run_serial(o, grid, folder) : run_distributed(o, grid, folder);
    if (session) session->world().barrier();
    if (!root) return 0;
    fs::remove_all(folder);
    const double mib = 8.0 * static_cast<double>(grid.nb_cells()) / (1024.0 * 1024.0);
    std::printf("%td,%s,%.0f,%.3f,%.3f,%.2f\n", o.n,
                o.serial ? "serial" : std::to_string(ranks).c_str(), mib, row.npy_s, row.netcdf_s,
                row.netcdf_s / row.npy_s);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_distributed_output: " << e.what() << "\n";
    return 1;
  }
}

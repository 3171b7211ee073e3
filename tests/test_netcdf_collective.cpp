// A NetCDF file written by the ranks together (io/netcdf_collective.hpp) against the
// serial writer's file of the whole fields: byte for byte, for maps with and without a leading
// dimension, a variable without maps and the file's attributes, on grids whose rows split unevenly
// and where a rank holds no rows, whole or a block of columns at a time. Runs under mpirun at 1, 2
// and 3 ranks (test_distributed).
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "distributed/communicator.hpp"
#include "distributed/slab.hpp"
#include "io/netcdf_collective.hpp"
#include "io/netcdf_writer.hpp"

using namespace coatfft;
using namespace coatfft::io;

namespace {

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A folder of rank 0's making, the same path on every rank (the ranks share its file system).
std::filesystem::path shared_folder(const Communicator& comm) {
  std::string name = (std::filesystem::temp_directory_path() /
                      ("coatfft_netcdf_collective_" + std::to_string(::getpid())))
                         .string();
  comm.broadcast(name);
  if (comm.rank() == 0) std::filesystem::create_directories(name);
  comm.barrier();
  return name;
}

// The values of two maps stacked over a leading dimension of 2 depths, rows `y0` to `y0 + rows`:
// each cell's value says its depth, row and column.
std::vector<double> stacked_rows(const Grid& g, std::ptrdiff_t y0, std::ptrdiff_t rows) {
  std::vector<double> values;
  for (int depth = 0; depth < 2; ++depth)
    for (std::ptrdiff_t j = y0; j < y0 + rows; ++j)
      for (std::ptrdiff_t i = 0; i < g.nx(); ++i)
        values.push_back(1e4 * depth + 1e2 * double(j) + double(i) + 0.125);
  return values;
}

// A dataset of `values` (rows as `stacked_rows` made them): a map, the stack, a depth profile.
NetcdfDataset dataset(const Grid& g, const std::vector<double>& values,
                      const std::vector<double>& profile) {
  NetcdfDataset d{g, true, {}, {}, {{{"source", "test"}}, {{"scale", 2.5}}}};
  d.dimensions.push_back({"depth", 2, {1e-6, 2e-6}, {{{"units", "m"}}, {}}});
  const std::span<const double> all(values);
  d.variables.push_back({"top", {}, all.first(values.size() / 2), {{{"units", "Pa"}}, {}}});
  d.variables.push_back({"stack", {"depth"}, all, {}});
  d.variables.push_back({"profile", {"depth"}, profile, {}, false});
  return d;
}

}  // namespace

TEST_CASE("a NetCDF file written by the ranks together is the serial writer's, byte for byte") {
  const Communicator comm = Communicator::world();
  const std::filesystem::path folder = shared_folder(comm);
  const std::vector<double> profile = {3.0, -4.0};
  // 13 rows split unevenly; 4 rows at 3 ranks leave a rank without rows.
  for (const std::ptrdiff_t ny : {13, 4}) {
    const Grid g(6, ny, 6e-4, 1e-4 * double(ny));
    const Slab s = slab_of(comm, g.nx(), g.ny());
    const std::filesystem::path serial = folder / ("serial" + std::to_string(ny) + ".nc");
    const std::filesystem::path together = folder / ("ranks" + std::to_string(ny) + ".nc");
    if (comm.rank() == 0) write_netcdf(serial, dataset(g, stacked_rows(g, 0, ny), profile));
    const std::vector<double> mine = stacked_rows(g, s.y0, s.rows);
    NetcdfDataset d = dataset(g, mine, profile);
    d.first_row = s.y0;
    d.rows = s.rows;
    // The maps 4 columns at a time (4 and 2 of the 6), as a map larger than the writer's buffer.
    d.buffer_values = 4 * static_cast<std::size_t>(ny);
    write_netcdf_collective(comm, together, d);
    comm.barrier();
    INFO(ny << " rows at " << comm.size() << " ranks");
    CHECK(comm.all(contents(together) == contents(serial)));
    // The file is new or nothing: an existing one is refused on every rank, left as it was.
    const std::string before = contents(together);
    CHECK_THROWS_AS(write_netcdf_collective(comm, together, d), InvalidArgument);
    CHECK(comm.all(contents(together) == before));
  }
  comm.barrier();
  if (comm.rank() == 0) std::filesystem::remove_all(folder);
}

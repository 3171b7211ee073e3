#include "io/netcdf_collective.hpp"

#include <mpi.h>
#include <netcdf.h>
#include <netcdf_par.h>

#include <string>

#include "core/error.hpp"
#include "distributed/detail/mpi_handle.hpp"
#include "io/netcdf_file.hpp"

namespace coatfft::io {

namespace {

// `path` created on every rank; InvalidArgument on every rank when any rank could not create it (a
// rank that did keeps its handle open: closing is collective, and the run ends).
NetcdfFile create_collective(const Communicator& comm, const std::filesystem::path& path,
                             bool large_variables) {
  int id = -1;
  const int format = large_variables ? NC_64BIT_DATA : NC_64BIT_OFFSET;
  const int status = nc_create_par(path.c_str(), NC_NOCLOBBER | format,
                                   coatfft::detail::mpi_comm(comm), MPI_INFO_NULL, &id);
  if (!comm.all(status == NC_NOERR)) {
    check_netcdf(status, path, "cannot create");
    throw InvalidArgument(path.string() + ": cannot create on every rank");
  }
  NetcdfFile nc(path, id);
  nc.defer_errors();
  return nc;
}

// Every variable's values put by all ranks in each call (MPI-IO's collective writes), not by each
// on its own.
void ask_collective_access(NetcdfFile& nc) {
  int variables = 0;
  nc.check(nc_inq_nvars(nc.id(), &variables), "variables");
  for (int var = 0; var < variables; ++var)
    nc.check(nc_var_par_access(nc.id(), var, NC_COLLECTIVE), "collective access");
}

}  // namespace

void write_netcdf_collective(const Communicator& comm, const std::filesystem::path& path,
                             NetcdfDataset dataset) {
  dataset.puts_shared = comm.rank() == 0;
  NetcdfFile nc = create_collective(comm, path, needs_64bit_data(dataset));
  define_netcdf(nc, dataset);
  ask_collective_access(nc);
  put_netcdf(nc, dataset);
  nc.close();
  const bool written = nc.error().empty();
  COATFFT_REQUIRE(comm.all(written), written ? "failed writing " + path.string() : nc.error());
}

void write_heights_slab(const Communicator& comm, const std::filesystem::path& path,
                        const Field& rows, const Grid& grid, const Slab& slab, bool periodic,
                        const NetcdfAttributes& attributes) {
  NetcdfDataset d = heights_dataset(grid, periodic, rows, attributes);
  d.first_row = slab.y0;
  d.rows = slab.rows;
  write_netcdf_collective(comm, path, std::move(d));
}

}  // namespace coatfft::io

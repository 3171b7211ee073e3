#pragma once
// One NetCDF file written by the ranks of a communicator together, without gathering a field: each
// rank puts its rows of every map at their place in collective calls (NetCDF's MPI build writes
// NetCDF-3 files through PnetCDF's MPI-IO). The file holds what write_netcdf
// writes of the whole fields; only the header's padding may differ. Built with COATFFT_MPI.
#include <filesystem>

#include "core/grid.hpp"
#include "core/types.hpp"
#include "distributed/communicator.hpp"
#include "distributed/slab.hpp"
#include "io/netcdf_writer.hpp"

namespace coatfft::io {

/// Writes `dataset`, whose maps hold this rank's rows (`first_row`, `rows`), as the new file
/// `path`; the coordinates and the variables without maps come from rank 0. Every rank passes the
/// same dimensions, variables and attributes. Collective; InvalidArgument on every rank when any
/// rank cannot create or write the file (an existing one is refused).
void write_netcdf_collective(const Communicator& comm, const std::filesystem::path& path,
                             NetcdfDataset dataset);

/// write_heights's NetCDF file of a height map [m] from this rank's rows `rows` (nx, slab.rows)
/// of it. Collective, as write_netcdf_collective.
void write_heights_slab(const Communicator& comm, const std::filesystem::path& path,
                        const Field& rows, const Grid& grid, const Slab& slab, bool periodic,
                        const NetcdfAttributes& attributes = {});

}  // namespace coatfft::io

#include "scene/npy_slab.hpp"

#include <mpi.h>

#include <array>
#include <string>

#include "core/error.hpp"
#include "distributed/detail/mpi_handle.hpp"
#include "scene/npy.hpp"

namespace coatfft::scene {

void write_npy_slab(const Communicator& comm, const std::filesystem::path& path, const Field& rows,
                    const Slab& slab) {
  COATFFT_REQUIRE(rows.rows() == slab.nx && rows.cols() == slab.rows,
                  "write_npy_slab: the rows are not of the slab's shape");
  MPI_File file;
  const int opened = MPI_File_open(detail::mpi_comm(comm), path.c_str(),
                                   MPI_MODE_CREATE | MPI_MODE_WRONLY, MPI_INFO_NULL, &file);
  if (!comm.all(opened == MPI_SUCCESS)) {
    if (opened == MPI_SUCCESS) MPI_File_close(&file);
    throw InvalidArgument("cannot open " + path.string() + " for writing");
  }
  bool written = MPI_File_set_size(file, 0) == MPI_SUCCESS;  // an earlier file's tail goes
  const auto shape = std::array<std::size_t, 2>{static_cast<std::size_t>(slab.ny),
                                                static_cast<std::size_t>(slab.nx)};
  const std::string preamble = npy_preamble(shape);
  if (comm.rank() == 0)
    written &= MPI_File_write_at(file, 0, preamble.data(), static_cast<int>(preamble.size()),
                                 MPI_CHAR, MPI_STATUS_IGNORE) == MPI_SUCCESS;
  // Whole rows as one element each: a rank's count of doubles may exceed an int.
  MPI_Datatype row;
  MPI_Type_contiguous(static_cast<int>(slab.nx), MPI_DOUBLE, &row);
  MPI_Type_commit(&row);
  const auto offset =
      static_cast<MPI_Offset>(preamble.size()) +
      static_cast<MPI_Offset>(slab.y0 * slab.nx) * static_cast<MPI_Offset>(sizeof(double));
  written &= MPI_File_write_at_all(file, offset, rows.data(), static_cast<int>(slab.rows), row,
                                   MPI_STATUS_IGNORE) == MPI_SUCCESS;
  MPI_Type_free(&row);
  written &= MPI_File_close(&file) == MPI_SUCCESS;
  COATFFT_REQUIRE(comm.all(written), "failed writing ", path.string());
}

}  // namespace coatfft::scene

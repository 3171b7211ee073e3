#include "io/npy_slab.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "distributed/detail/agreed_refusal.hpp"
#include "distributed/detail/mpi_handle.hpp"
#include "io/npy.hpp"

namespace coatfft::io {

namespace {

// `path` opened for writing by every rank and emptied (an earlier file's tail goes);
// InvalidArgument on every rank when any rank cannot.
MPI_File open_for_writing(const Communicator& comm, const std::filesystem::path& path) {
  MPI_File file;
  const int opened = MPI_File_open(detail::mpi_comm(comm), path.c_str(),
                                   MPI_MODE_CREATE | MPI_MODE_WRONLY, MPI_INFO_NULL, &file);
  const bool emptied = opened == MPI_SUCCESS && MPI_File_set_size(file, 0) == MPI_SUCCESS;
  if (!comm.all(emptied)) {
    if (opened == MPI_SUCCESS) MPI_File_close(&file);
    throw InvalidArgument("cannot open " + path.string() + " for writing");
  }
  return file;
}

}  // namespace

void write_npy_slab(const Communicator& comm, const std::filesystem::path& path, const Field& rows,
                    const Slab& slab) {
  COATFFT_REQUIRE(rows.rows() == slab.nx && rows.cols() == slab.rows,
                  "write_npy_slab: the rows are not of the slab's shape");
  MPI_File file = open_for_writing(comm, path);
  bool written = true;
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

void write_text_slab(const Communicator& comm, const std::filesystem::path& path,
                     std::string_view text) {
  std::vector<std::uint64_t> sizes(static_cast<std::size_t>(comm.size()));
  const std::uint64_t mine = text.size();
  comm.all_gather(&mine, sizeof mine, sizes.data());
  MPI_Offset offset = 0;
  for (int r = 0; r < comm.rank(); ++r) offset += static_cast<MPI_Offset>(sizes[std::size_t(r)]);
  MPI_File file = open_for_writing(comm, path);
  bool written = true;
  // In pieces of at most 1 GiB: MPI counts are ints.
  constexpr std::size_t piece = std::size_t{1} << 30;
  for (std::size_t done = 0; done < text.size(); done += piece) {
    const std::size_t n = std::min(piece, text.size() - done);
    written &= MPI_File_write_at(file, offset + static_cast<MPI_Offset>(done), text.data() + done,
                                 static_cast<int>(n), MPI_CHAR, MPI_STATUS_IGNORE) == MPI_SUCCESS;
  }
  written &= MPI_File_close(&file) == MPI_SUCCESS;
  COATFFT_REQUIRE(comm.all(written), "failed writing ", path.string());
}

namespace {

// Refuses, on every rank alike, the first value of the file (in its row-major order) that is not
// finite: its place is the smallest over the ranks, its value the one rank's that holds it.
void require_finite(const Communicator& comm, const std::filesystem::path& path, const Field& rows,
                    const Slab& slab, std::string_view value_word) {
  double first = -std::numeric_limits<double>::infinity();  // minus the first bad place
  for (Eigen::Index j = 0; j < rows.cols() && std::isinf(first); ++j)
    for (Eigen::Index i = 0; i < rows.rows(); ++i)
      if (!std::isfinite(rows(i, j))) {
        first = -static_cast<double>((slab.y0 + j) * slab.nx + i);
        break;
      }
  const double place = -comm.max(first);
  if (std::isinf(place)) return;
  const auto n = static_cast<std::ptrdiff_t>(place);
  const std::ptrdiff_t j = n / slab.nx, i = n % slab.nx;
  const bool mine = j >= slab.y0 && j < slab.y0 + slab.rows;
  const double value = comm.sum(mine ? rows(i, j - slab.y0) : 0.0);
  // The file is the one the holding rank read (each rank reads its own scene's).
  const auto holder = static_cast<int>(comm.max(mine ? comm.rank() : -1.0));
  std::string file = path.string();
  comm.broadcast(file, holder);
  throw InvalidArgument(detail::concat("rank ", holder, ": ", file, ": row ", j, ", column ", i,
                                       ": ", value_word, " ", value, " is not finite"));
}

}  // namespace

Field read_npy_slab(const Communicator& comm, const std::filesystem::path& path, const Slab& slab,
                    std::string_view value_word) {
  const auto ny = static_cast<std::size_t>(slab.ny), nx = static_cast<std::size_t>(slab.nx);
  NpyArray array;
  agreed_refusal(comm, [&] { array = read_npy_row_header(path, ny, nx); });
  MPI_File file;
  const int opened =
      MPI_File_open(detail::mpi_comm(comm), path.c_str(), MPI_MODE_RDONLY, MPI_INFO_NULL, &file);
  COATFFT_REQUIRE(comm.all(opened == MPI_SUCCESS), "cannot open ", path.string());
  // Whole rows as one element each: a rank's count of values may exceed an int.
  MPI_Datatype row;
  MPI_Type_contiguous(static_cast<int>(nx * array.value_bytes), MPI_BYTE, &row);
  MPI_Type_commit(&row);
  std::vector<unsigned char> bytes(static_cast<std::size_t>(slab.rows) * nx * array.value_bytes);
  const auto offset =
      static_cast<MPI_Offset>(array.data_offset) +
      static_cast<MPI_Offset>(static_cast<std::size_t>(slab.y0) * nx * array.value_bytes);
  bool read = MPI_File_read_at_all(file, offset, bytes.data(), static_cast<int>(slab.rows), row,
                                   MPI_STATUS_IGNORE) == MPI_SUCCESS;
  MPI_Type_free(&row);
  read &= MPI_File_close(&file) == MPI_SUCCESS;
  COATFFT_REQUIRE(comm.all(read), "failed reading ", path.string());
  Field rows = slab.field();
  npy_to_doubles(array, bytes.data(), static_cast<std::size_t>(rows.size()), rows.data());
  require_finite(comm, path, rows, slab, value_word);
  return rows;
}

}  // namespace coatfft::io

#include "io/netcdf_file.hpp"

#include <netcdf.h>
#include <netcdf_mem.h>

#include "core/error.hpp"

namespace coatfft::io {

void check_netcdf(int status, const std::filesystem::path& path, std::string_view what) {
  if (status != NC_NOERR)
    throw InvalidArgument(detail::concat(path.string(), ": ", what, ": ", nc_strerror(status)));
}

NetcdfFile NetcdfFile::open_memory(const std::filesystem::path& path, std::string& bytes) {
  int id = -1;
  check_netcdf(nc_open_mem(path.c_str(), NC_NOWRITE, bytes.size(), bytes.data(), &id), path,
               "not a readable NetCDF file");
  return NetcdfFile(path, id);
}

NetcdfFile NetcdfFile::create(const std::filesystem::path& path, bool large_variables) {
  int id = -1;
  // netcdf-c's I/O buffer defaults to the file system's block (4 KiB): a 128 MiB map would take
  // 32768 writes and three times as many seeks. 4 MiB takes 32.
  std::size_t buffer = std::size_t{4} << 20;
  const int format = large_variables ? NC_64BIT_DATA : NC_64BIT_OFFSET;
  check_netcdf(nc__create(path.c_str(), NC_NOCLOBBER | format, 0, &buffer, &id), path,
               "cannot create");
  return NetcdfFile(path, id);
}

NetcdfFile::NetcdfFile(NetcdfFile&& other) noexcept
    : path_(std::move(other.path_)),
      id_(other.id_),
      defers_errors_(other.defers_errors_),
      error_(std::move(other.error_)) {
  other.id_ = -1;
}

NetcdfFile::~NetcdfFile() {
  if (id_ >= 0) nc_close(id_);
}

void NetcdfFile::close() {
  const int id = id_;
  id_ = -1;
  check(nc_close(id), "cannot write");
}

void NetcdfFile::check(int status, std::string_view what) {
  if (!defers_errors_) return check_netcdf(status, path_, what);
  if (status != NC_NOERR && error_.empty())
    error_ = detail::concat(path_.string(), ": ", what, ": ", nc_strerror(status));
}

}  // namespace coatfft::io

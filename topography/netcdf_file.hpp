#pragma once
// A NetCDF dataset handle that is closed whatever happens (RAII over netcdf-c's ncid), and the
// one check of netcdf-c's status codes, for the NetCDF reader and writer of the scene layer.
#include <filesystem>
#include <string>
#include <string_view>

namespace coatfft::topography {

/// Throws InvalidArgument "PATH: WHAT: netcdf-c's message" unless `status` is NC_NOERR.
void check_netcdf(int status, const std::filesystem::path& path, std::string_view what);

class NetcdfFile {
 public:
  /// Opens the dataset held in `bytes` (NetCDF-3 or NetCDF-4) for reading; `bytes` must outlive
  /// the handle. `path` names it in messages.
  static NetcdfFile open_memory(const std::filesystem::path& path, std::string& bytes);
  /// Creates `path` as a NetCDF-3 file with 64-bit offsets (the format SurfaceTopography writes
  /// and its serial reader takes), refusing to overwrite an existing file.
  static NetcdfFile create(const std::filesystem::path& path);

  NetcdfFile(NetcdfFile&& other) noexcept;
  NetcdfFile& operator=(NetcdfFile&&) = delete;
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;
  ~NetcdfFile();

  int id() const { return id_; }
  const std::filesystem::path& path() const { return path_; }
  /// Closes the file, reporting an error of the last write (a full disk) as close does.
  void close();

 private:
  NetcdfFile(std::filesystem::path path, int id) : path_(std::move(path)), id_(id) {}
  std::filesystem::path path_;
  int id_ = -1;
};

}  // namespace coatfft::topography

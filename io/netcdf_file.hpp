#pragma once
// A NetCDF dataset handle that is closed whatever happens (RAII over netcdf-c's ncid), and the
// one check of netcdf-c's status codes, for the NetCDF reader and writers of the scene layer.
#include <filesystem>
#include <string>
#include <string_view>

namespace coatfft::io {

/// Throws InvalidArgument "PATH: WHAT: netcdf-c's message" unless `status` is NC_NOERR.
void check_netcdf(int status, const std::filesystem::path& path, std::string_view what);

class NetcdfFile {
 public:
  /// Opens the dataset held in `bytes` (NetCDF-3 or NetCDF-4) for reading; `bytes` must outlive
  /// the handle. `path` names it in messages.
  static NetcdfFile open_memory(const std::filesystem::path& path, std::string& bytes);
  /// Creates `path` as a NetCDF-3 file with 64-bit offsets (the format SurfaceTopography writes
  /// and its serial reader takes), or with `large_variables` in the 64-bit data format (CDF-5,
  /// io/netcdf_writer.hpp), refusing to overwrite an existing file.
  static NetcdfFile create(const std::filesystem::path& path, bool large_variables = false);
  /// Takes the handle `id` of a dataset opened or created as `path` (a collective write's,
  /// io/netcdf_collective.hpp); closed by this object.
  NetcdfFile(std::filesystem::path path, int id) : path_(std::move(path)), id_(id) {}

  NetcdfFile(NetcdfFile&& other) noexcept;
  NetcdfFile& operator=(NetcdfFile&&) = delete;
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;
  ~NetcdfFile();

  int id() const { return id_; }
  const std::filesystem::path& path() const { return path_; }
  /// Closes the file, reporting an error of the last write (a full disk) as close does.
  void close();

  /// check_netcdf on this file; or, once defer_errors() was called, keeps the first error's
  /// message (error()) and returns: a rank of a collective write must go on taking part in every
  /// collective call, or the other ranks would wait for it forever.
  void check(int status, std::string_view what);
  void defer_errors() { defers_errors_ = true; }
  /// The first error kept since defer_errors(), or "".
  const std::string& error() const { return error_; }

 private:
  std::filesystem::path path_;
  int id_ = -1;
  bool defers_errors_ = false;
  std::string error_;
};

}  // namespace coatfft::io

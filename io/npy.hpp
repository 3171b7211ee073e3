#pragma once
// Reading and writing 2-D float64 arrays as NumPy .npy (format 1.0, C order); CSV is io/csv.hpp.
// A Field (nx, ny) is stored as shape (ny, nx): row j is y_j (docs/conventions.md), which is
// the Field's own memory layout, so no transposition happens.
//
// The readers take only regular files (io/input_file.hpp) and check every size before they
// allocate. Their refusals are one-line InvalidArgument messages that start with the path; a
// place in a CSV file is "PATH:LINE:" with 1-based line numbers, a place in the array is
// "row j, column i" with 0-based indices as NumPy writes a[j, i]; text echoed from the file is
// quoted, its non-printable bytes escaped, and shortened to 80 characters.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "core/types.hpp"
#include "io/input_file.hpp"

namespace coatfft::io {

/// The bytes before the data of a C-order little-endian float64 .npy file (format 1.0) of shape
/// `shape`: magic, version, header length and the header dict, padded so that the data starts on
/// a 64-byte boundary.
std::string npy_preamble(std::span<const std::size_t> shape, std::string_view descr = "<f8");

/// Writes `data` as a C-order little-endian float64 .npy file of shape `shape` (whose product
/// must be data.size()).
void write_npy_array(const std::filesystem::path& path, std::span<const std::size_t> shape,
                     std::span<const double> data);

/// Writes `data` as a C-order uint8 .npy file of shape `shape` (a mask: 0 or 1 per cell).
void write_npy_bytes(const std::filesystem::path& path, std::span<const std::size_t> shape,
                     std::span<const std::uint8_t> data);

/// Writes `field` as a (ny, nx) little-endian float64 .npy file.
void write_npy(const std::filesystem::path& path, const Field& field);

/// Reads a 2-D .npy file (format 1.0, 2.0 or 3.0) of shape (rows, cols) into a Field (cols,
/// rows): float64, float32 or float16 values ('<f8', '>f8', '<f4', '>f4', '<f2', '>f2'; '=' or no
/// mark: little endian),
/// in C or Fortran order (numpy's fortran_order), converted to double. The header must be a
/// well-formed dict with exactly the keys 'descr', 'fortran_order' and 'shape', the shape two
/// positive integers, and the file exactly the header followed by rows x cols x 8 bytes. Throws
/// InvalidArgument naming the file for anything else, quoting the header as it is in the file (less
/// its padding).
Field read_npy(const std::filesystem::path& path, std::uintmax_t max_bytes = kMaxArrayFileBytes);

/// A 2-D .npy file's shape and where its values lie, for a reader of some of its rows only
/// (io/npy_slab.hpp).
struct NpyArray {
  std::size_t rows = 0, cols = 0;  ///< the array's shape (rows, cols)
  std::uintmax_t data_offset = 0;  ///< the bytes before the values
  std::size_t value_bytes = 8;     ///< of one value: 8, 4 or 2
  bool big_endian = false;
  bool fortran = false;  ///< fortran_order: the values column after column
};

/// The header of the .npy file at `path`, checked as read_npy checks it (the data's size
/// included), without reading the values.
NpyArray read_npy_header(const std::filesystem::path& path,
                         std::uintmax_t max_bytes = kMaxArrayFileBytes);

/// read_npy_header for a reader of rows (ny rows of nx values) apart, whose file may exceed
/// read_npy's limit (no process holds all of it): also refuses another shape and Fortran order.
NpyArray read_npy_row_header(const std::filesystem::path& path, std::size_t ny, std::size_t nx);

/// The `count` values of `array`'s type at `bytes` (count * value_bytes bytes of its file) as
/// doubles into `out`.
void npy_to_doubles(const NpyArray& array, const unsigned char* bytes, std::size_t count,
                    double* out);

}  // namespace coatfft::io

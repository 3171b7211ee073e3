#pragma once
// Reading and writing 2-D float64 arrays as NumPy .npy (format 1.0, C order) and plain CSV.
// A Field (nx, ny) is stored as shape (ny, nx): row j is y_j (docs/conventions.md), which is
// the Field's own memory layout, so no transposition happens.
//
// The readers take only regular files (cli/input_file.hpp) and check every size before they
// allocate. Their refusals are one-line InvalidArgument messages that start with the path; a
// place in a CSV file is "PATH:LINE:" with 1-based line numbers, a place in the array is
// "row j, column i" with 0-based indices as NumPy writes a[j, i]; text echoed from the file is
// quoted, its non-printable bytes escaped, and shortened to 80 characters.
#include <cstdint>
#include <filesystem>

#include "core/types.hpp"

namespace coatfft::cli {

/// Default limit on the size of a .npy or CSV file: 4 GiB (a 16384 x 16384 .npy takes 2 GiB).
inline constexpr std::uintmax_t kMaxArrayFileBytes = std::uintmax_t{4} << 30;

/// Writes `field` as a (ny, nx) little-endian float64 .npy file.
void write_npy(const std::filesystem::path& path, const Field& field);

/// Reads a 2-D '<f8' C-order .npy file (format 1.0, 2.0 or 3.0) of shape (rows, cols) into a
/// Field (cols, rows). The header must be a well-formed dict with exactly the keys 'descr',
/// 'fortran_order' and 'shape', the shape two positive integers, and the file exactly the header
/// followed by rows x cols x 8 bytes. Throws InvalidArgument naming the file for anything else,
/// quoting the header as it is in the file (less its padding).
Field read_npy(const std::filesystem::path& path, std::uintmax_t max_bytes = kMaxArrayFileBytes);

/// Reads a CSV matrix (rows separated by newlines, values by commas, semicolons or blanks; '#'
/// starts a comment; lines without values are skipped) into a Field (cols, rows). Values are
/// decimal numbers as std::from_chars reads them, with an optional leading '+' ("inf" and "nan"
/// included); a value too small for float64 reads as 0 or a subnormal, as strtod gives it, a value
/// too large is refused. Throws InvalidArgument on ragged rows, non-numbers or an empty file.
Field read_csv_matrix(const std::filesystem::path& path,
                      std::uintmax_t max_bytes = kMaxArrayFileBytes);

}  // namespace coatfft::cli
